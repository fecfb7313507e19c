#!/usr/bin/env bash
# Samples saved by the path tracer's noise threshold (rt-render --noise-threshold) at the same
# mean error as uniform sampling, on the Cornell box (../shared/models/obj/CornellBox-Original,
# lit by its lamp) and a textured model (../shared/models/gltf/Duck, its base colour texture,
# lit by a uniform grey sky only). docs/path-tracing.md ("Noise-adaptive sampling") is this
# script's output.
#
#   bench/noise_threshold.sh [--size 128] [--threshold 0.03] [--max 1024] [--reference 2048]
#                            [--threads 2] [--keep DIR]
#
# Method: per scene, a reference of --reference paths per pixel (another seed); uniform renders of
# 16, 32, ... --max / 2 paths; one adaptive render of at most --max paths a pixel. The error of a
# picture is the mean over pixels and channels of |x - reference| / (reference + 0.01) (as
# bench/compare_images.py). The uniform count that gives the adaptive render's error is read off
# the uniform renders' errors, interpolated in log-log (error falls as a power of the samples);
# the saving is 1 - (the adaptive render's samples / that count). --keep DIR leaves the EXRs there
# (SCENE-adaptive-aov.exr with the samples layer: where each pixel stopped).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
size=128 threshold=0.03 max=1024 reference=2048 threads=2 keep=""
# shellcheck source=bench/rt_bench.bash
source "$here/bench/rt_bench.bash"
readOptions noise_threshold.sh "size threshold max reference threads" -- "$@"
benchSetup noise_threshold.sh
oiiotool --pattern constant:color=0.5,0.5,0.5 64x32 3 -d float -o "$work/grey.exr"

cornell=("$models/obj/CornellBox-Original/CornellBox-Original.obj" --look-from 0,1,3.9 --look-at 0,1,0 --fov 40)
duck=("$models/gltf/Duck/Duck.gltf" --frame --no-default-light --environment "$work/grey.exr")

# The uniform samples a pixel that give error E, from CURVE's "samples error" lines, in log-log:
# uniformFor E CURVE.
uniformFor() {
    python3 - "$1" "$2" <<'PY'
import math, sys
target = float(sys.argv[1])
points = sorted((int(s), float(e)) for s, e in (line.split() for line in sys.argv[2].splitlines()))
# the segment that brackets the target, else the nearest end's segment (extrapolated)
pairs = list(zip(points, points[1:]))
(s0, e0), (s1, e1) = next((p for p in pairs if p[1][1] <= target <= p[0][1]),
                          pairs[-1] if target < points[-1][1] else pairs[0])
slope = math.log(e1 / e0) / math.log(s1 / s0)
print(f"{s0 * (target / e0) ** (1 / slope):.1f}")
PY
}

run() {
    local name="$1"; shift
    local common=(-x "$size" -y "$size" --integrator path --threads "$threads" --alpha off --exr-pixels float -q "$@")
    "$render" "${common[@]}" -S "$reference" --seed 1 -f "$work/$name-ref.exr"
    local s curve=""
    for ((s = 16; s <= max / 2; s *= 2)); do
        "$render" "${common[@]}" -S "$s" -f "$work/$name-$s.exr"
        curve+="$s $(meanRelativeError "$work/$name-$s.exr" "$work/$name-ref.exr")"$'\n'
    done
    "$render" "${common[@]}" -S "$max" --noise-threshold "$threshold" --stats-json "$work/$name-stats.json" \
        --aov samples -f "$work/$name-adaptive-aov.exr"
    oiiotool "$work/$name-adaptive-aov.exr" --ch R,G,B -o "$work/$name-adaptive.exr"
    local taken perPixel adaptiveError needed
    taken=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["samplesTaken"])' "$work/$name-stats.json")
    perPixel=$(awk -v t="$taken" -v n="$size" 'BEGIN { printf "%.1f", t / (n * n) }')
    adaptiveError=$(meanRelativeError "$work/$name-adaptive.exr" "$work/$name-ref.exr")
    needed=$(uniformFor "$adaptiveError" "$curve")
    echo "uniform: $(tr '\n' ' ' <<<"$curve")" >&2
    awk -v n="$name" -v a="$perPixel" -v e="$adaptiveError" -v u="$needed" \
        'BEGIN { printf "| %s | %s | %.5f | %.1f | %.1f %% |\n", n, a, e, u, 100 * (1 - a / u) }'
}

echo "${size}x${size}, --noise-threshold $threshold -S $max, reference $reference paths, $threads threads"
echo "| scene | adaptive: samples a pixel | its mean rel. error | uniform samples a pixel for that error | saved |"
echo "|---|---|---|---|---|"
run cornell "${cornell[@]}"
run duck "${duck[@]}"
