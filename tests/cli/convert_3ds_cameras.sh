# 3DS cameras (issue 10, item 2): the cameras of shared/models/3ds/TargetCameraAnim and
# CameraRollAnim are taken from the files' camera chunks, so the picture through them shows the
# box (before, Assimp's values gave a camera at twice its position looking straight up: an
# empty picture). --camera auto ignores the file's camera and frames the scene.
source "$(dirname "$0")/common.bash"
need_shared_models
MODELS="$RT_SHARED_DIR/models/3ds"

for name in TargetCameraAnim CameraRollAnim; do
    model="$MODELS/$name/$name.3ds"
    expect_exit 0 "$RT_CONVERT" "$model" --json
    python3 -c 'import json,sys; assert json.load(sys.stdin)["cameras"] == {"inFile": 1, "used": "Camera01", "generated": False}' \
        <"$WORK/stdout" ||
        fail "$name: the file's camera is not used: $(cat "$WORK/stdout")"
    expect_exit 0 "$RT_CONVERT" "$model" --camera auto --json
    python3 -c 'import json,sys; assert json.load(sys.stdin)["cameras"] == {"inFile": 1, "used": None, "generated": True}' \
        <"$WORK/stdout" ||
        fail "$name: --camera auto did not frame the scene: $(cat "$WORK/stdout")"

    # The box covers part of the 40x15 text picture (one character per pixel, blank where no
    # surface is seen), through the file's camera and through the framing one.
    expect_exit 0 "$RT_CONVERT" "$model" --camera auto -o "$WORK/auto.xml"
    for scene in "$model" "$WORK/auto.xml"; do
        expect_exit 0 "$RT_RENDER" "$scene" -x 40 -y 15 -o text -q
        seen=$(tr -d ' \n' <"$WORK/stdout" | wc -c)
        [ "$seen" -ge 30 ] && [ "$seen" -le 570 ] ||
            fail "$name through $scene: $seen of 600 pixels show the model: $(cat "$WORK/stdout")"
    done
done
echo "convert_3ds_cameras: ok"
