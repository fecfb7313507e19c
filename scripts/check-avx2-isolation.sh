#!/usr/bin/env bash
# The AVX2 copy of the packet traversal (libtrace/accel/kd_packet.cpp built with RT_PACKET_AVX2,
# core/simd.h) may hold AVX instructions only in its own functions: the traversal and its helpers
# in namespace rt::simd_avx2. Any other function in the object is an inline function of a header
# that other files share, and the linker may keep this object's copy for every caller, the
# single rays and CPUs without AVX2 included; it must have the baseline instructions.
#   scripts/check-avx2-isolation.sh OBJECT...
# Exits 1 with one line "check-avx2-isolation ERROR: OBJECT: function: N AVX instructions" per
# function that breaks the rule.
set -euo pipefail
status=0
for object in "$@"; do
    # objdump's lines: "ADDRESS <function>:" then "  OFFSET:<tab>MNEMONIC OPERANDS"; VEX and EVEX
    # mnemonics start with v (vmovupd, vaddpd, vzeroupper), no baseline one does in compiled C++.
    report=$(objdump -d --no-show-raw-insn -C "$object" | awk -F'\t' -v object="$object" '
        /^[0-9a-f]+ <.*>:$/ { fn = substr($0, index($0, "<") + 1); sub(/>:$/, "", fn) }
        NF >= 2 && $2 ~ /^v/ { avx[fn]++ }
        END {
            for (fn in avx)
                if (fn !~ /rt::simd_avx2::/ && fn !~ /trace(Shadow)?Packet<\(rt::SimdLevel\)1>/)
                    printf "check-avx2-isolation ERROR: %s: %s: %d AVX instructions\n", object, fn, avx[fn]
        }')
    if [[ -n "$report" ]]; then
        echo "$report" >&2
        status=1
    fi
done
exit "$status"
