#!/usr/bin/env bash
# rt's path tracer against Blender Cycles on the same models: whole images compared in linear
# colour. docs/path-tracing.md ("Against Blender Cycles") is this script's output; not run in CI.
#
#   bench/compare_cycles.sh [--samples 64] [--threads 2] [--only NAME] [--work DIR] [--pictures docs/images]
#                           [--multiscatter] [--equal-time SECONDS [--reference-samples 1024]]
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
# Error at equal time (--equal-time SECONDS): each renderer samples each model for SECONDS (rt's
# --time-limit, Cycles' time_limit; loading, sync and builds left out of both), and its image is
# compared with the same renderer's converged image (--reference-samples paths per pixel, another
# seed, so that the two renders' samples are not the same sequence's): the mean
# relative error of what noise is left. Each against its own reference, so that the differences of
# modelling the table's first columns measure do not count as noise (the reference's own noise adds
# a little to both). The set holds a textured model (the Duck) and a generated terrain of 1,002,528
# triangles (an OBJ written into the work folder), and the clear coat: KHR_materials_clearcoat's
# factors of the Khronos ClearCoatTest model on generated spheres (a glTF written there too).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
samples=64 threads=2 only="" work="" pictures="" multiscatter="" equal_time=0 reference_samples=1024
while [[ $# -gt 0 ]]; do
    case "$1" in
        --samples) samples="$2"; shift 2 ;;
        --threads) threads="$2"; shift 2 ;;
        --only) only="$2"; shift 2 ;;
        --work) work="$2"; shift 2 ;;
        --pictures) pictures="$2"; shift 2 ;;
        --multiscatter) multiscatter=multiscatter; shift ;;
        --equal-time) equal_time="$2"; shift 2 ;;
        --reference-samples) reference_samples="$2"; shift 2 ;;
        -h|--help) sed -n '2,28p' "$0"; exit 0 ;;
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

# A terrain of 2 x 708 x 708 triangles under the sky: makeTerrain OUT.obj
makeTerrain() {
    "$python" - "$1" <<'EOF'
import math, os, sys
path = sys.argv[1]
stem = os.path.splitext(path)[0]
n = 708
with open(stem + ".mtl", "w") as mtl:
    mtl.write("newmtl ground\nKd 0.6 0.6 0.6\nKs 0 0 0\nillum 1\n")
with open(path, "w") as obj:
    obj.write("mtllib %s.mtl\nusemtl ground\n" % os.path.basename(stem))
    for i in range(n + 1):
        for j in range(n + 1):
            x, z = 2.0 * i / n - 1, 2.0 * j / n - 1
            y = 0.15 * math.sin(5 * x) * math.cos(4 * z) + 0.01 * math.sin(97 * x + 13 * z)
            obj.write("v %.6f %.6f %.6f\n" % (x, y, z))
    for i in range(n):
        for j in range(n):
            a = i * (n + 1) + j + 1
            obj.write("f %d %d %d\nf %d %d %d\n" % (a, a + 1, a + n + 2, a, a + n + 2, a + n + 1))
EOF
}

# ClearCoatTest's factors (glTF-Sample-Assets, Models/ClearCoatTest; its textures and coat normals
# left out) on spheres, as docs/images/clearcoat-scene.sh places them for rt, written as a glTF that
# both renderers import: the red base (0.5, 0.02, 0.01; roughness 0.44) under clearcoat 0, 0.5 and 1
# (coat roughness 0.03), the blue base (0.013, 0.022, 0.109; roughness 0.6) under a full coat of
# roughness 0 to 1, a grey floor and an emissive panel above the camera: makeClearcoat OUT.gltf
makeClearcoat() {
    "$python" - "$1" <<'EOF'
import base64, json, math, struct, sys

path = sys.argv[1]
positions, normals, indices = [], [], []
primitives = []  # (first index, index count, material)

def add(verts, norms, tris, material):
    base = len(positions)
    first = len(indices)
    positions.extend(verts)
    normals.extend(norms)
    for t in tris:
        indices.extend(i + base for i in t)
    primitives.append((first, len(indices) - first, material))

def sphere(cx, cy, cz, r, material, rings=24, segments=48):
    verts, norms, tris = [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            norms.append(n)
            verts.append((cx + r * n[0], cy + r * n[1], cz + r * n[2]))
    for i in range(rings):
        for j in range(segments):
            a = i * (segments + 1) + j
            b = a + segments + 1
            if i > 0: tris.append((a, a + 1, b))
            if i < rings - 1: tris.append((a + 1, b + 1, b))
    add(verts, norms, tris, material)

# A horizontal quad at height y, its corners counter-clockwise seen from its front (glTF's rule).
def quad(y, corners, normal, material):
    add([(x, y, z) for x, z in corners], [normal] * 4, [(0, 1, 2), (0, 2, 3)], material)

materials = [
    {"name": "panel", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0},
     "emissiveFactor": [1, 1, 1], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 6}}},
    {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0,
                                               "roughnessFactor": 0.9}},
]
def coated(name, color, roughness, coat, coat_roughness):
    m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": color + [1], "metallicFactor": 0,
                                                "roughnessFactor": roughness}}
    if coat > 0:
        m["extensions"] = {"KHR_materials_clearcoat": {"clearcoatFactor": coat,
                                                       "clearcoatRoughnessFactor": coat_roughness}}
    materials.append(m)
    return len(materials) - 1

