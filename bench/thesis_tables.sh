#!/usr/bin/env bash
# Regenerates the measured side of docs/thesis-results.md: thesis Tables 4.1-4.5 with rt's
# figures beside the thesis's (issue 15), and in Tables 4.2-4.4 the wide BVH beside the thesis's two
# trees (issue 37), measured the same way. What it costs: docs/thesis-results.md, Table 4.5.
#
#   bench/thesis_tables.sh                      print the tables (Markdown) on stdout
#   bench/thesis_tables.sh --update docs/thesis-results.md
#                                               replace the parts between the
#                                               <!-- tables:begin --> and <!-- tables:end --> lines
#                                               (Tables 4.1-4.4, Embree) and between
#                                               <!-- compilers:begin/end --> (Table 4.5)
#
# Options: --runs N (10, as the thesis: the mean of N runs; a cell stops early once it has
# spent --budget seconds, default 20, and then says how many runs it had), --no-compilers
# (skip Table 4.5 and its eight builds), --only-compilers (Table 4.5 alone), --no-embree
# (skip the Embree column).
#
# Method, as thesis 4.3: 800x600, shadows on, reflections to depth 3 (-s -d 3), no output
# (-o null). Times are rt-render's own -b figures (wall clock of the tree build and of the
# render): with --threads 1 on an otherwise idle machine that is the CPU time the thesis
# measured. Table 4.5 is measured differently: see compiler_table below.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
runs=10 budget=20 tables=1 compilers=1 embree=1 update=""
while [[ $# -gt 0 ]]; do
    case "$1" in
        --runs) runs="$2"; shift 2 ;;
        --budget) budget="$2"; shift 2 ;;
        --no-compilers) compilers=0; shift ;;
        --only-compilers) tables=0; shift ;;
        --no-embree) embree=0; shift ;;
        --update) update="$2"; shift 2 ;;
        -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
        *) echo "thesis_tables.sh ERROR: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[[ "$runs" =~ ^[1-9][0-9]*$ && "$budget" =~ ^[0-9]+$ ]] ||
    { echo "thesis_tables.sh ERROR: --runs needs a positive integer and --budget seconds" >&2; exit 2; }
if (( compilers )); then
    for tool in g++-12 clang++-14 python3; do
        command -v "$tool" >/dev/null ||
            { echo "thesis_tables.sh ERROR: Table 4.5 needs $tool (scripts/install-deps.sh --checks), or --no-compilers" >&2; exit 2; }
    done
fi

scenes=(balls balls2 ships tree pyramid5)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
log() { echo "thesis_tables: $*" >&2; }

cd "$here"
load="$(cut -d' ' -f1-3 /proc/loadavg)"  # the machine may be shared: the document says how busy it was
if (( tables )); then
    log "building release and release-float"
    for preset in release release-float; do
        cmake --preset "$preset" >/dev/null
        cmake --build --preset "$preset" --target rt-render rt-convert >/dev/null
    done
    for s in "${scenes[@]}"; do
        build/release/tools/convert/rt-convert --generate "$s" -o "$work/$s.xml" -q
    done
fi
render_d=build/release/tools/render/rt-render
render_f=build/release-float/tools/render/rt-render

# measure RENDERER SCENE ARGS...: the mean of the -b line's fields over the runs, as
# "build render total objects lights nodes tests runs".
measure() {
    local renderer="$1" scene="$2"; shift 2
    local n=0 start=$SECONDS lines=""
    while (( n < runs )); do
        lines+="$("$renderer" "$work/$scene.xml" -s -d 3 -x 800 -y 600 -o null -b -q "$@")"$'\n'
        n=$((n + 1))
        (( SECONDS - start >= budget )) && break
    done
    awk 'NF { b += $1; r += $2; n++; rest = $3 " " $4 " " $5 " " $6 }
         END { printf "%.2f %.2f %.2f %s %d\n", b / n, r / n, (b + r) / n, rest, n }' <<<"$lines"
}

declare -A m  # m[renderer/scene/tree/threads] = the measure line
(( tables )) && for s in "${scenes[@]}"; do
    for tree in bsp kd bvh; do
        for threads in 1 2; do
            log "$s $tree, $threads thread(s)"
            m[d/$s/$tree/$threads]="$(measure "$render_d" "$s" --accel "$tree" --threads "$threads")"
        done
    done
    for tree in kd bvh; do
        log "$s $tree, float"
        m[f/$s/$tree/1]="$(measure "$render_f" "$s" --accel "$tree" --threads 1)"
    done
