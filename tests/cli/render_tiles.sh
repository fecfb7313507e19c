# Render farms (docs/render-farm.md): four --region tiles merged with oiiotool equal one
# full render exactly, and the thread count changes no bit.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
# Every random part on (jittered supersampling, soft shadows, glossy reflections); 70x40
# and the split at 33,17 are off the 32x32 block grid on purpose.
opts=(-q -s -d 3 -x 70 -y 40 -S 2 -D b -r 3 --exr-pixels float)
"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/full.exr"
"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/t0.exr" --region 0,0,33,17
"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/t1.exr" --region 33,0,70,17
"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/t2.exr" --region 0,17,33,40
"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/t3.exr" --region 33,17,70,40

iinfo -v "$WORK/t1.exr" >"$WORK/t1.txt"
grep -q "pixel data origin: x=33, y=0" "$WORK/t1.txt" || fail "tile 1 does not start at 33,0: $(cat "$WORK/t1.txt")"
grep -q "full/display size: 70 x 40" "$WORK/t1.txt" || fail "tile 1 lost the display window"

# The merge of docs/render-farm.md: outside its data window a tile reads as zero, so the sum is exact.
oiiotool "$WORK/t0.exr" "$WORK/t1.exr" --add "$WORK/t2.exr" --add "$WORK/t3.exr" --add -o "$WORK/merged.exr"
idiff -fail 0 -warn 0 "$WORK/full.exr" "$WORK/merged.exr" >"$WORK/idiff.txt" || fail "merged tiles differ: $(cat "$WORK/idiff.txt")"
# ... and the comparison can fail: three tiles are not the picture.
oiiotool "$WORK/t0.exr" "$WORK/t1.exr" --add "$WORK/t2.exr" --add -o "$WORK/partial.exr"
if idiff -fail 0 -warn 0 "$WORK/full.exr" "$WORK/partial.exr" >/dev/null; then fail "idiff passed a missing tile"; fi

"$RT_RENDER" "$scene" "${opts[@]}" --threads 1 -f "$WORK/one.exr"
"$RT_RENDER" "$scene" "${opts[@]}" --threads 2 -f "$WORK/two.exr"
idiff -fail 0 -warn 0 "$WORK/one.exr" "$WORK/two.exr" >/dev/null || fail "1 and 2 threads differ"
idiff -fail 0 -warn 0 "$WORK/one.exr" "$WORK/full.exr" >/dev/null || fail "two renders of the same scene differ"
echo "render_tiles: ok"