# The camera looks along +z: +x is on the picture's left.
quad(6, [(3, -8), (3, -5), (-3, -5), (-3, -8)], (0, -1, 0), 0)       # facing down, above the camera
quad(-2.1, [(-30, 30), (30, 30), (30, -30), (-30, -30)], (0, 1, 0), 1)  # facing up
for x, coat in ((2.4, 0), (0, 0.5), (-2.4, 1)):
    sphere(x, 1.1, 0, 1, coated("red%g" % coat, [0.5, 0.02, 0.01], 0.44, coat, 0.03))
for k, rough in enumerate((0, 0.25, 0.5, 0.75, 1)):
    sphere(4 - 2 * k, -1.1, 0, 0.9, coated("blue%g" % rough, [0.013, 0.022, 0.109], 0.6, 1, rough))

blob = b"".join(struct.pack("<I", i) for i in indices)
index_bytes = len(blob)
blob += b"".join(struct.pack("<3f", *p) for p in positions)
blob += b"".join(struct.pack("<3f", *n) for n in normals)
n = len(positions)
lo = [min(p[a] for p in positions) for a in range(3)]
hi = [max(p[a] for p in positions) for a in range(3)]
views = [{"buffer": 0, "byteOffset": 0, "byteLength": index_bytes, "target": 34963},
         {"buffer": 0, "byteOffset": index_bytes, "byteLength": 12 * n, "target": 34962},
         {"buffer": 0, "byteOffset": index_bytes + 12 * n, "byteLength": 12 * n, "target": 34962}]
accessors = [{"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3", "min": lo, "max": hi},
             {"bufferView": 2, "componentType": 5126, "count": n, "type": "VEC3"}]
meshes = []
for first, count, material in primitives:
    accessors.append({"bufferView": 0, "byteOffset": 4 * first, "componentType": 5125, "count": count,
                      "type": "SCALAR"})
    meshes.append({"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": len(accessors) - 1,
                                   "material": material}]})
