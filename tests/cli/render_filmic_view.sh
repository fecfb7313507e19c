# --view "ACES 1.0 - SDR Video", the built-in config's filmic view (OpenColorIO 2's ACES 1.0
# output transform): a bright render whose PNG the Standard view clips (many pixels at 255) keeps
# its highlights; mid grey and the EXR are as the docs say.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
bright=(-q -K -s -x 64 -y 48 --exposure 3)   # three stops over: the lit surfaces go far past 1
aces="ACES 1.0 - SDR Video"

"$RT_RENDER" "$scene" "${bright[@]}" -f "$WORK/standard.png" -f "$WORK/standard.exr"
"$RT_RENDER" "$scene" "${bright[@]}" --view "$aces" -f "$WORK/aces.png" -f "$WORK/aces.exr"
idiff -fail 0 -warn 0 "$WORK/standard.exr" "$WORK/aces.exr" >/dev/null || fail "the view changed the EXR"

# The share of pixels with a channel at 255, from a binary PPM.
clipped() {
    oiiotool "$1" --ch R,G,B -o "$WORK/clip.ppm"
    python3 - "$WORK/clip.ppm" <<'PY'
import sys
data = open(sys.argv[1], "rb").read()
fields, i = [], 0
while len(fields) < 4:
    while data[i:i + 1].isspace(): i += 1
    j = i
    while not data[j:j + 1].isspace(): j += 1
    fields.append(data[i:j]); i = j
w, h = int(fields[1]), int(fields[2])
px = data[i + 1:i + 1 + 3 * w * h]
print(f"{sum(255 in px[k:k + 3] for k in range(0, len(px), 3)) / (w * h):.4f}")
PY
}
standard=$(clipped "$WORK/standard.png") filmic=$(clipped "$WORK/aces.png")
echo "pixels with a channel at 255: Standard $standard, $aces $filmic"
awk -v s="$standard" -v f="$filmic" 'BEGIN { exit !(s > 0.2 && f < 0.01) }' || fail "clipped: Standard $standard, ACES $filmic"

# Mid grey (0.18, a sky of it behind the camera's back to the scene) through the ACES output
# transform: display code 91 (0.356), against 118 for Standard.
oiiotool --pattern constant:color=0.18,0.18,0.18 4x4 3 -d float -o "$WORK/grey.exr"
"$RT_RENDER" "$scene" -q -x 8 -y 8 --environment "$WORK/grey.exr" --look-from 0,0,1000 --look-at 0,0,2000 \
    --alpha off --view "$aces" -f "$WORK/grey.png"
code=$(oiiotool "$WORK/grey.png" --cut 1x1+0+0 --printstats | awk '/Avg:/ {printf "%.0f", $3 * 255; exit}')
[[ $code == 91 ]] || fail "mid grey through $aces is code $code, not 91"
echo "render_filmic_view: ok"
