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
for model in glb/2CylinderEngine/2CylinderEngine.glb obj/stanford-bunny/stanford-bunny.obj obj/spd-balls/balls_s2.obj; do
    best=999 peak=0
    for _ in $(seq $runs); do
        rm -rf "$work/out" && mkdir "$work/out"
        read -r kb s < <(measure "$convert" "$shared/models/$model" -o "$work/out/scene.xml")
        best=$(awk -v a="$best" -v b="$s" 'BEGIN {print (b < a ? b : a)}')
        peak=$((kb > peak ? kb : peak))
    done
    written=$(du -sb --apparent-size "$work/out" | cut -f1)
    awk -v m="$model" -v t="$best" -v w="$written" -v p="$peak" -v b="$base_kb" 'BEGIN {
        work = (p - b) * 1024
        printf "%-44s %8.2f %9.2fM %9.2fM %9.2fM %9.2fM %7.2f\n", m, t, w / 1e6, p * 1024 / 1e6, b * 1024 / 1e6, work / 1e6, work / w
    }'
done
