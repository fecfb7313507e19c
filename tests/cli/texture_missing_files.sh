# Missing texture files: one warning line per file, not one per material or map that names it,
# and each a single line (OpenImageIO's error text kept to its first line); rt-convert says the
# same before it writes a scene that names them, once per file, and in --json's notes
# (issue 36, item 7). The picture is rendered with white in their place.
source "$(dirname "$0")/common.bash"
# Three missing JPEGs named seven times by four materials.
cat >"$WORK/model.mtl" <<'MTL'
newmtl one
map_Kd a.jpg
map_d b.jpg
newmtl two
map_Kd a.jpg
map_Ke c.jpg
newmtl three
map_Kd b.jpg
map_d a.jpg
newmtl four
map_Kd c.jpg
MTL
{
    echo "mtllib model.mtl"
    printf 'v %s\n' "0 0 0" "1 0 0" "0 1 0" "1 1 0" "2 0 0" "2 1 0"
    printf 'vt %s\n' "0 0" "1 0" "0 1" "1 1"
    echo "usemtl one"; echo "f 1/1 2/2 3/3"
    echo "usemtl two"; echo "f 2/2 4/4 3/3"
    echo "usemtl three"; echo "f 2/1 5/2 4/3"
    echo "usemtl four"; echo "f 5/1 6/2 4/3"
} >"$WORK/model.obj"

# warnings_once TOOL PREFIX: stderr has exactly one line about each missing file, starting with
# PREFIX, and no other line speaks of them (nothing wrapped onto a second line).
warnings_once() {
    for file in a.jpg b.jpg c.jpg; do
        [ "$(grep -c "^$2texture file $WORK/$file: " "$WORK/stderr")" = 1 ] ||
            fail "$1: not one line about $file: $(cat "$WORK/stderr")"
    done
    [ "$(grep -c "jpg\|open\|No such" "$WORK/stderr")" = 3 ] || fail "$1: more than three lines on them: $(cat "$WORK/stderr")"
}

expect_exit 0 "$RT_RENDER" "$WORK/model.obj" -x 16 -y 12 -f "$WORK/out.png" --progress none
warnings_once rt-render "rt-render: warning: "
grep -q "rt-render: warning: texture file $WORK/a.jpg: cannot read it (.*): white is used$" "$WORK/stderr" ||
    fail "rt-render: the warning does not say what is wrong: $(cat "$WORK/stderr")"

expect_exit 0 "$RT_CONVERT" "$WORK/model.obj" -o "$WORK/model.xml"
warnings_once rt-convert "  note: "
grep -q "^  note: texture file $WORK/b.jpg: cannot read it (No such file or directory): renders white$" "$WORK/stderr" ||
    fail "rt-convert: no note on the missing b.jpg: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_CONVERT" "$WORK/model.obj" -q --json
[ "$(grep -c '"texture file ' "$WORK/stdout")" = 3 ] || fail "rt-convert --json: not three notes: $(cat "$WORK/stdout")"
[ ! -s "$WORK/stderr" ] || fail "rt-convert -q printed: $(cat "$WORK/stderr")"

# The converted scene renders with the same single warnings; a file that is there is not named.
oiiotool --pattern checker:width=2:height=2 4x4 3 -d uint8 -o "$WORK/c.jpg"
expect_exit 0 "$RT_RENDER" "$WORK/model.xml" -x 16 -y 12 -f "$WORK/out2.png" --progress none
[ "$(grep -c "texture file" "$WORK/stderr")" = 2 ] || fail "rendering the XML: not two texture lines: $(cat "$WORK/stderr")"
grep -q "c.jpg" "$WORK/stderr" && fail "c.jpg is there now, and was named: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_CONVERT" "$WORK/model.obj"
[ "$(grep -c "texture file" "$WORK/stderr")" = 2 ] || fail "rt-convert: not two texture notes: $(cat "$WORK/stderr")"
echo "texture_missing_files: ok"
