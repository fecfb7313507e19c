# Values beyond what rt's scenes hold are checked once, where a model is imported (libtrace/import),
# so rt-convert and rt-render reading the model give the same answer: a glTF value out of range
# is exit 2 naming the file and the field (before: rt-convert wrote a scene rt-render refused,
# such as specular="-nan", and rt-render drew the model with NaN samples blacked out); an MTL
# texture option out of range takes its default with a note, as a bad material file is notes.
# The XML loader holds a <texture>'s transform to the same bound, and --exposure takes no NaN.
source "$(dirname "$0")/common.bash"

# A glTF file of one triangle, its material, texture, camera and light changed by the test's JSON
# patch: gltf NAME PYTHON-STATEMENTS (on `g`, the document).
gltf() {
    python3 - "$WORK/$1.gltf" "$2" <<'PY'
import base64, json, struct, sys
points = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
uvs = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
data = points + uvs
g = {
    "asset": {"version": "2.0"},
    "extensionsUsed": ["KHR_materials_ior", "KHR_texture_transform", "KHR_materials_emissive_strength",
                       "KHR_lights_punctual"],
    "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
        {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
    "images": [{"uri": "white.png"}],
    "textures": [{"source": 0}],
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
    "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.3, 0.3, 3]}],
    "scenes": [{"nodes": [0, 1]}],
}
m = g["materials"][0]
exec(sys.argv[2])
json.dump(g, open(sys.argv[1], "w"))
PY
}
# A white 1 x 1 PNG beside the models.
python3 - "$WORK/white.png" <<'PY'
import struct, sys, zlib
def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 2, 0, 0, 0))
png += chunk(b"IDAT", zlib.compress(b"\x00\xff\xff\xff")) + chunk(b"IEND", b"")
open(sys.argv[1], "wb").write(png)
PY

gltf ok 'pass'
expect_exit 0 "$RT_CONVERT" "$WORK/ok.gltf" -o "$WORK/ok.xml"
expect_exit 0 "$RT_RENDER" "$WORK/ok.xml" -x 16 -y 12 -q -o null

# case NAME FIELD PATCH: both tools refuse the file with one line naming it and the field.
case_refused() {
    gltf "$1" "$3"
    expect_exit 2 "$RT_CONVERT" "$WORK/$1.gltf" -o "$WORK/$1.xml"
    expect_one_error rt-convert "$1.gltf: .*$2"
    [ ! -e "$WORK/$1.xml" ] || fail "$1: rt-convert wrote a scene"
    expect_exit 2 "$RT_RENDER" "$WORK/$1.gltf" -x 16 -y 12 -q -o null
    expect_one_error rt-render "$1.gltf: .*$2"
}
case_refused ior 'material 0 ior 1e+300 is out of range' \
    'm["extensions"] = {"KHR_materials_ior": {"ior": 1e300}}'
case_refused base 'material 0 baseColorFactor 1e+300 is out of range' \
    'm["pbrMetallicRoughness"]["baseColorFactor"] = [1e300, 1, 1, 1]'
case_refused emissive 'material 0 emissiveFactor 1e+300 is out of range' 'm["emissiveFactor"] = [1e300, 0, 0]'
case_refused strength 'material 0 emissiveStrength 1e+300 is out of range' \
    'm["emissiveFactor"] = [1, 1, 1]; m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 1e300}}'
case_refused product 'material 0: emissiveFactor times emissiveStrength is beyond 1e15' \
    'm["emissiveFactor"] = [1e10, 1, 1]; m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 1e10}}'
case_refused cutoff_high 'material 0 alphaCutoff 1e+300 is out of range' 'm["alphaMode"] = "MASK"; m["alphaCutoff"] = 1e300'
case_refused cutoff_negative 'material 0 alphaCutoff -1 is out of range' 'm["alphaMode"] = "MASK"; m["alphaCutoff"] = -1'
for key in scale offset; do
    case_refused "transform_$key" "baseColorTexture $key 1e+300 is out of range" \
        "m['pbrMetallicRoughness']['baseColorTexture']['extensions'] = {'KHR_texture_transform': {'$key': [1e300, 1]}}"
