# Several -f in one run: one render, each file written from it in its own format, the same
# pictures as separate runs give.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
opts=(-K -s -x 40 -y 30 -S 4 --progress lines)

expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/a.png" -f "$WORK/b.exr" --aov Z -f "$WORK/c.jpg"
[ "$(grep -c "^rendered" "$WORK/stderr")" = 1 ] || fail "not one render: $(cat "$WORK/stderr")"
for f in a.png b.exr c.jpg; do grep -q "wrote $WORK/$f" "$WORK/stderr" || fail "no $f: $(cat "$WORK/stderr")"; done
iinfo "$WORK/b.exr" | grep -q "5 channel" || fail "the EXR lacks its Z layer: $(iinfo "$WORK/b.exr")"
"$RT_RENDER" "$scene" "${opts[@]}" -q -f "$WORK/alone.png"
idiff -fail 0 -warn 0 "$WORK/a.png" "$WORK/alone.png" >/dev/null || fail "the PNG differs from a render of its own"
"$RT_RENDER" "$scene" "${opts[@]}" -q -f "$WORK/alone.exr"
oiiotool "$WORK/b.exr" --ch R,G,B,A -o "$WORK/rgba.exr"
idiff -fail 0 -warn 0 "$WORK/rgba.exr" "$WORK/alone.exr" >/dev/null || fail "the EXR differs from a render of its own"

expect_exit 2 "$RT_RENDER" "$scene" -q -o png -f - -f -
expect_one_error rt-render "would both write to standard output"
expect_exit 2 "$RT_RENDER" "$scene" -q --aov Z -f "$WORK/x.png" -f "$WORK/y.jpg"
expect_one_error rt-render "--aov needs an EXR output"
echo "render_several_outputs: ok"
