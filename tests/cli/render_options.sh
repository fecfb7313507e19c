# rt-render's command line: thesis options with long names, output types, statistics, exit codes.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
small=(-K -q -x 32 -y 24)

# -b: "preprocessing render objects lights nodes tests-per-ray" (thesis appendix B).
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -s -d 3 -b
grep -Eq '^[0-9]+\.[0-9]{2} [0-9]+\.[0-9]{2} [1-9][0-9]* [1-9][0-9]* [1-9][0-9]* [0-9]+\.[0-9]{2}$' "$WORK/stdout" ||
    fail "-b printed: $(cat "$WORK/stdout")"
[ ! -s "$WORK/stderr" ] || fail "-q still wrote to stderr: $(cat "$WORK/stderr")"
# The same with long names; the summary goes to stderr, nothing but the line to stdout.
expect_exit 0 "$RT_RENDER" "$scene" --width 32 --height 24 --shadows --depth 3 --batch-stats --output null
[ "$(wc -l <"$WORK/stdout")" = 1 ] || fail "stdout has more than the -b line"
grep -q "camera, .* shadow, .* reflection rays" "$WORK/stderr" || fail "no summary on stderr"

# --seed: another seed, other noise, the same again each time; the statistics record it.
"$RT_RENDER" "$scene" "${small[@]}" -S 4 -D b -r 2 -f "$WORK/seed0.exr"
"$RT_RENDER" "$scene" "${small[@]}" -S 4 -D b -r 2 --seed 7 -f "$WORK/seed7.exr" --stats-json "$WORK/seed.json"
"$RT_RENDER" "$scene" "${small[@]}" -S 4 -D b -r 2 --seed 7 -f "$WORK/again7.exr"
if idiff -fail 0 -warn 0 "$WORK/seed0.exr" "$WORK/seed7.exr" >/dev/null; then fail "--seed 7 changed nothing"; fi
idiff -fail 0 -warn 0 "$WORK/seed7.exr" "$WORK/again7.exr" >/dev/null || fail "--seed 7 is not reproducible"
grep -q '"seed": 7' "$WORK/seed.json" || fail "the statistics do not record the seed"
# --stats-json is JSON with the counters; its camera rays are width x height x samples.
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -S 4 --stats-json -
python3 -c 'import json,sys; d=json.load(sys.stdin); r=d["rays"]; assert r["cameraRays"]==32*24*4, d; assert r["intersectionTestsPerRay"]>0' \
    <"$WORK/stdout" || fail "bad --stats-json: $(cat "$WORK/stdout")"

# -D s implies shadows; -D d alone does not.
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -D s -r 2 --stats-json -
python3 -c 'import json,sys; d=json.load(sys.stdin); assert d["picture"]["shadows"] and d["rays"]["shadowRays"]>0, d' <"$WORK/stdout" ||
    fail "-D s without shadows: $(cat "$WORK/stdout")"
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -D d -r 2 --stats-json -
python3 -c 'import json,sys; d=json.load(sys.stdin); assert d["rays"]["shadowRays"]==0, d' <"$WORK/stdout" ||
    fail "-D d cast shadow rays: $(cat "$WORK/stdout")"

# -p builds the tree only: no render time, no output file.
expect_exit 0 "$RT_RENDER" "$scene" -q -p -b -f "$WORK/nothing.png"
grep -Eq '^[0-9.]+ 0\.00 ' "$WORK/stdout" || fail "-p rendered: $(cat "$WORK/stdout")"
[ ! -e "$WORK/nothing.png" ] || fail "-p wrote a file"

# Output types: by -o, or by -f's extension; text goes to stdout by default; the scene may come from stdin.
for f in a.png b.exr c.tga d.txt; do expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -f "$WORK/$f"; done
iinfo "$WORK/a.png" | grep -q "32 x   24, 4 channel, uint8 png" || fail "a.png: $(iinfo "$WORK/a.png")"
iinfo "$WORK/b.exr" | grep -q "half openexr" || fail "b.exr: $(iinfo "$WORK/b.exr")"
iinfo -v "$WORK/b.exr" >"$WORK/b.txt"
for key in 'Software: "rt-render [0-9]' "rt:scene: \"$scene\"" 'rt:samplesPerPixel: 1' 'rt:colorSpace: "lin_rec709"' \
    'rt:renderSeconds: [0-9]'; do
    grep -q "$key" "$WORK/b.txt" || fail "b.exr metadata lacks $key: $(cat "$WORK/b.txt")"
