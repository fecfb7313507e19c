# rt-render as a farm task: --tiles CxR --tile I/N renders tile I (its data window in the full
# display window), bad tiles are exit 2, and --skip-existing keeps a complete output but renders
# a missing, damaged or different one again.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
base=(-K -s -S 2 --exr-pixels float)
opts=("${base[@]}" -x 70 -y 40)

"$RT_RENDER" "$scene" "${opts[@]}" -q --tiles 4x4 --tile 5/16 -f "$WORK/tile.exr"
"$RT_RENDER" "$scene" "${opts[@]}" -q --region 17,10,35,20 -f "$WORK/region.exr"
iinfo -v "$WORK/tile.exr" >"$WORK/tile.txt"
grep -q "pixel data origin: x=17, y=10" "$WORK/tile.txt" || fail "tile 5 of 4x4 does not start at 17,10: $(cat "$WORK/tile.txt")"
idiff -fail 0 -warn 0 "$WORK/region.exr" "$WORK/tile.exr" >/dev/null || fail "tile 5 differs from --region 17,10,35,20"

expect_exit 2 "$RT_RENDER" "$scene" "${opts[@]}" --tiles 4x4 --tile 16/16 -f "$WORK/t.exr"
expect_one_error rt-render "--tile 16 is outside 0-15"
expect_exit 2 "$RT_RENDER" "$scene" "${opts[@]}" --tiles 4x4 --tile 1/8 -f "$WORK/t.exr"
expect_one_error rt-render "--tiles 4x4 makes 16 tiles"
expect_exit 2 "$RT_RENDER" "$scene" "${opts[@]}" --tiles 4by4 --tile 1/16 -f "$WORK/t.exr"
expect_one_error rt-render "--tiles: expected CxR"
expect_exit 2 "$RT_RENDER" "$scene" "${opts[@]}" --tiles 71x1 --tile 0/71 -f "$WORK/t.exr"
expect_one_error rt-render "every tile needs a pixel"
expect_exit 2 "$RT_RENDER" "$scene" "${opts[@]}" --tile 1/16 -f "$WORK/t.exr"
expect_exit 2 "$RT_RENDER" "$scene" "${opts[@]}" --tiles 4x4 --tile 1/16 --region 0,0,1,1 -f "$WORK/t.exr"

# A complete output: exit 0 at once, the file untouched (the scene is not even loaded).
touch -d '2000-01-01' "$WORK/tile.exr"
expect_exit 0 "$RT_RENDER" /nonexistent.xml "${opts[@]}" --tiles 4x4 --tile 5/16 -f "$WORK/tile.exr" --skip-existing
grep -q "is complete: nothing to render" "$WORK/stderr" || fail "no note of the skip: $(cat "$WORK/stderr")"
[ "$(stat -c %Y "$WORK/tile.exr")" = "$(date -d 2000-01-01 +%s)" ] || fail "--skip-existing rewrote a complete tile"
# Another tile, another size, a damaged file or none: rendered (again).
expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" --tiles 4x4 --tile 6/16 -f "$WORK/tile.exr" --skip-existing
grep -q "again: its data window is 17,10,35,20" "$WORK/stderr" || fail "tile 6 over tile 5 was not rendered: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_RENDER" "$scene" "${base[@]}" -x 70 -y 41 --tiles 4x4 --tile 6/16 -f "$WORK/tile.exr" --skip-existing
grep -q "again: its display window is 0,0,70,40" "$WORK/stderr" || fail "another image size was not rendered: $(cat "$WORK/stderr")"
size=$(stat -c %s "$WORK/tile.exr")
head -c $((size - 100)) "$WORK/tile.exr" >"$WORK/truncated.exr"
mv "$WORK/truncated.exr" "$WORK/tile.exr"
expect_exit 0 "$RT_RENDER" "$scene" "${base[@]}" -x 70 -y 41 --tiles 4x4 --tile 6/16 -f "$WORK/tile.exr" --skip-existing
grep -q "again: unreadable" "$WORK/stderr" || fail "a truncated file was not rendered again: $(cat "$WORK/stderr")"
rm "$WORK/tile.exr"
expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" --tiles 4x4 --tile 5/16 -f "$WORK/tile.exr" --skip-existing
idiff -fail 0 -warn 0 "$WORK/region.exr" "$WORK/tile.exr" >/dev/null || fail "a missing tile was not rendered"
# Only a file rt-render wrote, with the channels it writes, is complete; the header says so before
# a pixel is read (a 1 MB EXR of 1,000 channels was read whole: 2.6 GB).
full=(-K -s -S 2 -x 70 -y 40)
"$RT_RENDER" "$scene" "${full[@]}" -q -f "$WORK/full.exr"
oiiotool "$WORK/full.exr" -o "$WORK/other.exr"  # the same pixels, written by oiiotool
expect_exit 0 "$RT_RENDER" "$scene" "${full[@]}" -f "$WORK/other.exr" --skip-existing
grep -q "again: rt-render did not write it (Software: 'OpenImageIO" "$WORK/stderr" ||
    fail "a file rt-render did not write was taken as complete: $(cat "$WORK/stderr")"
oiiotool --pattern constant:color=0.5 70x40 1000 -d half -o "$WORK/channels.exr"
expect_exit 0 "$RT_RENDER" "$scene" "${full[@]}" -f "$WORK/channels.exr" --skip-existing
grep -q "again: it has 1000 channels, not 4" "$WORK/stderr" || fail "1000 channels: $(cat "$WORK/stderr")"
echo "farm_tiles: ok"
