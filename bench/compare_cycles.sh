#!/usr/bin/env bash
# rt's path tracer against Blender Cycles on the same models: whole images compared in linear
# colour. docs/path-tracing.md ("Against Blender Cycles") is this script's output; not run in CI.
#
#   bench/compare_cycles.sh [--samples 64] [--threads 2] [--only NAME] [--work DIR] [--pictures docs/images]
#                           [--multiscatter]
#
# Needs Blender with its glTF importer and numpy, and OpenImageIO's Python bindings (Debian 12):
#   apt-get install blender python3-numpy python3-openimageio
# For each model: rt-convert writes rt's scene (its camera: the file's, or rt's framing one); the
# script sets its background (a constant sky of that radiance, or black) and drops rt's default
# light, so that both renderers see the same lights; rt-render --integrator path renders it (and
# again with --seed 1, for the noise floor), bench/cycles_render.py renders the model in Cycles
# from that scene's camera, background and lights, and bench/compare_images.py compares the two
# EXRs: the scale that matches exposure (mean of Cycles / mean of rt), then the mean relative
# error and the relative RMS difference, and writes rt | Cycles | error side by side.
# --multiscatter gives Cycles' Principled BSDFs multiple-scattering GGX (the importer's is single).
# Time at equal paths per pixel, both on --threads threads: rt's render seconds (--stats-json
# renderSeconds: loading and the tree's build left out) against Cycles' sampling seconds (the Time of
# Blender's "Finished" status line less that of its "Sample 0/N" line: sync, BVH build and kernel
# loading left out).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
samples=64 threads=2 only="" work="" pictures="" multiscatter=""
while [[ $# -gt 0 ]]; do
    case "$1" in
        --samples) samples="$2"; shift 2 ;;
        --threads) threads="$2"; shift 2 ;;
        --only) only="$2"; shift 2 ;;
        --work) work="$2"; shift 2 ;;
        --pictures) pictures="$2"; shift 2 ;;
        --multiscatter) multiscatter=multiscatter; shift ;;
        -h|--help) sed -n '2,21p' "$0"; exit 0 ;;
        *) echo "compare_cycles.sh ERROR: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
python=/usr/bin/python3 # Debian's, where python3-numpy and python3-openimageio install
models="$here/../shared/models"
for need in blender "$python"; do
    if ! command -v "$need" >/dev/null; then
        echo "compare_cycles.sh ERROR: $need not found (apt-get install blender python3-numpy python3-openimageio)" >&2
        exit 1
    fi
done
if ! "$python" -c 'import numpy, OpenImageIO' 2>/dev/null; then
    echo "compare_cycles.sh ERROR: $python lacks numpy or OpenImageIO (apt-get install python3-numpy python3-openimageio)" >&2
    exit 1
fi
if [[ ! -d "$models" ]]; then
    echo "compare_cycles.sh ERROR: $models: no shared models" >&2
    exit 1
fi
work="${work:-$(mktemp -d)}"
mkdir -p "$work" ${pictures:+"$pictures"}
cd "$here"
cmake --preset release >/dev/null
cmake --build --preset release --target rt-render rt-convert >/dev/null
render="$here/build/release/tools/render/rt-render"
convert="$here/build/release/tools/convert/rt-convert"

# rt's scene for the comparison: prepareScene MODEL OUT.xml BACKGROUND KEEP_LIGHTS [FROM AT FOV]
prepareScene() {
    "$convert" -q "$1" -o "$2"
    "$python" - "$@" <<'EOF'
import sys, xml.etree.ElementTree as ElementTree
_, _, path, background, keep_lights, *view = sys.argv
tree = ElementTree.parse(path)
root = tree.getroot()
for channel in "rgb":
    root.find("background").set(channel, background)
lights = root.find("lights")
if keep_lights == "no" and lights is not None:
    root.remove(lights)
if view:
    camera = root.find("camera")
    for name, value in zip(("origin", "destination"), view[:2]):
        for axis, number in zip("xyz", value.split(",")):
            camera.find(name).set(axis, number)
    camera.set("fov", view[2])
    camera.set("zoom", "100")
tree.write(path)
EOF
}

