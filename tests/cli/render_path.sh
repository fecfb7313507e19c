# rt-render --integrator path: renders, tiles exactly, refuses what it does not do yet.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
opts=(-q -x 48 -y 36 --integrator path -S 4 --max-bounces 4 --exr-pixels float)

"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/whole.exr"
stats=$(oiiotool "$WORK/whole.exr" --printstats)
grep -q "NanCount: 0 0 0" <<<"$stats" || fail "non-finite pixels: $stats"
# not black: the demo's lights reach the surfaces through next-event estimation
max=$(echo "$stats" | awk '/Max:/ {print $2; exit}')
awk -v m="$max" 'BEGIN {exit !(m > 0.05)}' || fail "the path-traced demo is black (max red $max)"

# two tiles give the same bits as the whole picture, on one thread and two
"$RT_RENDER" "$scene" "${opts[@]}" --threads 1 --tiles 2x1 --tile 0/2 -f "$WORK/left.exr"
"$RT_RENDER" "$scene" "${opts[@]}" --threads 2 --tiles 2x1 --tile 1/2 -f "$WORK/right.exr"
oiiotool "$WORK/left.exr" "$WORK/right.exr" --over -o "$WORK/merged.exr"
idiff -fail 0 -warn 0 "$WORK/merged.exr" "$WORK/whole.exr" >"$WORK/idiff.txt" ||
    fail "tiles differ from the whole picture: $(cat "$WORK/idiff.txt")"

# the Whitted tracer is untouched by the path tracer's options
"$RT_RENDER" "$scene" -q -x 48 -y 36 --exr-pixels float -f "$WORK/whitted.exr"
"$RT_RENDER" "$scene" -q -x 48 -y 36 --exr-pixels float --max-bounces 3 --clamp 2 -f "$WORK/whitted2.exr"
idiff -fail 0 -warn 0 "$WORK/whitted.exr" "$WORK/whitted2.exr" >/dev/null || fail "--max-bounces changed a Whitted render"

# --environment: an image of one colour lights the scene; the camera's misses show it
oiiotool --pattern constant:color=0.25,0.5,1 16x8 3 -d float -o "$WORK/sky.exr"
"$RT_RENDER" "$scene" "${opts[@]}" --environment "$WORK/sky.exr" --alpha off -f "$WORK/sky-lit.exr"
corner=$(oiiotool "$WORK/sky-lit.exr" --cut 1x1+0+0 --printstats | awk '/Avg:/ {print $3, $4, $5; exit}')
[[ "$corner" == "0.250000 0.500000 1.000000" ]] || fail "the sky's corner is $corner"
expect_exit 2 "$RT_RENDER" "$scene" -q -o null --integrator path --environment "$WORK/none.exr"

# <environment> in the scene (rt extension): the image relative to the scene, times its intensity;
# --environment takes its place
mkdir -p "$WORK/skyscene/skies"
cp "$WORK/sky.exr" "$WORK/skyscene/skies/blue.exr"
oiiotool --pattern constant:color=1,0,0 16x8 3 -d float -o "$WORK/red.exr"
sed 's|<scene>|<scene><environment texture="sky" intensity="2"/><textures><texture name="sky" file="skies/blue.exr"/></textures>|' \
    "$scene" >"$WORK/skyscene/scene.xml"
corner_of() { oiiotool "$1" --cut 1x1+0+0 --printstats | awk '/Avg:/ {print $3, $4, $5; exit}'; }
"$RT_RENDER" "$WORK/skyscene/scene.xml" "${opts[@]}" --alpha off -f "$WORK/named.exr"
[[ "$(corner_of "$WORK/named.exr")" == "0.500000 1.000000 2.000000" ]] || fail "the named sky's corner: $(corner_of "$WORK/named.exr")"
"$RT_RENDER" "$WORK/skyscene/scene.xml" "${opts[@]}" --alpha off --environment "$WORK/red.exr" -f "$WORK/over.exr"
[[ "$(corner_of "$WORK/over.exr")" == "1.000000 0.000000 0.000000" ]] || fail "--environment did not replace it"

expect_exit 2 "$RT_RENDER" "$scene" -q -o null --integrator bidirectional
expect_exit 2 "$RT_RENDER" "$scene" -q -o null --integrator path --max-bounces -1
expect_exit 2 "$RT_RENDER" "$scene" -q -o null --integrator path --clamp nan

# --light-sampler: the demo's thesis lights (no falloff) light every point alike and stay out of
# the light tree, so power and tree choose them alike
"$RT_RENDER" "$scene" "${opts[@]}" --light-sampler power -f "$WORK/power.exr"
idiff -fail 0 -warn 0 "$WORK/power.exr" "$WORK/whole.exr" >/dev/null || fail "--light-sampler power changed the demo"
expect_exit 2 "$RT_RENDER" "$scene" -q -o null --integrator path --light-sampler uniform

# every AOV with the path tracer
"$RT_RENDER" "$scene" "${opts[@]}" --aov all -f "$WORK/aov.exr"
channels=$(iinfo -v "$WORK/aov.exr" | grep "channel list")
for c in Z N.X Ng.X P.X albedo.R id.material cost.allTests variance.R; do
    [[ $channels == *"$c"* ]] || fail "no $c in $channels"
done
echo "render_path: ok"
