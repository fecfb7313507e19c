# No infinite pixel reaches a file without a word (docs/robustness.md, Limits): colours and
# intensities beyond 1e15 are refused where they are read (a light of 3.4e38 made every pixel of
# the Whitted tracer infinite); a pixel's samples are each held to 1e15 before they are summed
# (two finite samples of 2e38 summed to +inf, with no non-finite sample counted); and a half-float
# EXR holds at most 65504, so larger values are written as 65504 with a warning (a light of 1e5
# made 54 infinite pixels, silently).
source "$(dirname "$0")/common.bash"

# scene FILE LIGHT-RGB MATERIAL-ATTRIBUTES: a sphere lit by one light in front of it.
scene() {
    cat >"$1" <<XML
<scene>
  <camera fov="40"><origin x="0" y="0" z="-5" /><destination x="0" y="0" z="0" /></camera>
  <materials><material name="m" $3 /></materials>
  <objects><sphere x="0" y="0" z="0" r="1" material="m" /></objects>
  <lights><light x="0" y="0" z="-5" $2 /></lights>
</scene>
XML
}

# Refused where read, with the line.
scene "$WORK/light.xml" 'r="3.4e38" g="3.4e38" b="3.4e38"' ''
expect_exit 2 "$RT_RENDER" "$WORK/light.xml" -x 16 -y 12 -q -o null
expect_one_error rt-render "light.xml:5: .*attribute 'r' is too large (at most 1e15)"
scene "$WORK/emitter.xml" '' 'emission="3.4e38 0 0"'
expect_exit 2 "$RT_RENDER" "$WORK/emitter.xml" -x 16 -y 12 -q -o null
expect_one_error rt-render "emitter.xml:3: emission is too large (at most 1e15)"

# Finite samples of about 2e38 (1e15 x 1e15 x 2e8: each factor within range): the pixel's sum
# stays finite, and nothing is called non-finite.
scene "$WORK/bright.xml" 'r="1e15" g="1e15" b="1e15"' 'r="1e15" g="1e15" b="1e15" diffuse="2e8" ambient="0"'
expect_exit 0 "$RT_RENDER" "$WORK/bright.xml" -x 16 -y 12 -S 4 -q -f "$WORK/bright.exr" --exr-pixels float
iinfo --stats "$WORK/bright.exr" >"$WORK/iinfo.txt"
grep -q "InfCount: 0 0 0" "$WORK/iinfo.txt" && grep -q "NanCount: 0 0 0" "$WORK/iinfo.txt" ||
    fail "a sum of finite samples was written non-finite: $(grep -E 'NanCount|InfCount' "$WORK/iinfo.txt")"
grep -q "Max: 999999986991104\.0* 999999986991104\.0* 999999986991104" "$WORK/iinfo.txt" ||  # float's 1e15
    fail "the brightest pixel is not held at 1e15: $(grep 'Max:' "$WORK/iinfo.txt")"

# A light of 1e5 into the default half-float EXR: written as 65504, said once, even with -q.
scene "$WORK/half.xml" 'r="1e5" g="1e5" b="1e5"' ''
expect_exit 0 "$RT_RENDER" "$WORK/half.xml" -x 16 -y 12 -q -f "$WORK/half.exr"
[ "$(wc -l <"$WORK/stderr")" = 1 ] &&
    grep -q "^rt-render: warning: .*half.exr: [0-9]* values above half float's 65504 written as 65504" "$WORK/stderr" ||
    fail "no one-line warning of the clipped half values: $(cat "$WORK/stderr")"
iinfo --stats "$WORK/half.exr" >"$WORK/iinfo.txt"
grep -q "InfCount: 0 0 0" "$WORK/iinfo.txt" || fail "the half EXR holds +inf: $(grep InfCount "$WORK/iinfo.txt")"
# Float keeps them, and says nothing.
expect_exit 0 "$RT_RENDER" "$WORK/half.xml" -x 16 -y 12 -q -f "$WORK/float.exr" --exr-pixels float
[ ! -s "$WORK/stderr" ] || fail "a float EXR warned: $(cat "$WORK/stderr")"
echo "render_radiance_limits: ok"
