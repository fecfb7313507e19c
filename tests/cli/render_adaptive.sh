# --adaptive (thesis 2.3): fewer camera rays, the statistics say how many were saved, tiles
# still merge exactly and the thread count changes no bit; bad grids are usage errors.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
# 70x40 and the split at 33,17 are off the grid and the block grid on purpose.
opts=(-K -q -s -d 3 -x 70 -y 40 -S 2 -D s -r 3 --exr-pixels float --adaptive=4)
"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/full.exr" --stats-json "$WORK/stats.json"
python3 - "$WORK/stats.json" <<'PY' || fail "--stats-json does not show the camera rays saved: $(cat "$WORK/stats.json")"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["picture"]["adaptiveGrid"] == 4, s["picture"]
assert s["fullRenderCameraRays"] == 70 * 40 * 2
assert 0 < s["rays"]["cameraRays"] < s["fullRenderCameraRays"], s["rays"]
assert s["interpolatedPixels"] > 0
PY
n=0
for region in 0,0,33,17 33,0,70,17 0,17,33,40 33,17,70,40; do
    "$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/t$n.exr" --region $region
    n=$((n + 1))
done
oiiotool "$WORK/t0.exr" "$WORK/t1.exr" --add "$WORK/t2.exr" --add "$WORK/t3.exr" --add -o "$WORK/merged.exr"
idiff -fail 0 -warn 0 "$WORK/full.exr" "$WORK/merged.exr" >"$WORK/idiff.txt" || fail "merged tiles differ: $(cat "$WORK/idiff.txt")"
"$RT_RENDER" "$scene" "${opts[@]}" --threads 1 -f "$WORK/one.exr"
"$RT_RENDER" "$scene" "${opts[@]}" --threads 2 -f "$WORK/two.exr"
idiff -fail 0 -warn 0 "$WORK/one.exr" "$WORK/two.exr" >/dev/null || fail "1 and 2 threads differ"
# ... and the comparison can fail: the adaptive picture is not the full one.
"$RT_RENDER" "$scene" -K -q -s -d 3 -x 70 -y 40 -S 2 -D s -r 3 --exr-pixels float -f "$WORK/traced.exr"
if idiff -fail 0 -warn 0 "$WORK/traced.exr" "$WORK/full.exr" >/dev/null; then fail "--adaptive=4 changed nothing"; fi

# The summary on standard error says what was saved; --adaptive alone means a grid of 8.
"$RT_RENDER" "$scene" -x 64 -y 48 --adaptive 2>"$WORK/summary.txt"
grep -q "^adaptive 8: .* pixels interpolated, .* % of a full render's 3072 camera rays saved" "$WORK/summary.txt" ||
    fail "no adaptive summary: $(cat "$WORK/summary.txt")"

expect_exit 2 "$RT_RENDER" "$scene" --adaptive=6
expect_one_error rt-render "adaptive"
expect_exit 2 "$RT_RENDER" "$scene" --adaptive --adaptive-threshold -1
expect_one_error rt-render "adaptive-threshold"
expect_exit 2 "$RT_RENDER" "$scene" --adaptive --aov Z -f "$WORK/aov.exr"
expect_one_error rt-render "AOVs"
echo "render_adaptive: ok"
