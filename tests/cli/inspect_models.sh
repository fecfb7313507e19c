# rt-inspect reads model files through rt-convert's importers, converted in memory; broken
# ones are bad input. The models are the shared test models.
source "$(dirname "$0")/common.bash"
source "$(dirname "$0")/inspect_scenes.bash"
need_shared_models

expect_exit 0 "$RT_INSPECT" --tree kd --json "$RT_SHARED_DIR/models/obj/spd-teapot/teapot_s2.obj"
[ "$(json_number triangles "$WORK/stdout")" = 248 ] || fail "the SPD teapot has 248 triangles (MANIFEST.md)"
expect_exit 2 "$RT_INSPECT" "$RT_SHARED_DIR/models/bad/gltf-IndexOutOfRange/IndexOutOfRange.gltf"
echo "inspect_models: ok"