doc = {"asset": {"version": "2.0", "generator": "rt bench/compare_cycles.sh (ClearCoatTest's factors)"},
       "extensionsUsed": ["KHR_materials_clearcoat", "KHR_materials_emissive_strength"],
       "scene": 0, "scenes": [{"nodes": list(range(len(meshes)))}],
       "nodes": [{"mesh": i} for i in range(len(meshes))], "meshes": meshes, "materials": materials,
       "accessors": accessors, "bufferViews": views,
       "buffers": [{"byteLength": len(blob),
                    "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}]}
json.dump(doc, open(path, "w"))
EOF
}

echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores, $samples paths per pixel in both"
equal_head="" equal_rule=""
if [[ "$equal_time" != 0 ]]; then
    equal_head=" rt paths in ${equal_time} s | rt error | Cycles paths in ${equal_time} s | Cycles error |"
    equal_rule="---|---|---|---|"
fi
echo "| model | size | model's share | scale | mean rel. error: image / model | rel. RMS: image / model |" \
    "noise: mean rel. error | noise: rel. RMS | rt render s | Cycles sampling s | rt / Cycles |$equal_head"
echo "|---|---|---|---|---|---|---|---|---|---|---|$equal_rule"
# Cycles' paths per pixel: cyclesSamples LOG (the largest N of its "Sample N/M" status lines)
cyclesSamples() {
    grep -o "Sample [0-9]*/" "$1" | tr -dc '0-9\n' | sort -n | tail -1
}

# The equal-time columns: equalTime NAME MODEL SCENE WIDTH HEIGHT BACKGROUND RT-ARGS...
equalTime() {
    local name="$1" model="$2" scene="$3" width="$4" height="$5" background="$6"
    shift 6
    local cycles=(blender -b --factory-startup --python "$here/bench/cycles_render.py" -- "$model" "$scene")
    local rt_paths rt_error cycles_error
    "$render" "$scene" "$@" -S "$reference_samples" --seed 1 -f "$work/$name-rt-converged.exr"
    "$render" "$scene" "$@" -S 1000000 --time-limit "$equal_time" --stats-json "$work/$name-rt-timed.json" \
        -f "$work/$name-rt-timed.exr" 2>/dev/null
    rt_paths=$("$python" -c 'import json, sys; print(json.load(open(sys.argv[1]))["samplesPerPixel"])' \
        "$work/$name-rt-timed.json")
    "${cycles[@]}" "$work/$name-cycles-converged.exr" "$width" "$height" "$reference_samples" $multiscatter \
        "threads=$threads" seed=1 >"$work/$name-cycles-converged.log" 2>&1
    "${cycles[@]}" "$work/$name-cycles-timed.exr" "$width" "$height" 1000000 $multiscatter "threads=$threads" \
        "time=$equal_time" >"$work/$name-cycles-timed.log" 2>&1
    rt_error=$("$python" "$here/bench/compare_images.py" "$work/$name-rt-timed.exr" "$work/$name-rt-converged.exr" \
        --background "$background,$background,$background" --unscaled | cut -d' ' -f1)
    cycles_error=$("$python" "$here/bench/compare_images.py" "$work/$name-cycles-timed.exr" \
        "$work/$name-cycles-converged.exr" --background "$background,$background,$background" --unscaled | cut -d' ' -f1)
    echo " $rt_paths | $rt_error | $(cyclesSamples "$work/$name-cycles-timed.log") | $cycles_error |"
}

# compare NAME MODEL WIDTH HEIGHT BACKGROUND KEEP_LIGHTS [FROM AT FOV]
compare() {
    local name="$1" model="$2" width="$3" height="$4"
    shift 4
    [[ -z "$only" || "$only" == "$name" ]] || return 0
    local scene="$work/$name.xml" rt_seconds cycles_seconds result
    prepareScene "$model" "$scene" "$@"
    local common=(--integrator path -x "$width" -y "$height" --alpha off --exr-pixels float -q)
    local rt=("${common[@]}" -S "$samples")
    rt_seconds=$(rtSeconds "$work/$name-rt.json" "$render" "$scene" "${rt[@]}" -f "$work/$name-rt.exr")
    "$render" "$scene" "${rt[@]}" --seed 1 -f "$work/$name-rt-seed1.exr"
    cycles_seconds=$(cyclesSeconds "$work/$name-cycles.log" blender -b --factory-startup --python \
        "$here/bench/cycles_render.py" -- "$model" "$scene" "$work/$name-cycles.exr" "$width" "$height" "$samples" \
        $multiscatter "threads=$threads")
    result=$("$python" "$here/bench/compare_images.py" "$work/$name-rt.exr" "$work/$name-cycles.exr" \
        --background "$1,$1,$1" --noise "$work/$name-rt-seed1.exr" ${pictures:+--picture "$pictures/cycles-$name.jpg"})
    read -r scale coverage mre rms model_mre model_rms noise_mre noise_rms noise_model_mre noise_model_rms <<<"$result"
    local equal=""
    [[ "$equal_time" == 0 ]] || equal=$(equalTime "$name" "$model" "$scene" "$width" "$height" "$1" "${common[@]}" \
        --threads "$threads")
    echo "| $name | ${width}x$height | $coverage | $scale | $mre / $model_mre | $rms / $model_rms |" \
        "$noise_mre / $noise_model_mre | $noise_rms / $noise_model_rms | $rt_seconds | $cycles_seconds |" \
        "$(awk -v r="$rt_seconds" -v c="$cycles_seconds" 'BEGIN { printf "%.2f", r / c }') |$equal"
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
compare Duck "$models/glb/Duck/Duck.glb" 320 240 0.5 no
if [[ -z "$only" || "$only" == Terrain1M ]]; then
    makeTerrain "$work/terrain1m.obj"
    compare Terrain1M "$work/terrain1m.obj" 320 240 0.5 no 0,0.9,1.7 0,-0.1,0 50
fi
if [[ -z "$only" || "$only" == ClearCoat ]]; then
    makeClearcoat "$work/clearcoat.gltf"
    compare ClearCoat "$work/clearcoat.gltf" 200 150 0.25 no 0,0.3,-13 0,0,0 52
fi
