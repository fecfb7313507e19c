# Standard input and output names (issue 10, item 12), with files made here:
# - rt-convert - reads a glTF 2.0 model from standard input, binary (GLB) or JSON, and says what
#   standard input takes when given anything else (an XML scene);
# - rt-render - and rt-inspect - take a GLB there as well as an XML scene;
# - rt-convert -o with a name not ending in .xml (out.obj) is refused, exit 2, nothing written;
# - a thesis RAW model given to rt-render or rt-inspect is read as one (not by Assimp's RAW reader).
source "$(dirname "$0")/common.bash"

# One triangle (0,0,0) (1,0,0) (0,1,0); the buffer inline as base64 or as the GLB's BIN chunk.
accessor='"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]'
head='{"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"bufferViews":[{"buffer":0,"byteLength":36}],'
printf '%s' "$head$accessor"',"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]}' >"$WORK/tri.gltf"

le32() { printf "\\x$(printf %02x $(($1 & 255)))\\x$(printf %02x $((($1 >> 8) & 255)))\\x00\\x00"; }
json="$head$accessor"',"buffers":[{"byteLength":36}]}'
while [ $((${#json} % 4)) != 0 ]; do json="$json "; done
{
    printf 'glTF'; le32 2; le32 $((12 + 8 + ${#json} + 8 + 36))
    le32 ${#json}; printf 'JSON%s' "$json"
    le32 36; printf 'BIN\x00'
    printf '\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x80\x3f\x00\x00\x00\x00'
} >"$WORK/tri.glb"
expect_exit 0 "$RT_CONVERT" "$WORK/tri.glb" --json
grep -q '"sceneTriangles": 1' "$WORK/stdout" || fail "the hand-made GLB is not one triangle: $(cat "$WORK/stdout")"

# rt-convert - with a GLB and with glTF JSON: the same scene as from the file.
for model in tri.glb tri.gltf; do
    expect_exit 0 "$RT_CONVERT" - -o "$WORK/from-stdin.xml" <"$WORK/$model"
    grep -q "(glTF 2.0" "$WORK/stderr" || fail "$model on stdin: not read as glTF: $(cat "$WORK/stderr")"
    expect_exit 0 "$RT_CONVERT" "$WORK/$model" -o "$WORK/from-file.xml"
    cmp -s "$WORK/from-stdin/mesh0.raw" "$WORK/from-file/mesh0.raw" || fail "$model: stdin and file give different models"
done
expect_exit 0 "$RT_CONVERT" - -o - <"$WORK/tri.glb"
grep -q "<scene" "$WORK/stdout" || fail "rt-convert - -o - wrote no scene"

# Anything else on rt-convert's standard input: exit 2, one line saying what it takes.
"$RT_CONVERT" "$WORK/tri.glb" -o - 2>/dev/null >"$WORK/scene.xml"
expect_exit 2 "$RT_CONVERT" - -o "$WORK/x.xml" <"$WORK/scene.xml"
grep -q "standard input takes a glTF 2.0 model" "$WORK/stderr" || fail "no word on what stdin takes: $(cat "$WORK/stderr")"
[ "$(wc -l <"$WORK/stderr")" = 1 ] || fail "more than one error line: $(cat "$WORK/stderr")"

# rt-render and rt-inspect read a GLB on standard input as well as the XML scene.
for input in tri.glb scene.xml; do
    expect_exit 0 "$RT_RENDER" - -x 8 -y 6 -o null -q <"$WORK/$input"
    expect_exit 0 "$RT_INSPECT" - <"$WORK/$input"
done

# -o names rt's XML scene only.
expect_exit 2 "$RT_CONVERT" "$WORK/tri.glb" -o "$WORK/out.obj"
grep -q "out.obj.*\.xml" "$WORK/stderr" || fail "the refusal does not say rt-convert writes .xml: $(cat "$WORK/stderr")"
[ ! -e "$WORK/out.obj" ] && [ ! -e "$WORK/out" ] || fail "something was written for -o out.obj"

# A thesis RAW model, as rt-convert writes them, read by rt-render and rt-inspect.
raw="$WORK/from-file/mesh0.raw"
expect_exit 0 "$RT_RENDER" "$raw" -x 8 -y 6 -o null
grep -q "RAW: No meshes" "$WORK/stderr" && fail "the RAW model went to Assimp"
expect_exit 0 "$RT_INSPECT" "$raw"
expect_exit 0 "$RT_CONVERT" "$raw" --json
grep -q '"sceneTriangles": 1' "$WORK/stdout" || fail "the RAW model is not one triangle: $(cat "$WORK/stdout")"
echo "convert_stdin_and_outputs: ok"
