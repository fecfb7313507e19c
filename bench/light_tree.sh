#!/usr/bin/env bash
# The path tracer's light tree against choosing lights in proportion to power
# (rt-render --light-sampler tree|power): each one's error against a converged reference at the
# same paths per pixel, and its render seconds, on a generated scene of many small lamps and on the
# shared models with several emitters. docs/path-tracing.md ("Many lights") is this script's output.
#
#   bench/light_tree.sh [--size 160] [--samples 16] [--reference 1024] [--threads 2] [--keep DIR]
#
# Scenes: "lamps", 400 small emissive quads of random colours scattered under a ceiling over a floor
# with spheres (written by this script), and ../shared/models' EmissiveStrengthTest (five emissive
# cubes), LightsPunctualLamp (five punctual lights) and the Cornell box (one lamp: the two samplers
# should tie). The reference is the tree's with --reference paths and another seed. Error: the mean
# over pixels and channels of |x - reference| / (reference + 0.01), and the RMS difference over the
# reference's mean (as bench/compare_images.py).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
size=160 samples=16 reference=1024 threads=2 keep=""
# shellcheck source=bench/rt_bench.bash
source "$here/bench/rt_bench.bash"
readOptions light_tree.sh "size samples reference threads" -- "$@"
benchSetup light_tree.sh

# The "lamps" scene: 400 lamps 0.3 wide, facing down, at heights 1.5 to 3.5 over a 20 x 20 floor.
lampsScene() {
    cat <<'XML'
<?xml version="1.0" ?>
<scene>
  <background r="0" g="0" b="0" />
  <camera fov="60"> <origin x="0" y="9" z="-14" /> <destination x="0" y="0" z="0" /> </camera>
  <materials>
    <material name="floor" r="0.6" g="0.6" b="0.6" metallic="0" roughness="0.8" />
    <material name="ball" r="0.7" g="0.5" b="0.3" metallic="0" roughness="0.4" />
    <material name="red" r="0" g="0" b="0" emission="8 1 1" />
    <material name="green" r="0" g="0" b="0" emission="1 8 1" />
    <material name="blue" r="0" g="0" b="0" emission="1 1 8" />
  </materials>
  <objects>
    <quad material="floor">
      <vertex x="-10" y="0" z="-10" /> <vertex x="-10" y="0" z="10" />
      <vertex x="10" y="0" z="10" /> <vertex x="10" y="0" z="-10" />
    </quad>
XML
    awk 'BEGIN {
        srand(7); split("red green blue", colour, " ")
        for (i = 0; i < 400; ++i) {
            x = -10 + 20 * rand(); z = -10 + 20 * rand(); y = 1.5 + 2 * rand()
            printf "    <quad material=\"%s\">", colour[1 + i % 3]
            printf " <vertex x=\"%.3f\" y=\"%.3f\" z=\"%.3f\" />", x, y, z
            printf " <vertex x=\"%.3f\" y=\"%.3f\" z=\"%.3f\" />", x + 0.3, y, z
            printf " <vertex x=\"%.3f\" y=\"%.3f\" z=\"%.3f\" />", x + 0.3, y, z + 0.3
            printf " <vertex x=\"%.3f\" y=\"%.3f\" z=\"%.3f\" /> </quad>\n", x, y, z + 0.3
        }
        for (i = 0; i < 12; ++i)
            printf "    <sphere x=\"%.2f\" y=\"0.8\" z=\"%.2f\" r=\"0.8\" material=\"ball\" />\n", -8 + 16 * rand(), -8 + 16 * rand()
    }'
    echo "  </objects>"
    echo "</scene>"
}
lampsScene >"$work/lamps.xml"

# The mean relative error and the relative RMS difference of two float EXRs: errors X REFERENCE.
errors() {
    local squared mean
    squared=$(channelMean "$1" "$2" --sub --dup --mul)
    mean=$(channelMean "$2")
    echo "$(meanRelativeError "$1" "$2") $(awk -v s="$squared" -v m="$mean" 'BEGIN { printf "%.4f", sqrt(s) / m }')"
}

seconds() { python3 -c 'import json, sys; print("%.2f" % json.load(open(sys.argv[1]))["renderSeconds"])' "$1"; }

run() {
    local name="$1"; shift
    local common=(-x "$size" -y "$size" --integrator path --threads "$threads" --alpha off --exr-pixels float -q "$@")
    "$render" "${common[@]}" -S "$reference" --seed 1 -f "$work/$name-ref.exr"
    local sampler row="| $name |"
    for sampler in power tree; do
        "$render" "${common[@]}" -S "$samples" --light-sampler "$sampler" --stats-json "$work/$name-$sampler.json" \
            -f "$work/$name-$sampler.exr"
        read -r mre rms <<<"$(errors "$work/$name-$sampler.exr" "$work/$name-ref.exr")"
        row+=" $mre / $rms | $(seconds "$work/$name-$sampler.json") |"
    done
    echo "$row"
}

echo "${size}x${size}, $samples paths per pixel, reference $reference paths, $threads threads," \
    "load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| scene | power: mean rel. error / rel. RMS | power s | tree: mean rel. error / rel. RMS | tree s |"
echo "|---|---|---|---|---|"
run lamps "$work/lamps.xml"
run EmissiveStrengthTest "$models/glb/EmissiveStrengthTest/EmissiveStrengthTest.glb"
run LightsPunctualLamp "$models/gltf/LightsPunctualLamp/LightsPunctualLamp.gltf"
run CornellBox-Original "$models/obj/CornellBox-Original/CornellBox-Original.obj" \
    --look-from 0,1,3.9 --look-at 0,1,0 --fov 40
