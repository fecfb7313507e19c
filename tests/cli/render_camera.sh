# rt-render's camera: --look-from/--look-at/--up/--fov give the same bits as the same camera in the
# XML; a picture keeps its framing at any -x/-y for every form of camera; --frame fits the scene
# with a margin; --camera picks a named or numbered camera.
source "$(dirname "$0")/common.bash"

# scene CAMERA...: three spheres with the given <camera> elements.
scene() {
    cat <<XML
<scene><background r="0.1" g="0.2" b="0.3"/>
$*
<objects><sphere x="0" y="0" z="0" r="1"/><sphere x="2.5" y="0.5" z="1" r="0.7"/><sphere x="-2" y="-0.5" z="0.5" r="0.5"/></objects>
<lights><light x="-4" y="6" z="-8"/></lights></scene>
XML
}
xmlCamera='<camera fov="40"><origin x="3" y="2" z="-9"/><destination x="0.5" y="0.2" z="0"/><up x="0.1" y="1" z="0"/></camera>'
other='<camera f="1200" zoom="80"><origin x="-5" y="9" z="2"/><destination x="1" y="1" z="1"/></camera>'
scene "$xmlCamera" >"$WORK/a.xml"
scene "$other" >"$WORK/b.xml"
opts=(-q -s -x 64 -y 48 --exr-pixels float)

# The overrides turn b's camera into a's, bit for bit.
"$RT_RENDER" "$WORK/a.xml" "${opts[@]}" -f "$WORK/a.exr"
"$RT_RENDER" "$WORK/b.xml" "${opts[@]}" --look-from 3,2,-9 --look-at 0.5,0.2,0 --up 0.1,1,0 --fov 40 -f "$WORK/b.exr"
idiff -fail 0 -warn 0 "$WORK/a.exr" "$WORK/b.exr" >"$WORK/idiff.txt" || fail "overrides differ from the XML camera: $(cat "$WORK/idiff.txt")"
"$RT_RENDER" "$WORK/b.xml" "${opts[@]}" -f "$WORK/b0.exr"
if idiff -fail 0 -warn 0 "$WORK/a.exr" "$WORK/b0.exr" >/dev/null; then fail "the comparison cannot fail"; fi

# coverage FILE: the mean alpha, the fraction of the picture the spheres cover.
coverage() { oiiotool "$1" --ch A --printstats 2>/dev/null | awk '$1 == "Stats" && $2 == "Avg:" {print $3}'; }
# The same framing at 64x48 and 256x192, whatever gives the focal distance (f, the distance, fov).
for camera in "$xmlCamera" "$other" '<camera><origin x="0" y="0.5" z="-6"/><destination z="600"/></camera>'; do
    scene "$camera" >"$WORK/c.xml"
    "$RT_RENDER" "$WORK/c.xml" "${opts[@]}" -f "$WORK/small.exr"
    "$RT_RENDER" "$WORK/c.xml" -q -x 256 -y 192 -f "$WORK/large.exr"
    small=$(coverage "$WORK/small.exr") large=$(coverage "$WORK/large.exr")
    awk -v s="$small" -v l="$large" 'BEGIN { exit !(s > 0.01 && (s - l < 0.02 && l - s < 0.02)) }' ||
        fail "$camera: the spheres cover $small of 64x48 but $large of 256x192"
done

# --frame: the spheres fill the picture, and no pixel of its edge touches them.
edge() { oiiotool "$1" --ch A --cut "$2" --printstats 2>/dev/null | awk '$1 == "Stats" && $2 == "Max:" {print $3 + 0}'; }
for size in "-x 64 -y 48" "-x 30 -y 60"; do
    read -r _ w _ h <<<"$size"
    "$RT_RENDER" "$WORK/b.xml" -q $size --frame -f "$WORK/framed.exr"
    for border in "${w}x1+0+0" "${w}x1+0+$((h - 1))" "1x${h}+0+0" "1x${h}+$((w - 1))+0"; do
        [ "$(edge "$WORK/framed.exr" "$border")" = 0 ] || fail "--frame at $size: the scene touches the edge $border"
    done
    awk -v c="$(coverage "$WORK/framed.exr")" 'BEGIN { exit !(c > 0.03) }' || fail "--frame at $size: the scene is small"
done

# --camera NAME|INDEX picks among named cameras; the first is the default.
scene "<camera name=\"far\" fov=\"10\"><origin z=\"-30\"/><destination/></camera>" \
    "${xmlCamera/<camera /<camera name=\"near\" }" >"$WORK/two.xml"
for pick in near 1; do
    "$RT_RENDER" "$WORK/two.xml" "${opts[@]}" --camera "$pick" -f "$WORK/pick.exr"
    idiff -fail 0 -warn 0 "$WORK/a.exr" "$WORK/pick.exr" >/dev/null || fail "--camera $pick is not the second camera"
done
"$RT_RENDER" "$WORK/two.xml" "${opts[@]}" -f "$WORK/first.exr"
if idiff -fail 0 -warn 0 "$WORK/a.exr" "$WORK/first.exr" >/dev/null; then fail "the first camera is not the default"; fi
expect_exit 2 "$RT_RENDER" "$WORK/two.xml" -q --camera side
expect_one_error rt-render '--camera side: .*(its cameras: 0 "far", 1 "near")'
# A scene of one camera says so, not "(it has 0)".
expect_exit 2 "$RT_RENDER" "$WORK/a.xml" -q --camera 1
expect_one_error rt-render '--camera 1: .*(its one camera: 0)'

# Bad values are usage errors.
expect_exit 2 "$RT_RENDER" "$WORK/a.xml" -q --look-from 1,2
expect_one_error rt-render "--look-from: expected X,Y,Z"
expect_exit 2 "$RT_RENDER" "$WORK/a.xml" -q --look-at 3,2,-9 --look-from 3,2,-9
expect_one_error rt-render "origin and destination are the same point"
expect_exit 2 "$RT_RENDER" "$WORK/a.xml" -q --fov 180
# A model without a camera gets one framing it, and a note says so, unless --look-from, --look-at
# or --fov place the camera: then the note would speak of a camera not used (issue 36, item 9).
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$WORK/nocamera.obj"
expect_exit 0 "$RT_RENDER" "$WORK/nocamera.obj" -x 8 -y 6 --progress none
grep -q "warning: no usable camera: made one" "$WORK/stderr" || fail "no note on the generated camera: $(cat "$WORK/stderr")"
for placed in "--look-from 0.3,0.3,3" "--look-at 0.3,0.3,0" "--fov 30" "--look-from 0.3,0.3,3 --look-at 0.3,0.3,0"; do
    expect_exit 0 "$RT_RENDER" "$WORK/nocamera.obj" -x 8 -y 6 --progress none $placed
    grep -q "usable camera" "$WORK/stderr" && fail "$placed: a note on a camera it replaced: $(cat "$WORK/stderr")"
done
echo "render_camera: ok"
