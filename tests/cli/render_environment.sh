# --environment FILE with the Whitted tracer: the image is what camera rays and mirror
# reflections that leave the scene see, as in glTF viewers (before: the option was ignored, and
# they saw the black background). Options the chosen integrator does not use are noted.
source "$(dirname "$0")/common.bash"
oiiotool --pattern constant:color=0.25,0.5,0.75 16x8 3 -d float -o "$WORK/sky.exr"
pixel() { oiiotool "$1" --cut "1x1+$2+$3" --printstats | awk '/Stats Avg:/ { print $3, $4, $5; exit }'; }
near() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b - 0.002 && a < b + 0.002) }'; }
expect_sky() {
    read -r r g b <<<"$(pixel "$1" "$2" "$3")"
    near "$r" 0.25 && near "$g" 0.5 && near "$b" 0.75 || fail "$4: pixel $2,$3 is $r $g $b, not the sky"
}

# A mirror ball in the middle of the picture, nothing else, no light.
cat >"$WORK/ball.xml" <<'XML'
<scene>
  <camera fov="60"><origin x="0" y="0" z="5" /><destination x="0" y="0" z="0" /></camera>
  <materials><material name="mirror" diffuse="0" ambient="0" reflection="1" /></materials>
  <objects><sphere x="0" y="0" z="0" r="1" material="mirror" /></objects>
</scene>
XML
opts=(-x 40 -y 30 -q --exr-pixels float --alpha off)
expect_exit 0 "$RT_RENDER" "$WORK/ball.xml" "${opts[@]}" --environment "$WORK/sky.exr" -f "$WORK/ball.exr"
expect_sky "$WORK/ball.exr" 1 1 "the background"
expect_sky "$WORK/ball.exr" 20 15 "the mirror's reflection"
expect_exit 0 "$RT_RENDER" "$WORK/ball.xml" "${opts[@]}" --environment "$WORK/sky.exr" --integrator path -f "$WORK/path.exr"
expect_sky "$WORK/path.exr" 1 1 "the path tracer's background"

# Given to the integrator that does not use them, options are noted, one line each.
expect_exit 0 "$RT_RENDER" "$WORK/ball.xml" -x 8 -y 6 --integrator path -d 3 -r 4 -o null
grep -q "^rt-render: note: --depth is not used by --integrator path" "$WORK/stderr" || fail "no note for -d: $(cat "$WORK/stderr")"
grep -q "^rt-render: note: --distributed-samples is not used" "$WORK/stderr" || fail "no note for -r: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_RENDER" "$WORK/ball.xml" -x 8 -y 6 --max-bounces 3 --clamp 2 -o null
grep -q "^rt-render: note: --max-bounces is not used by --integrator whitted" "$WORK/stderr" ||
    fail "no note for --max-bounces: $(cat "$WORK/stderr")"
grep -q "^rt-render: note: --clamp is not used" "$WORK/stderr" || fail "no note for --clamp: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_RENDER" "$WORK/ball.xml" -x 8 -y 6 --max-bounces 3 -s -o null
[ "$(grep -c note "$WORK/stderr")" = 1 ] || fail "a used option was noted: $(cat "$WORK/stderr")"
echo "render_environment: ok"