# rt's render seconds: rtSeconds JSON RT-RENDER-ARGS... (the render's --stats-json goes to JSON)
rtSeconds() {
    local json="$1"
    shift
    "$@" --threads "$threads" --stats-json "$json" 2>"$work/last.log" || { cat "$work/last.log" >&2; return 1; }
    "$python" -c 'import json, sys; print("%.2f" % json.load(open(sys.argv[1]))["renderSeconds"])' "$json"
}

# Cycles' sampling seconds: cyclesSeconds LOG BLENDER-ARGS... (Blender's standard output goes to LOG)
cyclesSeconds() {
    local log="$1"
    shift
    "$@" >"$log" 2>&1 || { cat "$log" >&2; return 1; }
    awk -F'|' '
        function seconds(field) { split(substr(field, index(field, ":") + 1), t, ":"); return t[1] * 60 + t[2] }
        { for (i = 1; i <= NF; ++i) if ($i ~ /^ *Time:/) time = seconds($i) }
        /\| Sample 0\// && start == "" { start = time }
        /\| Finished/ { end = time }
        END { if (start == "" || end == "") exit 1; printf "%.2f\n", end - start }' "$log"
}

echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores, $samples paths per pixel in both"
echo "| model | size | model's share | scale | mean rel. error: image / model | rel. RMS: image / model |" \
    "noise: mean rel. error | noise: rel. RMS | rt render s | Cycles sampling s | rt / Cycles |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
# compare NAME MODEL WIDTH HEIGHT BACKGROUND KEEP_LIGHTS [FROM AT FOV]
compare() {
    local name="$1" model="$2" width="$3" height="$4"
    shift 4
    [[ -z "$only" || "$only" == "$name" ]] || return 0
    local scene="$work/$name.xml" rt_seconds cycles_seconds result
    prepareScene "$model" "$scene" "$@"
    local rt=(--integrator path -S "$samples" -x "$width" -y "$height" --alpha off --exr-pixels float -q)
    rt_seconds=$(rtSeconds "$work/$name-rt.json" "$render" "$scene" "${rt[@]}" -f "$work/$name-rt.exr")
    "$render" "$scene" "${rt[@]}" --seed 1 -f "$work/$name-rt-seed1.exr"
    cycles_seconds=$(cyclesSeconds "$work/$name-cycles.log" blender -b --factory-startup --python \
        "$here/bench/cycles_render.py" -- "$model" "$scene" "$work/$name-cycles.exr" "$width" "$height" "$samples" \
        $multiscatter "threads=$threads")
    result=$("$python" "$here/bench/compare_images.py" "$work/$name-rt.exr" "$work/$name-cycles.exr" \
        --background "$1,$1,$1" --noise "$work/$name-rt-seed1.exr" ${pictures:+--picture "$pictures/cycles-$name.jpg"})
    read -r scale coverage mre rms model_mre model_rms noise_mre noise_rms noise_model_mre noise_model_rms <<<"$result"
    echo "| $name | ${width}x$height | $coverage | $scale | $mre / $model_mre | $rms / $model_rms |" \
        "$noise_mre / $noise_model_mre | $noise_rms / $noise_model_rms | $rt_seconds | $cycles_seconds |" \
        "$(awk -v r="$rt_seconds" -v c="$cycles_seconds" 'BEGIN { printf "%.2f", r / c }') |"
}
compare MetalRoughSpheresNoTextures "$models/glb/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb" \
    320 240 0.5 no
compare TransmissionRoughnessTest "$models/glb/TransmissionRoughnessTest/TransmissionRoughnessTest.glb" \
    384 240 0.5 no 0.2,0.05,1.5 0.2,0,0 40
compare EmissiveStrengthTest "$models/glb/EmissiveStrengthTest/EmissiveStrengthTest.glb" 320 240 0 no
compare NormalTangentMirrorTest "$models/glb/NormalTangentMirrorTest/NormalTangentMirrorTest.glb" 320 240 0.5 no
compare LightsPunctualLamp "$models/gltf/LightsPunctualLamp/LightsPunctualLamp.gltf" 320 240 0 yes
compare CornellBox-Original "$models/obj/CornellBox-Original/CornellBox-Original.obj" 256 256 0 no \
    0,1,3.9 0,1,0 40