done
field() { awk -v i="$2" '{print $i}' <<<"${m[$1]}"; }

# The thesis's S1 (Core 2 Duo E6420, 2.13 GHz, one thread), Tables 4.2-4.4, per scene:
# BSP build render total, KD build render total / BSP nodes, KD nodes, BSP tests, KD tests /
# double build render, float build render.
declare -A thesis42=([balls]="0.40 0.41 0.82 0.29 0.40 0.69" [balls2]="0.01 3.90 3.90 0.09 2.90 2.99"
    [ships]="0.01 2.40 2.40 0.01 1.90 1.91" [tree]="0.96 148.95 149.92 2.63 2.75 5.37"
    [pyramid5]="0.69 55.29 55.98 4.73 6.87 11.59")
declare -A thesis43=([balls]="3951 12423 27.46 10.19" [balls2]="4379 100157 1101.21 50.37"
    [ships]="1497 1785 11.04 8.67" [tree]="435 7699 1378.85 21.48" [pyramid5]="136363 25391 5.59 10.91")
declare -A thesis44=([balls]="0.29 0.40 0.38 0.55" [balls2]="0.08 2.75 0.08 3.40" [ships]="0.02 2.30 0.02 2.91"
    [tree]="2.67 2.83 2.88 3.50" [pyramid5]="4.78 7.07 3.93 8.27")
declare -A thesis41=([balls]="7383 3" [balls2]="597873 3" [ships]="1017 2" [tree]="180182 7" [pyramid5]="18750 1")
word() { awk -v i="$2" '{print $i}' <<<"$1"; }
ratio() { echo "$1 $2" | awk '{ if ($1 >= 0 && $2 > 0) printf "%.2f", $1 / $2; else printf "-" }'; }

machine() {
    echo "Measured $(date -u '+%Y-%m-%d %H:%M') UTC on $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores), rt $(git rev-parse --short HEAD),"
    echo "load average (1, 5, 15 min) $load before the run, $(cut -d' ' -f1-3 /proc/loadavg) after it."
}

tables() {
    machine
    echo "$(c++ --version | head -1); each cell the mean of up to $runs runs (fewer where a cell passed ${budget} s: the runs column)."
    echo
    echo "#### Table 4.1: the scenes (objects = triangles + spheres)"
    echo
    echo "| scene | objects, thesis | objects, rt | lights, thesis | lights, rt |"
    echo "|---|---:|---:|---:|---:|"
    for s in "${scenes[@]}"; do
        echo "| $s | $(word "${thesis41[$s]}" 1) | $(field "d/$s/kd/1" 4) | $(word "${thesis41[$s]}" 2) | $(field "d/$s/kd/1" 5) |"
    done
    echo
    echo "#### Table 4.2: BSP and KD (and rt's BVH), seconds (build / render / total) and the speed-ups of the total"
    echo
    echo "| scene | tree | thesis S1 | rt, 1 thread | rt, 2 threads | runs |"
    echo "|---|---|---:|---:|---:|---:|"
    for s in "${scenes[@]}"; do
        local t="${thesis42[$s]}"
        for tree in bsp kd bvh; do
            local o=0 thesis="-"; [[ $tree == kd ]] && o=3
            [[ $tree == bvh ]] || thesis="$(word "$t" $((o + 1))) / $(word "$t" $((o + 2))) / $(word "$t" $((o + 3)))"
            echo "| $s | ${tree^^} | $thesis |" \
                "$(field "d/$s/$tree/1" 1) / $(field "d/$s/$tree/1" 2) / $(field "d/$s/$tree/1" 3) |" \
                "$(field "d/$s/$tree/2" 1) / $(field "d/$s/$tree/2" 2) / $(field "d/$s/$tree/2" 3) |" \
                "$(field "d/$s/$tree/1" 8), $(field "d/$s/$tree/2" 8) |"
        done
        echo "| $s | BSP / KD | $(ratio "$(word "$t" 3)" "$(word "$t" 6)") |" \
            "$(ratio "$(field "d/$s/bsp/1" 3)" "$(field "d/$s/kd/1" 3)") |" \
            "$(ratio "$(field "d/$s/bsp/2" 3)" "$(field "d/$s/kd/2" 3)") | |"
        echo "| $s | KD / BVH | - | $(ratio "$(field "d/$s/kd/1" 3)" "$(field "d/$s/bvh/1" 3)") |" \
            "$(ratio "$(field "d/$s/kd/2" 3)" "$(field "d/$s/bvh/2" 3)") | |"
    done
    echo
    echo "#### Table 4.3: tree quality: nodes, and intersection tests per ray"
    echo
    echo "| scene | BSP nodes, thesis | BSP nodes, rt | KD nodes, thesis | KD nodes, rt | BVH nodes, rt | BSP tests/ray, thesis | BSP tests/ray, rt | KD tests/ray, thesis | KD tests/ray, rt | BVH tests/ray, rt |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    for s in "${scenes[@]}"; do
        local t="${thesis43[$s]}"
        echo "| $s | $(word "$t" 1) | $(field "d/$s/bsp/1" 6) | $(word "$t" 2) | $(field "d/$s/kd/1" 6) | $(field "d/$s/bvh/1" 6) |" \
            "$(word "$t" 3) | $(field "d/$s/bsp/1" 7) | $(word "$t" 4) | $(field "d/$s/kd/1" 7) | $(field "d/$s/bvh/1" 7) |"
    done
    echo
    echo "#### Table 4.4: double (D) against float (F), KD (and rt's BVH), one thread, seconds (build / render) and F / D of the total"
    echo
    echo "| scene | D, thesis S1 | F, thesis S1 | F / D, thesis | D, rt | F, rt | F / D, rt | D, rt BVH | F, rt BVH | F / D, rt BVH |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    for s in "${scenes[@]}"; do
        local t="${thesis44[$s]}"
        echo "| $s | $(word "$t" 1) / $(word "$t" 2) | $(word "$t" 3) / $(word "$t" 4) |" \
            "$(awk '{ printf "%.2f", ($3 + $4) / ($1 + $2) }' <<<"$t") |" \
            "$(field "d/$s/kd/1" 1) / $(field "d/$s/kd/1" 2) | $(field "f/$s/kd/1" 1) / $(field "f/$s/kd/1" 2) |" \
            "$(ratio "$(field "f/$s/kd/1" 3)" "$(field "d/$s/kd/1" 3)") |" \
            "$(field "d/$s/bvh/1" 1) / $(field "d/$s/bvh/1" 2) | $(field "f/$s/bvh/1" 1) / $(field "f/$s/bvh/1" 2) |" \
            "$(ratio "$(field "f/$s/bvh/1" 3)" "$(field "d/$s/bvh/1" 3)") |"
    done
    if (( embree )); then embree_table; fi
}