done
case_refused transform_rotation 'baseColorTexture rotation 1e+300 is out of range' \
    'm["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {"KHR_texture_transform": {"rotation": 1e300}}'
case_refused aspect 'camera 0: yfov 0.8 and aspectRatio 1e+300 make a horizontal fov of 180 degrees or more' \
    'g["cameras"][0]["perspective"]["aspectRatio"] = 1e300'
case_refused shear "camera 0: its node's matrix makes the view and up directions parallel" \
    'g["nodes"][1] = {"camera": 0, "matrix": [1, 0, 0, 0, 1e300, 1, 0, 0, 0, 0, 1, 0, 0.3, 0.3, 3, 1]}'
case_refused light 'light 0 intensity 3.4e+38 is out of range' \
    'g["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 3.4e38}]}}; g["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}}); g["scenes"][0]["nodes"].append(2)'

# MTL texture options beyond range: the default and a note, and a scene rt-render draws without NaN.
cat >"$WORK/m.obj" <<'OBJ'
mtllib m.mtl
v 0 0 0
v 1 0 0
v 0 1 0
vt 0 0
vt 1 0
vt 0 1
usemtl hostile
f 1/1 2/2 3/3
OBJ
for option in '-s 1e39 1e39 1' '-o 0 1e39 0' '-bm 1e39'; do
    map=map_Kd
    [ "$option" = '-bm 1e39' ] && map=map_bump
    printf 'newmtl hostile\nKd 1 1 1\n%s %s white.png\n' "$map" "$option" >"$WORK/m.mtl"
    expect_exit 0 "$RT_CONVERT" "$WORK/m.obj" -o "$WORK/m.xml"
    grep -q "texture white.png: ${option%% *} .*inf.* is out of range (at most 1e6 in magnitude): [01] used" "$WORK/stderr" ||
        fail "MTL $option: no note: $(cat "$WORK/stderr")"
    expect_exit 0 "$RT_RENDER" "$WORK/m.xml" -x 16 -y 12 -o null
    ! grep -q "non-finite" "$WORK/stderr" || fail "MTL $option: the converted scene renders NaN: $(cat "$WORK/stderr")"
    expect_exit 0 "$RT_RENDER" "$WORK/m.obj" -x 16 -y 12 -o null
    ! grep -q "non-finite" "$WORK/stderr" || fail "MTL $option: the model renders NaN: $(cat "$WORK/stderr")"
done

# The XML loader's <texture> transform: the same bound, with the line.
for attribute in 'scale="1e39 1"' 'offset="1 1e39"' 'rotation="1e39"' 'rotation="2e6"'; do
    cat >"$WORK/t.xml" <<XML
<scene>
  <camera fov="50"><origin x="0" y="0" z="-5" /><destination x="0" y="0" z="0" /></camera>
  <textures><texture name="t" type="checker" $attribute /></textures>
  <materials><material name="m" texture="t" /></materials>
  <objects><sphere x="0" y="0" z="0" r="1" material="m" /></objects>
  <lights><light x="0" y="5" z="-5" /></lights>
</scene>
XML
    expect_exit 2 "$RT_RENDER" "$WORK/t.xml" -x 16 -y 12 -q -o null
    expect_one_error rt-render "t.xml:3: .*out of range"
done

# --exposure nan was a black PNG.
expect_exit 2 "$RT_RENDER" "$WORK/ok.xml" -x 16 -y 12 -q --exposure nan -f "$WORK/nan.png"
expect_one_error rt-render "--exposure: nan is not in -64-64"
[ ! -e "$WORK/nan.png" ] || fail "--exposure nan wrote a picture"
echo "convert_out_of_range: ok"
