#!/usr/bin/env bash
# The AVX2 and AVX-512 copies of the traversals (libtrace/accel/kd_single.cpp and kd_packet.cpp
# built with RT_LEVEL_AVX2 or RT_LEVEL_AVX512, accel/simd_level.h) may hold vector instructions
# only in their own functions: the level's SplitTree::searchNearest, searchBlocker, tracePacket and
# traceShadowPacket, and the helpers in namespace rt::simd_LEVEL. Any other function in the object
# is an inline function of a header that other files share, and the linker may keep this object's
# copy for every caller, CPUs without the level included; it must have the baseline instructions.
# Besides:
# - AVX-512 instructions (ZMM registers, k masks, registers 16 to 31, all EVEX-only) appear only
#   in the AVX-512 copy, so none reaches a CPU that has AVX2 only;
# - no copy holds a fused multiply-add, which would round differently from the scalar code.
#   scripts/check-simd-isolation.sh LEVEL OBJECT...     (LEVEL: avx2 or avx512)
# Exits 1 with one line "check-simd-isolation ERROR: OBJECT: function: N ... instructions" per
# function that breaks a rule.
set -euo pipefail
level=$1
shift
case "$level" in
    avx2) index=1 ;;
    avx512) index=2 ;;
    *)
        echo "check-simd-isolation ERROR: unknown level '$level' (avx2 or avx512)" >&2
        exit 2
        ;;
esac
status=0
for object in "$@"; do
    # objdump's lines: "ADDRESS <function>:" then "  OFFSET:<tab>MNEMONIC OPERANDS"; VEX and EVEX
    # mnemonics start with v (vmovupd, vaddpd, vzeroupper), AVX-512's mask ones with k (kmovb), no
    # baseline one does in compiled C++.
    report=$(objdump -d --no-show-raw-insn -C "$object" | awk -F'\t' -v object="$object" -v level="$level" \
        -v index_="$index" '
        /^[0-9a-f]+ <.*>:$/ { fn = substr($0, index($0, "<") + 1); sub(/>:$/, "", fn) }
        NF >= 2 && $2 ~ /^[vk]/ { vector[fn]++ }
        NF >= 2 && $2 ~ /%zmm|%k[0-7]|%[xy]mm(1[6-9]|2[0-9]|3[01])/ { avx512[fn]++ }
        NF >= 2 && $2 ~ /^vf(n)?m(add|sub)/ { fma[fn]++ }
        END {
            own = "rt::simd_" level "::|(trace(Shadow)?Packet|search(Nearest|Blocker))<\\(rt::SimdLevel\\)" index_ "(, \\(rt::TriangleTest\\)[0-9](, (true|false))?)?>"
            for (fn in vector)
                if (fn !~ own)
                    printf "check-simd-isolation ERROR: %s: %s: %d vector instructions\n", object, fn, vector[fn]
            if (level != "avx512")
                for (fn in avx512)
                    printf "check-simd-isolation ERROR: %s: %s: %d AVX-512 instructions\n", object, fn, avx512[fn]
            for (fn in fma)
                printf "check-simd-isolation ERROR: %s: %s: %d fused multiply-add instructions\n", object, fn, fma[fn]
        }')
    if [[ -n "$report" ]]; then
        echo "$report" >&2
        status=1
    fi
done
exit "$status"