# Table 4.5: the ships render built by g++-12 and clang++-14 at -O2, -O3 and -O3 -march=native
# with geometry in double, and at -O3 in float: eight builds of bench_thesis_frame
# (bench/thesis_frame.cpp and the ray-tracing layers: no importers, OpenImageIO or tools), each in
# build/compilers-NAME, through ccache. It makes ships in memory, renders it in one process again
# and again and reports the CPU time of each frame: ships renders in 0.05 s, and a process of
# rt-render spends 0.3 s more on starting OpenImageIO and loading, which would hide the compilers'
# difference (thesis 4.5 measured 2 s).
compiler_flags=("-O3" "-O2" "-O3 -march=native")  # -O3 first: CMake's Release, the project's own build
float_flags=("-O3")  # float is the thesis's question (4.4, 4.5) at the default flags; a build not in ccache is ~35 s on two cores

# compiler_build CXX FLAGS REAL: configures and builds bench_thesis_frame; prints its path.
compiler_build() {
    local cxx="$1" flags="$2" real="$3"
    local dir="build/compilers-${cxx}${flags// /}-$real"  # two levels deep, as build/release: ccache shares
    # ccache hashes the compiler's name: g++-12 by the presets' name c++ where that is the same
    # compiler, so that the -O3 double build is the release preset's bench_thesis_frame from the cache.
    # The full path: CMake takes a bare name for a change of compiler and starts the build afresh.
    cxx="$(command -v "$cxx")"
    [[ "$(realpath "$cxx")" == "$(realpath "$(command -v c++)")" ]] && cxx="$(command -v c++)"
    cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
        -DCMAKE_CXX_FLAGS_RELEASE="$flags -DNDEBUG" -DRT_REAL="$real" -DRT_BUILD_TESTS=OFF -DRT_BUILD_BENCH=ON \
        >/dev/null
    local TIMEFORMAT="thesis_tables: built $dir in %0R s (CPU %0U + %0S s)"
    time cmake --build "$dir" --target bench_thesis_frame >/dev/null
    echo "$dir/bench/bench_thesis_frame"
}

