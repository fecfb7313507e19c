# rt-render --light TYPE:NUMBERS adds point, spot and sun lights from the command line, in both
# integrators, replacing the default headlight; --no-default-light removes it (issue 36).
# Bad values are one error line, exit 2.
source "$(dirname "$0")/common.bash"

# A closed grey cube from -1 to 1, without lights: it gets the headlight.
{
    echo "mtllib box.mtl" && echo "usemtl grey"
    for v in "-1 -1 -1" "1 -1 -1" "1 1 -1" "-1 1 -1" "-1 -1 1" "1 -1 1" "1 1 1" "-1 1 1"; do echo "v $v"; done
    printf 'f %s\n' "1 2 3" "1 3 4" "5 8 7" "5 7 6" "1 4 8" "1 8 5" "2 6 7" "2 7 3" "1 5 6" "1 6 2" "4 3 7" "4 7 8"
} >"$WORK/box.obj"
printf 'newmtl grey\nKd 0.8 0.8 0.8\n' >"$WORK/box.mtl"
inside=(-x 32 -y 24 -q --exr-pixels float --look-from 0,0,0 --look-at 0,0,-1 --fov 90)
# stats IMAGE: "r g b", the image's mean colour; pixel IMAGE X Y: that pixel's.
stats() { oiiotool "$1" --printstats | awk '/Stats Avg:/ { print $3, $4, $5; exit }'; }
pixel() { oiiotool "$1" --cut "1x1+$2+$3" --printstats | awk '/Stats Avg:/ { print $3, $4, $5; exit }'; }
# same A B: whether the two pictures hold the same bits (idiff: the files' headers hold the render time).
same() { idiff -fail 0 -warn 0 "$1" "$2" >/dev/null; }
above() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'; }
zero() { awk -v a="$1" 'BEGIN { exit !(a == 0) }'; }

for integrator in whitted path; do
    opts=("${inside[@]}" --integrator "$integrator" -S 2)
    [ "$integrator" = whitted ] && opts+=(-s)
    # A white point light at the camera is the headlight: the same bits.
    expect_exit 0 "$RT_RENDER" "$WORK/box.obj" "${opts[@]}" -f "$WORK/head.exr"
    expect_exit 0 "$RT_RENDER" "$WORK/box.obj" "${opts[@]}" --light point:0,0,0 -f "$WORK/point.exr"
    same "$WORK/head.exr" "$WORK/point.exr" || fail "$integrator: --light point:0,0,0 is not the headlight at 0,0,0"
    # A red one replaces the headlight (nothing green is left), W scales it.
    expect_exit 0 "$RT_RENDER" "$WORK/box.obj" "${opts[@]}" --light point:0,0,0,1,0,0 -f "$WORK/red.exr"
    read -r r g b <<<"$(stats "$WORK/red.exr")"
    above "$r" 0.1 && zero "$g" && zero "$b" || fail "$integrator: a red light gave $r $g $b"
    expect_exit 0 "$RT_RENDER" "$WORK/box.obj" "${opts[@]}" --light point:0,0,0,1,0,0,0.5 -f "$WORK/half.exr"
    read -r half _ <<<"$(stats "$WORK/half.exr")"
    awk -v a="$half" -v b="$r" 'BEGIN { exit !(a > 0.49 * b && a < 0.51 * b) }' ||
        fail "$integrator: W 0.5 gave $half against $r"
    # Two lights add up: the second is a red spot at the camera, narrow, pointing ahead.
    expect_exit 0 "$RT_RENDER" "$WORK/box.obj" "${opts[@]}" --light point:0,0,0,0,1,0 \
        --light spot:0,0,0,0,0,-1,20,1,0,0 -f "$WORK/spot.exr"
    read -r cr cg _ <<<"$(pixel "$WORK/spot.exr" 16 12)"
    read -r er eg _ <<<"$(pixel "$WORK/spot.exr" 1 12)"
    above "$cr" 0.1 && above "$cg" 0.1 || fail "$integrator: the spot's centre is $cr $cg"
    above "$cr" "$er" || fail "$integrator: the spot lights its edge ($er) as its centre ($cr)"
    # A sun, seen from outside, lights the box; without it and without the headlight, nothing does.
    outside=(-x 32 -y 24 -q --exr-pixels float --integrator "$integrator" -S 2)
    expect_exit 0 "$RT_RENDER" "$WORK/box.obj" "${outside[@]}" --light sun:-1,-2,-1 -f "$WORK/sun.exr"
    read -r r _ <<<"$(stats "$WORK/sun.exr")"
    above "$r" 0.02 || fail "$integrator: the sun lights nothing (mean $r)"
    expect_exit 0 "$RT_RENDER" "$WORK/box.obj" "${outside[@]}" --no-default-light -f "$WORK/dark.exr"
    read -r r _ <<<"$(stats "$WORK/dark.exr")"
    zero "$r" || fail "$integrator: --no-default-light left light (mean $r)"
done

for bad in "lamp:1,2,3:TYPE one of point, spot, sun" "point:1,2:expected point:X,Y,Z" \
    "point:1,2,nan:finite numbers" "point:1,2,3,1,-1,0:must not be negative" "point:1,2,3,1,1,1,-2:must not be negative" \
    "spot:0,0,0,0,0,0:no direction" "spot:0,0,0,0,0,-1,120:the cone must be" "spot:0,0,0,0,0,-1,0:the cone must be" \
    "sun:0,0,0:no direction" "sun:1,2,3,4:expected sun:DX,DY,DZ"; do
    value=${bad%:*} why=${bad##*:}
    expect_exit 2 "$RT_RENDER" "$WORK/box.obj" -q --light "$value"
    expect_one_error rt-render "$why"
done
echo "render_lights: ok"
