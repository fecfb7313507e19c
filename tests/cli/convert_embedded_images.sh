# Images embedded in a .glb (a bufferView) or a data: URI: rt-convert writes them into the scene's
# folder beside the RAW files, and the materials name them; rt-render reading the model itself
# takes them from memory and leaves no file behind (not in the working folder, not in TMPDIR).
# Both pictures are the same bits, and textured: a generated quad with a red and green 2x2 PNG
# shows red and green; the Duck .glb comes out yellow (its texture), not white.
source "$(dirname "$0")/common.bash"

# mean_channels IMAGE: "r g b", the image's mean colour (oiiotool --printstats).
mean_channels() { oiiotool "$1" --printstats | awk '/Stats Avg:/ { print $3, $4, $5; exit }'; }

python3 - "$WORK/quad.glb" <<'PY'
import base64, struct, sys, json
png = base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAEElEQVR42mP4z8DAAMFAEgAd8AP9Cd2apwAAAABJRU5ErkJggg==")
geometry = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0) + struct.pack("<8f", 0, 1, 1, 1, 1, 0, 0, 0) \
    + struct.pack("<6H", 0, 1, 2, 0, 2, 3)
binary = geometry + png
views = [(0, 48), (48, 32), (80, 12), (92, len(png))]
doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
       "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
       "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0}}],
       "textures": [{"source": 0, "sampler": 0}], "samplers": [{"magFilter": 9728}],
       "images": [{"bufferView": 3, "mimeType": "image/png", "name": "red green"}],
       "buffers": [{"byteLength": len(binary)}],
       "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in views],
       "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                     {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                     {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
text = json.dumps(doc).encode()
text += b" " * (-len(text) % 4)
binary += b"\0" * (-len(binary) % 4)
with open(sys.argv[1], "wb") as f:
    f.write(struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(binary)))
    f.write(struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary)
PY

# Rendered from the .glb in an empty folder with an empty TMPDIR: nothing is left in either.
mkdir -p "$WORK/run" "$WORK/tmp"
(cd "$WORK/run" && TMPDIR="$WORK/tmp" "$RT_RENDER" ../quad.glb -x 32 -y 24 -q -f direct.exr) ||
    fail "rt-render failed on the .glb"
[ "$(ls -A "$WORK/run")" = direct.exr ] || fail "rt-render left files behind: $(ls -A "$WORK/run")"
[ -z "$(ls -A "$WORK/tmp")" ] || fail "rt-render left files in TMPDIR: $(ls -A "$WORK/tmp")"

expect_exit 0 "$RT_CONVERT" "$WORK/quad.glb" -o "$WORK/out/quad.xml"
cmp -s "$WORK/out/quad/red_green.png" <(python3 -c 'import base64,sys; sys.stdout.buffer.write(base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAEElEQVR42mP4z8DAAMFAEgAd8AP9Cd2apwAAAABJRU5ErkJggg=="))') ||
    fail "the embedded PNG was not written as out/quad/red_green.png: $(ls "$WORK/out/quad")"
grep -q 'file="quad/red_green.png"' "$WORK/out/quad.xml" || fail "the texture does not name quad/red_green.png"
(cd "$WORK/out" && "$RT_RENDER" quad.xml -x 32 -y 24 -q -f files.exr) || fail "rt-render failed on the converted scene"
idiff -fail 0 -warn 0 "$WORK/run/direct.exr" "$WORK/out/files.exr" >"$WORK/idiff.txt" ||
    fail "the .glb and the converted scene render differently: $(cat "$WORK/idiff.txt")"
"$RT_CONVERT" "$WORK/quad.glb" -o - 2>/dev/null | "$RT_RENDER" - -x 32 -y 24 -q -f "$WORK/piped.exr" ||
    fail "rt-convert -o - | rt-render - failed"
idiff -fail 0 -warn 0 "$WORK/run/direct.exr" "$WORK/piped.exr" >"$WORK/idiff.txt" ||
    fail "the piped scene (image inline) renders differently: $(cat "$WORK/idiff.txt")"
read -r r g b <<<"$(mean_channels "$WORK/run/direct.exr")"
python3 -c "import sys; r, g, b = map(float, sys.argv[1:]); sys.exit(0 if r > 0.05 and g > 0.05 and b < 0.2 * min(r, g) else 1)" \
    "$r" "$g" "$b" || fail "the quad is not red and green: mean $r $g $b"

need_shared_models
"$RT_RENDER" "$RT_SHARED_DIR/models/glb/Duck/Duck.glb" -x 48 -y 36 -q -f "$WORK/duck.exr" || fail "Duck.glb did not render"
read -r r g b <<<"$(mean_channels "$WORK/duck.exr")"
python3 -c "import sys; r, g, b = map(float, sys.argv[1:]); sys.exit(0 if r > 2 * b else 1)" "$r" "$g" "$b" ||
    fail "the Duck is not yellow (untextured?): mean $r $g $b"
echo "convert_embedded_images: ok"
