# Scene files through a tool: every bundled scene loads (also from stdin), and bad scenes
# give one line "rt-render ERROR: file:line: what" and exit code 2 (docs/scene-format.md).
source "$(dirname "$0")/common.bash"
render=("$RT_RENDER" -q -p)  # -p: load and build only

for scene in spheres transforms inline; do
    expect_exit 0 "${render[@]}" "$RT_SOURCE_DIR/scenes/$scene.xml"
done
# From stdin a scene with inline models needs no folder.
expect_exit 0 "${render[@]}" - <"$RT_SOURCE_DIR/scenes/inline.xml"

# expect_error FILE MESSAGE: rt-render exits 2 with exactly this message.
expect_error() {
    expect_exit 2 "${render[@]}" "$1"
    [ "$(cat "$WORK/stderr")" = "rt-render ERROR: $2" ] || fail "stderr: $(cat "$WORK/stderr"), expected: $2"
}

cat >"$WORK/colour.xml" <<'XML'
<scene>
  <camera><origin/><destination z="1"/></camera>
  <materials><material name="m" colour="1"/></materials>
</scene>
XML
expect_error "$WORK/colour.xml" "$WORK/colour.xml:3: unknown attribute 'colour' on <material>"

# A RAW model whose count promises more than the file holds.
printf 'raw3dT\x02\x00\x00\x00' >"$WORK/short.raw"
cat >"$WORK/short.xml" <<'XML'
<scene>
  <camera><origin/><destination z="1"/></camera>
  <models>
    <model name="m" file="short.raw"/>
  </models>
</scene>
XML
expect_error "$WORK/short.xml" \
    "$WORK/short.xml:4: model 'm': $WORK/short.raw: byte 10: truncated RAW data: 72 bytes of data for 2 triangles, the file has 0"

printf '<scene>\n<camera>\n</scene>\n' >"$WORK/malformed.xml"
expect_error "$WORK/malformed.xml" "$WORK/malformed.xml:3: malformed XML: Start-end tags mismatch"
