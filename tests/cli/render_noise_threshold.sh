# rt-render --noise-threshold: the path tracer stops sampling converged pixels; the samples AOV
# shows where, --stats-json counts what was saved; tiles and threads keep the bits; the Whitted
# tracer and a minimum below two are refused with one error line.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
opts=(-q -x 48 -y 36 --integrator path -S 64 --noise-threshold 0.05 --adaptive-min-samples 8 --exr-pixels float)

"$RT_RENDER" "$scene" "${opts[@]}" --threads 2 --aov samples --stats-json "$WORK/stats.json" -f "$WORK/whole.exr"
# the samples layer: from the minimum to -S, and not the same everywhere
read -r least most < <(oiiotool "$WORK/whole.exr" --ch samples.count --printstats |
    awk '/Min:/ {least = $3} /Max:/ {most = $3} END {print least, most}')
echo "samples a pixel: $least to $most"
awk -v a="$least" -v b="$most" 'BEGIN { exit !(a >= 8 && a < b && b <= 64) }' || fail "samples from $least to $most"
python3 - "$WORK/stats.json" <<'PY' || fail "stats: $(cat "$WORK/stats.json")"
import json, sys
s = json.load(open(sys.argv[1]))
taken, uniform = s["samplesTaken"], s["fullRenderCameraRays"]
print(f"samples taken {taken} of {uniform}")
assert abs(s["picture"]["noiseThreshold"] - 0.05) < 1e-6 and s["picture"]["adaptiveMinSamples"] == 8
assert 0 < taken < uniform == 48 * 36 * 64
assert s["samplesPerPixel"] <= 64
PY

# one thread and two tiles give the same bits as two threads and the whole picture
"$RT_RENDER" "$scene" "${opts[@]}" --threads 1 --tiles 2x1 --tile 0/2 -f "$WORK/left.exr"
"$RT_RENDER" "$scene" "${opts[@]}" --threads 2 --tiles 2x1 --tile 1/2 -f "$WORK/right.exr"
oiiotool "$WORK/left.exr" "$WORK/right.exr" --over -o "$WORK/merged.exr"
oiiotool "$WORK/whole.exr" --ch R,G,B,A -o "$WORK/whole-rgba.exr"
idiff -fail 0 -warn 0 "$WORK/merged.exr" "$WORK/whole-rgba.exr" >"$WORK/idiff.txt" ||
    fail "tiles differ from the whole picture: $(cat "$WORK/idiff.txt")"

# the summary says what was saved
"$RT_RENDER" "$scene" "${opts[@]/-q/--progress=none}" -o null 2>"$WORK/summary.txt"
grep -q "noise threshold 0.05 (at least 8 samples): .* samples taken, .* % saved" "$WORK/summary.txt" ||
    fail "no summary line: $(cat "$WORK/summary.txt")"

expect_exit 2 "$RT_RENDER" "$scene" -q -o null --noise-threshold 0.05
expect_one_error rt-render "--noise-threshold needs the path integrator"
expect_exit 2 "$RT_RENDER" "$scene" -q -o null --integrator path --noise-threshold 0.05 --adaptive-min-samples 1
expect_one_error rt-render "--adaptive-min-samples must be 0"
expect_exit 2 "$RT_RENDER" "$scene" -q -o null --integrator path --noise-threshold -1
echo "render_noise_threshold: ok"
