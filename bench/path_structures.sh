#!/usr/bin/env bash
# Which structure the path tracer should use by default (docs/trees.md, "The path tracer's
# structure"): rt-render --integrator path with the KD tree and with the BVH, on the thesis scenes
# (rt-convert --generate, their own cameras) and on models of the shared set, render and build apart.
# A path tracer's rays after the first bounce go every way, so the structure that wins on
# coherent camera rays need not win here.
#
#   bench/path_structures.sh [build-dir] [repeats]   (default: build/release, 3)
#
# Method: 160x120, 4 paths per pixel, --max-bounces 8 (the default), one thread, no output; the
# render's and the build's seconds from --stats-json (renderSeconds, tree.buildSeconds); each scene
# is rendered `repeats` times with kd and bvh in turn, so that both see the same load, and the
# fastest of each kept. Out: one row per scene, then the spread (min / median / max) of KD / BVH
# render time (> 1: the BVH renders faster). Needs rt-render, rt-convert and jq.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
repeats=${2:-3}
models=${RT_MODELS:-/work/shared/models}
[ -d "$models" ] || models=../shared/models
render=$build/tools/render/rt-render
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# "render build" seconds, the fastest of each over the repeats: best ACCEL FILE [OPTIONS...]
best() {
    local accel=$1
    shift
    "$render" "$@" --accel "$accel" --integrator path -S 4 -x 160 -y 120 --threads 1 -o null -q --stats-json - |
        jq -r '"\(.renderSeconds) \(.tree.buildSeconds)"' >>"$work/$accel"
}

row() {  # name file [options...]
    local name=$1
    shift
    rm -f "$work/kd" "$work/bvh"
    for _ in $(seq "$repeats"); do
        best kd "$@"
        best bvh "$@"
    done
    paste "$work/kd" "$work/bvh" | awk -v n="$name" '
        NR == 1 || $1 < kr { kr = $1 } NR == 1 || $2 < kb { kb = $2 } NR == 1 || $3 < br { br = $3 } NR == 1 || $4 < bb { bb = $4 }
        END { printf "| %s | %.3f | %.3f | %.2f | %.3f | %.3f |\n", n, kr, br, kr / br, kb, bb }' | tee -a "$work/rows"
}

echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores; rt-render --integrator path -S 4 -x 160 -y 120 --threads 1"
echo
echo "| Scene | KD render (s) | BVH render (s) | KD / BVH | KD build (s) | BVH build (s) |"
echo "|---|---|---|---|---|---|"
for scene in balls balls2 ships tree pyramid5; do
    "$build/tools/convert/rt-convert" --generate "$scene" -o "$work/$scene.xml" 2>/dev/null
    row "$scene" "$work/$scene.xml"
done
row CornellBox-Original "$models/obj/CornellBox-Original/CornellBox-Original.obj" --look-from 0,1,3.9 --look-at 0,1,0 --fov 40
for model in glb/Duck/Duck.glb glb/2CylinderEngine/2CylinderEngine.glb obj/teapot/teapot.obj \
    obj/stanford-bunny/stanford-bunny.obj glb/TransmissionRoughnessTest/TransmissionRoughnessTest.glb \
    glb/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb; do
    [ -f "$models/$model" ] && row "$(basename "$model")" "$models/$model"
done
echo
awk -F'|' '{ print $5 + 0 }' "$work/rows" | sort -g | awk '{ v[NR] = $1 } END {
    m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    printf "KD / BVH render time over %d scenes: min %.2f, median %.2f, max %.2f\n", NR, v[1], m, v[NR] }'
