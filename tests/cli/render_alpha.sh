# Alpha: on by default where the format has it (PNG, TGA straight; EXR premultiplied), off on request.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/transforms.xml"
opts=(-q -x 40 -y 30)

"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/a.png"
iinfo "$WORK/a.png" | grep -q "4 channel, uint8 png" || fail "a.png has no alpha: $(iinfo "$WORK/a.png")"
"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/a.tga"
iinfo "$WORK/a.tga" | grep -q "4 channel" || fail "a.tga has no alpha: $(iinfo "$WORK/a.tga")"
"$RT_RENDER" "$scene" "${opts[@]}" --alpha off -f "$WORK/b.png"
iinfo "$WORK/b.png" | grep -q "3 channel, uint8 png" || fail "--alpha off wrote alpha: $(iinfo "$WORK/b.png")"

# EXR: premultiplied, so a pixel with alpha 0 is 0 in every channel; without alpha, the background.
"$RT_RENDER" "$scene" "${opts[@]}" -S 4 --exr-pixels float -f "$WORK/a.exr"
"$RT_RENDER" "$scene" "${opts[@]}" -S 4 --exr-pixels float --alpha off -f "$WORK/b.exr"
iinfo -v "$WORK/a.exr" | grep -q "channel list: R, G, B, A" || fail "a.exr: $(iinfo -v "$WORK/a.exr")"
stats=$(oiiotool "$WORK/a.exr" --printstats)
grep -q "Min: 0.000000 0.000000 0.000000 0.000000" <<<"$stats" || fail "no empty pixel is all zero: $stats"
# Fractional coverage from supersampling: some alpha strictly between 0 and 1.
oiiotool "$WORK/a.exr" --ch A -o "$WORK/alpha.exr"
oiiotool --dumpdata "$WORK/alpha.exr" | awk '/^ *Pixel/ && $NF > 0 && $NF < 1 {found = 1} END {exit !found}' ||
    fail "-S 4 gave no fractional alpha"
# Premultiplied colour plus the background's share (1 - alpha) is the picture without alpha.
background=$(grep -o '<background[^>]*>' "$scene" | sed 's/.*r="\([^"]*\)" g="\([^"]*\)" b="\([^"]*\)".*/\1,\2,\3/')
oiiotool "$WORK/a.exr" --ch R=A,G=A,B=A --mulc -1 --addc 1 --mulc "$background" \
    "$WORK/a.exr" --ch R,G,B --add -o "$WORK/over.exr"
idiff -fail 1e-5 -warn 1e-5 "$WORK/over.exr" "$WORK/b.exr" >"$WORK/idiff.txt" ||
    fail "premultiplied over the background is not the picture without alpha: $(cat "$WORK/idiff.txt")"

expect_exit 2 "$RT_RENDER" "$scene" -q -o text --alpha on
expect_one_error rt-render "--alpha on: text output has no alpha channel"
echo "render_alpha: ok"
