# A glTF whose triangles all turn clockwise seen from where their normals point (inverted
# winding) has single-sided materials (glTF's default) culled where they face the camera, so it
# renders hollow: rt-convert's summary and rt-render's warnings say so, and --double-sided (both
# tools) draws it. docs/conversion.md, "Sides".
source "$(dirname "$0")/common.bash"

# A green square in z = 0, its normals +z, its two triangles clockwise seen from +z.
python3 - "$WORK/inverted.gltf" <<'PY'
import base64, json, struct, sys
data = struct.pack("<12f", -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0) + struct.pack("<12f", *[0, 0, 1] * 4) \
    + struct.pack("<6H", 0, 2, 1, 0, 3, 2)
doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "sign"}],
       "meshes": [{"name": "sign", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2,
                                                   "material": 0}]}],
       "materials": [{"name": "paint", "pbrMetallicRoughness": {"baseColorFactor": [0, 1, 0, 1], "metallicFactor": 0}}],
       "buffers": [{"byteLength": len(data),
                    "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
       "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                       {"buffer": 0, "byteOffset": 96, "byteLength": 12}],
       "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                     {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                     {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
open(sys.argv[1], "w").write(json.dumps(doc))
PY
note='1 mesh(es) with most triangles facing away from their vertex normals'

# rt-convert notes it; its scene keeps the material single-sided unless --double-sided.
expect_exit 0 "$RT_CONVERT" "$WORK/inverted.gltf" -o "$WORK/single.xml"
grep -q "note: $note.*--double-sided draws both sides.*: sign$" "$WORK/stderr" ||
    fail "rt-convert does not note the inverted winding: $(cat "$WORK/stderr")"
grep -q 'double_sided="false"' "$WORK/single.xml" || fail "the glTF's material is not single-sided"
expect_exit 0 "$RT_CONVERT" -q "$WORK/inverted.gltf" --double-sided -o "$WORK/both.xml"
grep -q 'double_sided' "$WORK/both.xml" && fail "--double-sided wrote a single-sided material: $(cat "$WORK/both.xml")"

# The green of the centre pixel of a render of $1 seen from +z, with options $2...
green() {
    local scene=$1
    shift
    "$RT_RENDER" "$scene" -x 1 -y 1 --look-from 0,0,4 --look-at 0,0,0 --fov 10 --alpha off --exr-pixels float \
        "$@" -f "$WORK/c.exr" 2>"$WORK/stderr" || fail "the render of $scene $* failed: $(cat "$WORK/stderr")"
    oiiotool --dumpdata "$WORK/c.exr" | awk '/Pixel/ {print $(NF-1)}'
}
above() { awk -v g="$1" -v t="$2" 'BEGIN {exit !(g > t)}'; }

for options in "" "--integrator path -S 4"; do
    # shellcheck disable=SC2086
    {
        hollow=$(green "$WORK/inverted.gltf" $options)
        above "$hollow" 0.01 && fail "$options: the square's culled front is drawn: green $hollow"
        grep -q "warning: $note" "$WORK/stderr" || fail "rt-render does not note the inverted winding: $(cat "$WORK/stderr")"
        drawn=$(green "$WORK/inverted.gltf" --double-sided $options)
        above "$drawn" 0.1 || fail "$options: --double-sided does not draw the square: green $drawn"
        drawn=$(green "$WORK/single.xml" --double-sided $options)
        above "$drawn" 0.1 || fail "$options: --double-sided does not draw the converted scene's square: green $drawn"
        drawn=$(green "$WORK/both.xml" $options)
        above "$drawn" 0.1 || fail "$options: the scene rt-convert --double-sided wrote hides the square: green $drawn"
    }
done
echo "render_inverted_winding: ok"
