# A sample that comes out NaN or infinite is written as black, counted in --stats-json and
# reported once on standard error with the first pixel it hit (even with -q), never written
# silently: a light of 1e15 on a material of colour 1e15 and diffuse 1e15 (each within the
# loader's bound, render_radiance_limits.sh) overflows float in their product.
source "$(dirname "$0")/common.bash"
cat >"$WORK/overflow.xml" <<'XML'
<scene>
  <camera fov="50"><origin x="0" y="0" z="-5" /><destination x="0" y="0" z="0" /></camera>
  <materials><material name="white" r="1e15" g="1e15" b="1e15" ambient="0.1" diffuse="1e15" /></materials>
  <objects><sphere x="0" y="0" z="0" r="1" material="white" /></objects>
  <lights>
    <light x="0" y="5" z="-5" r="1e15" g="1e15" b="1e15" />
  </lights>
</scene>
XML
expect_exit 0 "$RT_RENDER" "$WORK/overflow.xml" -x 32 -y 24 -q -f "$WORK/o.exr" --exr-pixels float \
    --stats-json "$WORK/stats.json"
[ "$(grep -c 'non-finite' "$WORK/stderr")" = 1 ] || fail "expected one warning line, got: $(cat "$WORK/stderr")"
grep -q "^rt-render: warning: [0-9]* non-finite .*first at pixel ([0-9]*, [0-9]*)" "$WORK/stderr" ||
    fail "the warning names no count or pixel: $(cat "$WORK/stderr")"
count=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["nonFiniteSamples"])' "$WORK/stats.json")
[ "$count" -gt 0 ] || fail "--stats-json counts $count non-finite samples"
iinfo --stats "$WORK/o.exr" >"$WORK/iinfo.txt"
grep -q "NanCount: 0 0 0" "$WORK/iinfo.txt" && grep -q "InfCount: 0 0 0" "$WORK/iinfo.txt" ||
    fail "non-finite pixels written: $(grep -E 'NanCount|InfCount' "$WORK/iinfo.txt")"

# A finite scene says nothing of the kind.
expect_exit 0 "$RT_RENDER" "$RT_SOURCE_DIR/scenes/demo.xml" -x 32 -y 24 -q -o null
! grep -q "non-finite" "$WORK/stderr" || fail "a finite render warned: $(cat "$WORK/stderr")"
echo "render_nonfinite: ok"
