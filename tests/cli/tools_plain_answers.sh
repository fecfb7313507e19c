# Small answers that were wrong or missing: too many threads for the address-space limit are rt's
# error line (libgomp's "Thread creation failed" before); geometry beyond 1e15 from the origin is
# an error (a sphere at 1e300 vanished silently); a size too large for one render names rt-render's
# --region (rt-inspect has none); a message of several lines is one line; a tree dump of more than
# 10 MB says so.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"

# 1023 stacks of 8 MiB do not fit in 2 GB of address space; 2 threads do. AddressSanitizer reserves
# terabytes of shadow memory at start, so under it no address-space limit can be set.
built_with "$RT_RENDER" asan || (
    ulimit -s 8192 -v 2000000
    expect_exit 2 "$RT_RENDER" "$scene" -x 16 -y 12 -q -o null --threads 1024
    expect_one_error rt-render "--threads: 1024 threads need .* of address space for their stacks; the limit (ulimit -v) leaves"
    expect_exit 0 "$RT_RENDER" "$scene" -x 16 -y 12 -q -o null --threads 2
)

cat >"$WORK/far.xml" <<'XML'
<scene>
  <camera fov="50"><origin x="0" y="0" z="-5" /><destination x="0" y="0" z="0" /></camera>
  <objects>
    <sphere x="0" y="0" z="0" r="1" />
    <sphere x="1e300" y="0" z="0" r="1" />
  </objects>
</scene>
XML
expect_exit 2 "$RT_RENDER" "$WORK/far.xml" -x 16 -y 12 -q -o null
expect_one_error rt-render "far.xml:5: <sphere> reaches beyond 1e15 from the origin"

expect_exit 2 "$RT_INSPECT" "$scene" -x 65536 -y 65536
expect_one_error rt-inspect "render it in regions (rt-render --region)"

# A PNG texture that is not one, and one cut short: OpenImageIO's message of several lines ("Read
# error ...", "Invalid image file ...") is one warning line, and libpng's own line ("libpng error:
# ...", which libpng prints itself while OpenImageIO reads) is folded into it (os/stderr_capture.h).
cat >"$WORK/tex.xml" <<'XML'
<scene>
  <camera fov="50"><origin x="0" y="0" z="-5" /><destination x="0" y="0" z="0" /></camera>
  <textures><texture name="t" file="bad.png" /></textures>
  <materials><material name="m" texture="t" /></materials>
  <objects><sphere x="0" y="0" z="0" r="1" material="m" /></objects>
</scene>
XML
printf '\x89PNG\r\n\x1a\ngarbagegarbagegarbage' >"$WORK/bad.png"
expect_exit 0 "$RT_RENDER" "$WORK/tex.xml" -x 16 -y 12 -o null
grep -q "^rt-render: warning: texture file .*bad.png: cannot read it (.*; PNG read error: .*): white is used$" \
    "$WORK/stderr" || fail "the texture's warning is not one line: $(cat "$WORK/stderr")"
grep -q '^PNG read error' "$WORK/stderr" && fail "a message of several lines: $(cat "$WORK/stderr")"
grep -q '^libpng' "$WORK/stderr" && fail "libpng's own line: $(cat "$WORK/stderr")"
oiiotool --pattern noise 64x64 3 -d uint8 -o "$WORK/full.png"
head -c 2000 "$WORK/full.png" >"$WORK/bad.png"
expect_exit 0 "$RT_RENDER" "$WORK/tex.xml" -x 16 -y 12 -o null
grep -q "^rt-render: warning: texture file .*bad.png: cannot read it (.*Read error: hit end of file.*): white is used$" \
    "$WORK/stderr" || fail "the cut texture's warning: $(cat "$WORK/stderr")"
grep -q '^libpng' "$WORK/stderr" && fail "libpng's own line: $(cat "$WORK/stderr")"
# A tree dump of more than 10 MB (25,000 spheres: about 12 MB of JSON) says its size.
python3 - >"$WORK/many.xml" <<'PY'
import random
random.seed(1)
print('<scene><camera fov="50"><origin x="0" y="0" z="-5" /><destination x="0" y="0" z="0" /></camera><objects>')
for _ in range(25000):
    print('<sphere x="%.4f" y="%.4f" z="%.4f" r="0.005" />' % tuple(random.uniform(-1, 1) for _ in range(3)))
print('</objects></scene>')
PY
expect_exit 0 "$RT_INSPECT" "$WORK/many.xml" --dump json -f "$WORK/many.json"
bytes=$(stat -c %s "$WORK/many.json")
grep -q "^rt-inspect: note: .*many.json is $((bytes / 1000000)) MB: the dump holds every node" "$WORK/stderr" ||
    fail "no note of the dump's $bytes bytes: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_INSPECT" "$WORK/many.xml" --dump json -f "$WORK/many.json" -q
[ ! -s "$WORK/stderr" ] || fail "-q still notes: $(cat "$WORK/stderr")"
echo "tools_plain_answers: ok"