# frame_seconds BENCH: the mean CPU time of one ships frame, one thread, over --runs repetitions.
frame_seconds() {
    RT_BENCH_THESIS_SCENE=ships RT_BENCH_ACCEL=kd "$1" --benchmark_filter=/threads:1/ \
        --benchmark_repetitions="$runs" --benchmark_min_time=0.5 --benchmark_report_aggregates_only=true \
        --benchmark_format=json 2>/dev/null |
        python3 -c 'import json, sys
b = {x["aggregate_name"]: x for x in json.load(sys.stdin)["benchmarks"] if x.get("run_type") == "aggregate"}
print("%.4f" % (b["mean"]["cpu_time"] / 1000))'  # the unit is ms (bench/render_frames.h)
}

# spread REAL: the slowest over the fastest of compiler_table's t[*/REAL] cells.
spread() {
    local key
    for key in "${!t[@]}"; do [[ $key == */$1 ]] && echo "${t[$key]}"; done |
        sort -g | awk 'NR == 1 { min = $1 } { max = $1 } END { printf "%.2f", max / min }'
}

compiler_table() {
    local start=$SECONDS cxx flags real
    declare -A t=()
    # Double first, every compiler and flag set (the table's grid), then float.
    for real in double float; do
        for flags in "${compiler_flags[@]}"; do
            [[ $real == double || " ${float_flags[*]} " == *" $flags "* ]] || continue
            for cxx in g++-12 clang++-14; do
                t[$cxx/$flags/$real]="$(frame_seconds "$(compiler_build "$cxx" "$flags" "$real")")"
                log "compilers: $cxx $flags, $real: ${t[$cxx/$flags/$real]} s per frame"
            done
        done
    done
    log "compilers: the builds and their measurements took $((SECONDS - start)) s"
    echo "#### Table 4.5: compilers, ships, KD, one thread, CPU seconds per frame (mean of $runs repetitions of bench_thesis_frame)"
    echo
    echo "| compiler | flags | double | float | F / D |"
    echo "|---|---|---:|---:|---:|"
    echo "| thesis S1: GCC 3.4 / 4.1 / 4.2 / 4.3 | (the thesis's Makefile) | 2.51 / 2.02 / 1.98 / 2.18 | 2.36 / 2.41 / 2.37 / 2.53 | 0.94 / 1.19 / 1.20 / 1.16 |"
    for flags in "${compiler_flags[@]}"; do
        for cxx in g++-12 clang++-14; do
            echo "| $($cxx --version | head -1 | sed 's/ (Debian[^)]*)//; s/Debian //') | $flags |" \
                "${t[$cxx/$flags/double]} | ${t[$cxx/$flags/float]:--} | $(ratio "${t[$cxx/$flags/float]:--1}" "${t[$cxx/$flags/double]}") |"
        done
    done
    echo
    echo "Slowest over fastest: double $(spread double), float $(spread float)" \
        "(the thesis's four GCCs: double 1.27, float 1.07). -march=native is $(g++-12 -march=native -Q --help=target |
        awk '$1 == "-march=" { print $2 }') here."
    echo
    machine
}
# The Embree column: bench/vs_embree's rays per second, rt's KD tree against Embree, on the
# thesis scenes (built only where Embree is installed: scripts/install-bench-deps.sh).
embree_table() {
    if ! cmake --build --preset release --target vs_embree >/dev/null 2>&1; then
        log "Embree not installed: no Embree column (scripts/install-bench-deps.sh)"
        return
    fi
    log "vs_embree on the thesis scenes"
    echo
    echo "#### Beside Embree (bench/vs_embree, one pass; see docs/benchmarks.md for its method)"
    build/release/bench/vs_embree --scenes "${scenes[@]}" --passes 1 2>/dev/null | sed -n '/^### /,$p' | sed 's/^### /##### /'
}

# replace NAME TEXT FILE: TEXT between FILE's <!-- NAME:begin --> and <!-- NAME:end --> lines.
replace() {
    local begin="<!-- $1:begin -->" end="<!-- $1:end -->" tmp="$3.tmp.$$"
    grep -qx -- "$begin" "$3" && grep -qx -- "$end" "$3" ||
        { echo "thesis_tables.sh ERROR: $3: no $begin / $end lines" >&2; exit 2; }
    awk -v text="$2" -v begin="$begin" -v end="$end" \
        '$0 == end { print text; skip = 0 } !skip { print } $0 == begin { skip = 1 }' "$3" >"$tmp" && mv "$tmp" "$3"
    log "updated $3 ($1)"
}

for part in tables compilers; do
    (( ${!part} )) || continue
    fn=$part; [[ $part == compilers ]] && fn=compiler_table
    if [[ -z "$update" ]]; then "$fn"; else replace "$part" "$("$fn")" "$update"; fi
done
