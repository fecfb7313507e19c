#!/usr/bin/env bash
# Conversion time and peak memory of rt-convert on the largest shared models, against the
# bytes it writes (scene XML + RAW models); the goal is a peak under 3x what is written.
#   bench/convert.sh [build-dir]        (default: build/release; models from $RT_SHARED_DIR or ../shared)
# Peak memory is the maximum resident set size from /usr/bin/time -v. The process's own
# start-up (code and shared libraries: Assimp, tinygltf, tinyobjloader, libstdc++) is measured apart with
# `rt-convert --version` and reported, so that "work" = peak - start-up is what converting costs.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
convert="$build/tools/convert/rt-convert"
shared=${RT_SHARED_DIR:-../shared}
runs=3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# rss_kb and seconds of one run: "KB SECONDS"
measure() {
    /usr/bin/time -v "$@" 2>"$work/time" >/dev/null || { cat "$work/time" >&2; exit 1; }
    awk -F': ' '/Maximum resident/ {kb=$2} /Elapsed \(wall clock\)/ {n=split($2, t, ":"); s=t[n]+60*t[n-1]} END {print kb, s}' "$work/time"
}

read -r base_kb _ < <(measure "$convert" --version)
printf '%-44s %8s %10s %10s %10s %10s %7s\n' model "time s" "written" "peak" "start-up" "work" "work/written"
# A larger OBJ than any shared one: a 708 x 708 height-field grid, 999,698 triangles (37 MB).
awk 'BEGIN { n = 708
    for (j = 0; j < n; j++) for (i = 0; i < n; i++)
        printf "v %.6f %.6f %.6f\n", i / n, j / n, 0.1 * sin(i * 0.05) * cos(j * 0.05)
    for (j = 0; j < n - 1; j++) for (i = 0; i < n - 1; i++) {
        a = j * n + i + 1; c = a + n
        printf "f %d %d %d\nf %d %d %d\n", a, a + 1, c + 1, a, c + 1, c
    } }' >"$work/grid-1M.obj"

for model in glb/2CylinderEngine/2CylinderEngine.glb obj/stanford-bunny/stanford-bunny.obj obj/spd-balls/balls_s2.obj \
    "$work/grid-1M.obj"; do
    case $model in /*) path=$model model=generated/grid-1M.obj ;; *) path="$shared/models/$model" ;; esac
    best=999 peak=0
    for _ in $(seq $runs); do
        rm -rf "$work/out" && mkdir "$work/out"
        read -r kb s < <(measure "$convert" "$path" -o "$work/out/scene.xml")
        best=$(awk -v a="$best" -v b="$s" 'BEGIN {print (b < a ? b : a)}')
        peak=$((kb > peak ? kb : peak))
    done
    written=$(du -sb --apparent-size "$work/out" | cut -f1)
    awk -v m="$model" -v t="$best" -v w="$written" -v p="$peak" -v b="$base_kb" 'BEGIN {
        work = (p - b) * 1024
        printf "%-44s %8.2f %9.2fM %9.2fM %9.2fM %9.2fM %7.2f\n", m, t, w / 1e6, p * 1024 / 1e6, b * 1024 / 1e6, work / 1e6, work / w
    }'
done
