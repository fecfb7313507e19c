# A file that is no scene says what it is, in one line and exit 2, in every tool that reads
# scenes: an image given as the scene (an environment map meant for --environment), and a
# model other than glTF on standard input, which takes an rt XML scene or a glTF model only
# (issue 36, item 9).
source "$(dirname "$0")/common.bash"
oiiotool --pattern constant:color=0.5,0.6,0.9 8x4 3 -d half -o "$WORK/sky.exr"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$WORK/model.obj"

for tool in "$RT_RENDER" "$RT_INSPECT" "$RT_CONVERT"; do
    name=$(basename "$tool")
    expect_exit 2 "$tool" "$WORK/sky.exr"
    expect_one_error "$name" "$WORK/sky.exr: is an image, not a model or scene (an environment map goes to rt-render --environment"
done
for tool in "$RT_RENDER" "$RT_INSPECT"; do
    name=$(basename "$tool")
    expect_exit 2 "$tool" - <"$WORK/model.obj"
    expect_one_error "$name" "<stdin>: standard input takes an rt XML scene or a glTF 2.0 model (binary GLB or JSON), and this is neither; give other model files by name"
    # The same model by name is read.
    expect_exit 0 "$tool" "$WORK/model.obj" -q -x 8 -y 6
done
echo "tools_wrong_scene: ok"
