# Turntables: --orbit N renders N frames around the look-at point into -f out_####.png (Blender's
# convention), the tree built once; --frames A..B renders some of them; frame 0 is the plain render.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/transforms.xml"
opts=(-s -x 40 -y 30 --exr-pixels float --progress lines)

expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" --orbit 4 -f "$WORK/turn/f_###.exr" --stats-json "$WORK/turn/s_#.json"
[ "$(grep -c "tree built" "$WORK/stderr")" = 1 ] || fail "the tree was not built exactly once: $(cat "$WORK/stderr")"
for f in 000 001 002 003; do [ -f "$WORK/turn/f_$f.exr" ] || fail "no frame $f: $(ls "$WORK/turn")"; done
for f in 0 1 2 3; do grep -q '"cameraRays": 1200' "$WORK/turn/s_$f.json" || fail "no statistics for frame $f"; done
"$RT_RENDER" "$scene" "${opts[@]}" -q -f "$WORK/plain.exr"
idiff -fail 0 -warn 0 "$WORK/plain.exr" "$WORK/turn/f_000.exr" >/dev/null || fail "frame 0 is not the plain render"
if idiff -fail 0 -warn 0 "$WORK/plain.exr" "$WORK/turn/f_001.exr" >/dev/null; then fail "frame 1 did not turn"; fi

# A farm's array job renders its share; the frames are the same bits.
expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" -q --orbit 4 --frames 2..3 -f "$WORK/part/f_###.exr"
[ "$(ls "$WORK/part")" = "$(printf 'f_002.exr\nf_003.exr')" ] || fail "--frames 2..3 wrote: $(ls "$WORK/part")"
idiff -fail 0 -warn 0 "$WORK/part/f_003.exr" "$WORK/turn/f_003.exr" >/dev/null || fail "frame 3 differs between runs"
expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" -q --orbit 4 --frames 1 -f "$WORK/one/f_#.exr"
[ "$(ls "$WORK/one")" = f_1.exr ] || fail "--frames 1 wrote: $(ls "$WORK/one")"

expect_exit 2 "$RT_RENDER" "$scene" -q --orbit 4 -f "$WORK/no-number.png"
expect_one_error rt-render "needs #### where the frame number goes"
expect_exit 2 "$RT_RENDER" "$scene" -q --frames 1..2 -f "$WORK/f_#.png"
expect_one_error rt-render "--frames needs --orbit"
expect_exit 2 "$RT_RENDER" "$scene" -q --orbit 4 --frames 3..4 -f "$WORK/f_#.png"
expect_one_error rt-render "frames are 0..3"
echo "render_orbit: ok"
