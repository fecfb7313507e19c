# The default light of a model without lights is a headlight: a white point light at the camera
# rendered, wherever --look-from, --frame or --orbit put it, in both integrators (issue 36).
# A closed box seen from inside is lit by it (before: the light stayed at the file's camera,
# outside the box, and the inside was black); a model renders to the same bits from its file and
# from the XML rt-convert writes, with either integrator (before: the path tracer read the file
# without the light the XML has); the path tracer lights a model with emitters by them alone.
source "$(dirname "$0")/common.bash"

# A closed cube from -1 to 1 (its triangles facing in), grey; box-lamp.obj has a lamp (Ke) inside.
box_obj() {
    echo "mtllib box.mtl"
    echo "usemtl grey"
    for v in "-1 -1 -1" "1 -1 -1" "1 1 -1" "-1 1 -1" "-1 -1 1" "1 -1 1" "1 1 1" "-1 1 1"; do echo "v $v"; done
    printf 'f %s\n' "1 2 3" "1 3 4" "5 8 7" "5 7 6" "1 4 8" "1 8 5" "2 6 7" "2 7 3" "1 5 6" "1 6 2" "4 3 7" "4 7 8"
}
box_obj >"$WORK/box.obj"
printf 'newmtl grey\nKd 0.8 0.8 0.8\nnewmtl lamp\nKd 0 0 0\nKe 4 4 4\n' >"$WORK/box.mtl"
{
    box_obj
    echo "usemtl lamp"
    printf 'v %s\n' "-0.3 0.9 -0.3" "0.3 0.9 -0.3" "0.3 0.9 0.3" "-0.3 0.9 0.3"
    echo "f 9 12 11" && echo "f 9 11 10"
} >"$WORK/box-lamp.obj"

small=(-x 32 -y 24 -q --exr-pixels float)
whitted=("${small[@]}" -s)
path=("${small[@]}" --integrator path -S 4)
options_of() { if [ "$1" = path ]; then opts=("${path[@]}"); else opts=("${whitted[@]}"); fi; }
# mean IMAGE: the mean of the image's first channel (oiiotool --printstats).
mean() { oiiotool "$1" --printstats | awk '/Stats Avg:/ { print $3; exit }'; }
# above A B: whether A > B.
# same A B: whether the two pictures hold the same bits (idiff: the files' headers hold the render time).
same() { idiff -fail 0 -warn 0 "$1" "$2" >/dev/null; }
above() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'; }
zero() { awk -v a="$1" 'BEGIN { exit !(a == 0) }'; }

# File and XML: the same bits, in both integrators, with and without emitters.
for model in box box-lamp; do
    expect_exit 0 "$RT_CONVERT" "$WORK/$model.obj" -o "$WORK/$model.xml"
    grep -q 'headlight="true"' "$WORK/$model.xml" || fail "$model.xml has no headlight: $(grep light "$WORK/$model.xml")"
    for integrator in whitted path; do
        options_of "$integrator"
        expect_exit 0 "$RT_RENDER" "$WORK/$model.obj" "${opts[@]}" -f "$WORK/$model-$integrator-file.exr"
        expect_exit 0 "$RT_RENDER" "$WORK/$model.xml" "${opts[@]}" -f "$WORK/$model-$integrator-xml.exr"
        same "$WORK/$model-$integrator-file.exr" "$WORK/$model-$integrator-xml.exr" ||
            fail "$model, $integrator: the model file and its XML render differently"
        # and from inside, where only a headlight that moved lights the walls
        inside=(--look-from 0,0,0 --look-at 0,0,-1 --fov 90)
        expect_exit 0 "$RT_RENDER" "$WORK/$model.obj" "${opts[@]}" "${inside[@]}" -f "$WORK/$model-$integrator-in-file.exr"
        expect_exit 0 "$RT_RENDER" "$WORK/$model.xml" "${opts[@]}" "${inside[@]}" -f "$WORK/$model-$integrator-in-xml.exr"
        same "$WORK/$model-$integrator-in-file.exr" "$WORK/$model-$integrator-in-xml.exr" ||
            fail "$model, $integrator, inside: the model file and its XML render differently"
    done
done

# Inside the box, lit by the headlight alone: the walls are lit (Whitted before: 0.08, the
# ambient term; the path tracer's: 0).
for integrator in whitted path; do
    m=$(mean "$WORK/box-$integrator-in-file.exr")
    above "$m" 0.25 || fail "$integrator: the inside of the box is dark (mean $m): the headlight did not follow the camera"
done
# The path tracer lights the box with a lamp by the lamp: the headlight is left out, so the
# picture differs from the Whitted one's light, and the lamp's box is darker than the headlit one.
m_lamp=$(mean "$WORK/box-lamp-path-in-file.exr") m_head=$(mean "$WORK/box-path-in-file.exr")
above "$m_lamp" 0.01 || fail "the lamp does not light the box (mean $m_lamp)"
above "$m_head" "$m_lamp" || fail "the headlight seems to light the lamp's box too ($m_lamp against $m_head)"

# Every frame of an orbit inside the box is lit: the headlight moves with the camera.
expect_exit 0 "$RT_RENDER" "$WORK/box.obj" "${whitted[@]}" --look-from 0,0,0.5 --look-at 0,0,0 --fov 90 \
    --orbit 4 -f "$WORK/orbit_#.exr"
for f in 0 1 2 3; do
    m=$(mean "$WORK/orbit_$f.exr")
    above "$m" 0.25 || fail "orbit frame $f is dark (mean $m)"
done
# --no-default-light takes the headlight away (only the ambient
# term of no light: black).
expect_exit 0 "$RT_RENDER" "$WORK/box.obj" "${whitted[@]}" --look-from 0,0,0 --look-at 0,0,-1 --fov 90 \
    --no-default-light -f "$WORK/none.exr"
zero "$(mean "$WORK/none.exr")" || fail "--no-default-light left a light: mean $(mean "$WORK/none.exr")"
echo "render_default_light: ok"