done
iinfo "$WORK/c.tga" | grep -q "tga" || fail "c.tga: $(iinfo "$WORK/c.tga")"
[ "$(wc -l <"$WORK/d.txt")" = 24 ] || fail "d.txt is not 24 lines"
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -o png --png-bits 16 -f "$WORK/e.png"
iinfo "$WORK/e.png" | grep -q "uint16 png" || fail "e.png is not 16-bit"
expect_exit 0 "$RT_RENDER" - "${small[@]}" -o text <"$scene"
[ "$(wc -l <"$WORK/stdout")" = 24 ] || fail "text to stdout from a scene on stdin: $(cat "$WORK/stdout")"
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -o png -f - 
cmp -s "$WORK/stdout" "$WORK/a.png" || fail "PNG on stdout differs from the file"

# Bad usage and bad input: exit 2 with one line on stderr.
expect_exit 2 "$RT_RENDER"
expect_exit 2 "$RT_RENDER" "$scene" -d 11
expect_exit 2 "$RT_RENDER" "$scene" -o jpeg
expect_exit 2 "$RT_RENDER" "$scene" -D x
expect_exit 2 "$RT_RENDER" "$scene" -B -K
expect_exit 2 "$RT_RENDER" "$scene" -K --accel naive
expect_exit 2 "$RT_RENDER" "$scene" -x 0
expect_exit 2 "$RT_RENDER" "$scene" -o png
grep -q "needs -f" "$WORK/stderr" || fail "-o png without -f: $(cat "$WORK/stderr")"
expect_exit 2 "$RT_RENDER" "$scene" -f "$WORK/out.xyz"
expect_exit 2 "$RT_RENDER" "$scene" --region 1,2,3
grep -q "x0,y0,x1,y1" "$WORK/stderr" || fail "bad region message: $(cat "$WORK/stderr")"
expect_exit 2 "$RT_RENDER" "$scene" "${small[@]}" --region 0,0,33,10
grep -q "outside" "$WORK/stderr" || fail "region outside the image: $(cat "$WORK/stderr")"
expect_exit 2 "$RT_RENDER" "$scene" "${small[@]}" --display Cinema -f "$WORK/x.png"
expect_exit 2 "$RT_RENDER" "$WORK/no-such-scene.xml"
[ "$(wc -l <"$WORK/stderr")" = 1 ] || fail "more than one line for a missing scene: $(cat "$WORK/stderr")"
grep -q "^rt-render ERROR: .*no-such-scene.xml" "$WORK/stderr" || fail "missing scene: $(cat "$WORK/stderr")"
# A scene that does not load: exit 2, file and line.
printf '<?xml version="1.0"?>\n<scene>\n  <sphere x="0"/>\n</scene>\n' >"$WORK/bad.xml"
expect_exit 2 "$RT_RENDER" "$WORK/bad.xml"
grep -q "bad.xml:3:" "$WORK/stderr" || fail "no file:line for a bad scene: $(cat "$WORK/stderr")"

# The three accelerators find the same hits, so the pictures are the same bits.
for accel in naive bsp kd; do
    expect_exit 0 "$RT_RENDER" "$scene" -q -s -d 3 -x 48 -y 36 --accel "$accel" --exr-pixels float -f "$WORK/$accel.exr" -b
done
idiff -fail 0 -warn 0 "$WORK/naive.exr" "$WORK/bsp.exr" >/dev/null || fail "BSP and naive renders differ"
idiff -fail 0 -warn 0 "$WORK/naive.exr" "$WORK/kd.exr" >/dev/null || fail "KD and naive renders differ"

# Without -B, -K or --accel the KD tree is used: the -b line's node count (field 5) exceeds
# the naive list's single node.
expect_exit 0 "$RT_RENDER" "$scene" -x 16 -y 12 -o null -b
[ "$(awk '{print $5}' "$WORK/stdout")" -gt 1 ] || fail "the default is not a tree: $(cat "$WORK/stdout")"
expect_exit 0 "$RT_RENDER" "$scene" -x 16 -y 12 -o null -b --accel naive
[ "$(awk '{print $5}' "$WORK/stdout")" = 1 ] || fail "--accel naive has nodes: $(cat "$WORK/stdout")"
echo "render_options: ok"
