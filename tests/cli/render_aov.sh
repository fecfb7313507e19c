# --aov: AOV layers after the colour in one EXR, named layer.channel for oiiotool --ch; ids as
# uint32; the cost layer's mean is the statistics' work per camera ray.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
opts=(-K -q -s -d 2 -x 48 -y 36)

expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" --aov all -f "$WORK/all.exr" --stats-json "$WORK/s.json"
iinfo -v "$WORK/all.exr" >"$WORK/info.txt"
# OpenEXR keeps the channels sorted by name; each is there with its type.
for channel in "R (half)" "A (half)" "Z (float)" "N.X (float)" "N.Z (float)" "Ng.Y (float)" "P.X (float)" \
    "albedo.B (float)" "id.material (uint)" "id.primitive (uint)" "cost.steps (float)" "cost.tests (float)" \
    "cost.allSteps (float)" "cost.allTests (float)"; do
    grep "channel list" "$WORK/info.txt" | grep -qF "$channel" || fail "no $channel: $(grep 'channel list' "$WORK/info.txt")"
done
oiiotool "$WORK/all.exr" --ch N.X,N.Y,N.Z -o "$WORK/n.exr" || fail "oiiotool cannot take the N layer"
iinfo "$WORK/n.exr" | grep -q "3 channel" || fail "the N layer: $(iinfo "$WORK/n.exr")"

# The mean of cost.tests over the picture is the intersection tests per camera ray.
mean=$(oiiotool "$WORK/all.exr" --ch cost.tests --printstats | awk '$1 == "Stats" && $2 == "Avg:" {print $3}')
rays=$(grep -o '"cameraRays": [0-9]*' "$WORK/s.json" | grep -o '[0-9]*$')
awk -v m="$mean" -v r="$rays" 'BEGIN { exit !(m > 0 && r == 48 * 36) }' || fail "cost.tests mean $mean over $rays camera rays"

# A subset in the order of the table; the colour is the same as without AOVs.
expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" --aov cost,Z -f "$WORK/two.exr"
iinfo "$WORK/two.exr" | grep -q "9 channel" || fail "--aov cost,Z: $(iinfo -v "$WORK/two.exr")"
"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/plain.exr"
oiiotool "$WORK/two.exr" --ch R,G,B,A -o "$WORK/rgba.exr"
idiff -fail 0 -warn 0 "$WORK/plain.exr" "$WORK/rgba.exr" >/dev/null || fail "AOVs changed the colour"

expect_exit 2 "$RT_RENDER" "$scene" -q --aov Z -f "$WORK/a.png"
expect_one_error rt-render "--aov needs an EXR output"
expect_exit 2 "$RT_RENDER" "$scene" -q --aov depth -f "$WORK/a.exr"
expect_one_error rt-render "unknown AOV 'depth'"
echo "render_aov: ok"
