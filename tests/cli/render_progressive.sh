# --time-limit: the path tracer writes the passes that finished (the bits of -S K, K in the EXR and
# the JSON); the Whitted tracer, cut short, writes nothing and exits 3. -p's estimate. --aov variance.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
path=(-q -x 32 -y 24 --integrator path --max-bounces 3 --exr-pixels float)
samples_of() { iinfo -v "$1" | sed -n 's/.*rt:samplesPerPixel: \([0-9]*\).*/\1/p'; }

# A limit far beyond the render changes no bit.
"$RT_RENDER" "$scene" "${path[@]}" -S 8 -f "$WORK/free.exr"
"$RT_RENDER" "$scene" "${path[@]}" -S 8 --time-limit 100000 -f "$WORK/limited.exr" --stats-json "$WORK/limited.json"
idiff -fail 0 -warn 0 "$WORK/free.exr" "$WORK/limited.exr" >/dev/null || fail "a generous --time-limit changed the picture"
[ "$(samples_of "$WORK/limited.exr")" = 8 ] || fail "rt:samplesPerPixel: $(iinfo -v "$WORK/limited.exr")"
grep -q '"samplesPerPixel": 8,' "$WORK/limited.json" && grep -q '"timeLimitReached": false' "$WORK/limited.json" ||
    fail "the JSON: $(grep -i 'samples\|limit' "$WORK/limited.json")"

# A limit reached: the K passes that finished, the same bits as -S K, on two threads as on one.
expect_exit 0 "$RT_RENDER" "$scene" "${path[@]}" -S 1000000 --time-limit 1 -f "$WORK/cut.exr" \
    --stats-json "$WORK/cut.json"
k=$(samples_of "$WORK/cut.exr")
[ -n "$k" ] && [ "$k" -ge 1 ] && [ "$k" -lt 1000000 ] || fail "rt:samplesPerPixel '$k' after the time limit"
grep -q "reached: $k of 1000000 samples per pixel taken and written" "$WORK/stderr" || fail "$(cat "$WORK/stderr")"
grep -q "\"samplesPerPixel\": $k," "$WORK/cut.json" && grep -q '"timeLimitReached": true' "$WORK/cut.json" ||
    fail "the JSON: $(grep -i 'samples\|limit' "$WORK/cut.json")"
"$RT_RENDER" "$scene" "${path[@]}" -S "$k" --threads 1 -f "$WORK/k.exr"
idiff -fail 0 -warn 0 "$WORK/k.exr" "$WORK/cut.exr" >"$WORK/idiff.txt" ||
    fail "the time-limited picture is not the -S $k one: $(cat "$WORK/idiff.txt")"

# A heavy Whitted render (20000 lights, shadows: tens of seconds) stops at once with exit 3, no file.
python3 - "$scene" "$WORK/heavy.xml" <<'PY'
import sys
text = open(sys.argv[1]).read()
lights = "".join(f'<light x="{i % 100 * 0.1 - 5}" y="8" z="{i // 100 * 0.05 - 5}" r="0.0001" g="0.0001" b="0.0001"/>'
                 for i in range(20000))
open(sys.argv[2], "w").write(text.replace("<lights>", "<lights>" + lights))
PY
start=$(date +%s.%N)
expect_exit 3 "$RT_RENDER" "$WORK/heavy.xml" -q -s -x 32 -y 24 --time-limit 0.3 -f "$WORK/heavy.png" \
    --stats-json "$WORK/heavy.json"
elapsed=$(echo "$(date +%s.%N) - $start" | bc)
expect_one_error rt-render "--time-limit 0.3 s ran out before the picture was finished: nothing written"
[ ! -e "$WORK/heavy.png" ] && [ ! -e "$WORK/heavy.json" ] || fail "a cut Whitted render left a file"
[ -z "$(ls -A "$WORK" | grep rt-tmp || true)" ] || fail "temporaries left: $(ls -A "$WORK")"
awk -v e="$elapsed" 'BEGIN { exit !(e < 30) }' || fail "the time-limited render took $elapsed s"
# The path tracer with not one pass finished: the same.
expect_exit 3 "$RT_RENDER" "$WORK/heavy.xml" -q --integrator path -x 32 -y 24 --time-limit 1e-9 -f "$WORK/heavy.exr"
expect_one_error rt-render "before the first pass (one sample of every pixel) was finished: nothing written"
expect_exit 2 "$RT_RENDER" "$scene" -q -o null --time-limit -1
expect_exit 2 "$RT_RENDER" "$scene" -q -o null --time-limit nan

# -p: the estimate on standard error (not with -q), and in the JSON.
expect_exit 0 "$RT_RENDER" "$WORK/heavy.xml" -p -s -x 32 -y 24 --threads 2 --stats-json "$WORK/p.json"
grep -q "^rt-render: estimate: 32x24 pixels x 1 sample: .* rays, .* intersection tests, about .* s on 2 threads (probe: [0-9]* pixels traced in" \
    "$WORK/stderr" || fail "no estimate: $(cat "$WORK/stderr")"
python3 - "$WORK/p.json" <<'PY' || fail "the estimate in the JSON: $(grep -A9 estimate "$WORK/p.json")"
import json, sys
e = json.load(open(sys.argv[1]))["estimate"]
# every probed pixel sees the floor or a sphere lit by 20000 lights: about that many rays a pixel
assert e["cameraSamples"] == 32 * 24 and e["threads"] == 2 and e["probePixels"] >= 1, e
assert 1000 * 768 < e["rays"] < 200000 * 768, e
assert e["seconds"] > 0, e
PY
expect_exit 0 "$RT_RENDER" "$scene" -p -q
[ ! -s "$WORK/stderr" ] || fail "-p -q printed: $(cat "$WORK/stderr")"

# --aov variance with the path tracer: three float channels, lower with more samples.
"$RT_RENDER" "$scene" "${path[@]}" -S 4 --aov variance -f "$WORK/v4.exr"
"$RT_RENDER" "$scene" "${path[@]}" -S 16 --aov variance -f "$WORK/v16.exr"
channels=$(iinfo -v "$WORK/v4.exr" | grep "channel list")
[[ $channels == *"variance.R, variance.G, variance.B"* ]] || fail "no variance layer: $channels"
mean_variance() { oiiotool "$1" --ch variance.G --printstats | awk '$1 == "Stats" && $2 == "Avg:" {print $3}'; }
v4=$(mean_variance "$WORK/v4.exr") v16=$(mean_variance "$WORK/v16.exr")
echo "mean variance.G: -S 4 $v4, -S 16 $v16"
awk -v a="$v4" -v b="$v16" 'BEGIN { exit !(b > 0 && a / b > 2 && a / b < 8) }' || fail "variance -S 4: $v4, -S 16: $v16"
echo "render_progressive: ok"
