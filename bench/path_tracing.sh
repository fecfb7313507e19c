#!/usr/bin/env bash
# Paths per second of the path tracer (rt-render --integrator path) on 1 and 2 threads, on the
# Cornell box (../shared/models/obj/CornellBox-Original, lit by its lamp) and on a 1M-triangle
# scene (../shared/models/glb/MetalRoughSpheresNoTextures, 1.04 M triangles, lit by rt's default light). docs/benchmarks.md ("Path tracing") is this script's output.
#
#   bench/path_tracing.sh [--samples 16] [--repeat 2]
#
# Method: the KD tree, --max-bounces 8 (the default), one picture per configuration and repeat;
# paths per second = pixels x samples / the render's wall-clock seconds (rt-render's -b figure,
# which leaves out loading and the tree's build); the best of the repeats is kept. Both thread
# counts run in the same invocation, so their ratio is measured under the same load.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
samples=16 repeat=2
while [[ $# -gt 0 ]]; do
    case "$1" in
        --samples) samples="$2"; shift 2 ;;
        --repeat) repeat="$2"; shift 2 ;;
        -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
        *) echo "path_tracing.sh ERROR: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
models="$here/../shared/models"
if [[ ! -d "$models" ]]; then
    echo "path_tracing.sh ERROR: $models: no shared models" >&2
    exit 1
fi
cd "$here"
cmake --preset release >/dev/null
cmake --build --preset release --target rt-render >/dev/null
render=build/release/tools/render/rt-render

# the best render seconds of $repeat runs, and the primitives: bestSeconds THREADS ARGS...
bestSeconds() {
    local threads="$1" best="" line
    shift
    for ((i = 0; i < repeat; ++i)); do
        line=$("$render" "$@" --integrator path -S "$samples" --threads "$threads" -o null -q -b)
        best=$(awk -v a="${line#* }" -v b="$best" 'BEGIN { split(a, f, " "); print (b == "" || f[1] < b) ? f[1] : b }')
    done
    echo "$best $(echo "$line" | awk '{print $3}')"
}

echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores, $samples paths per pixel"
echo "| scene | primitives | pixels | 1 thread | 2 threads | 2 / 1 |"
echo "|---|---|---|---|---|---|"
row() {
    local name="$1" width="$2" height="$3"
    shift 3
    local one two paths triangles
    read -r one triangles < <(bestSeconds 1 "$@" -x "$width" -y "$height")
    read -r two triangles < <(bestSeconds 2 "$@" -x "$width" -y "$height")
    paths=$((width * height * samples))
    awk -v n="$name" -v t="$triangles" -v w="$width" -v h="$height" -v p="$paths" -v a="$one" -v b="$two" 'BEGIN {
        printf "| %s | %s | %dx%d | %.3f M paths/s | %.3f M paths/s | %.2fx |\n", n, t, w, h, p / a / 1e6, p / b / 1e6, a / b }'
}
row CornellBox-Original 256 256 "$models/obj/CornellBox-Original/CornellBox-Original.obj" \
    --look-from 0,1,3.9 --look-at 0,1,0 --fov 40
row MetalRoughSpheresNoTextures 160 120 \
    "$models/glb/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb"
