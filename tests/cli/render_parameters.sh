# rt-render --set NAME=VALUE fills $NAME, ${NAME} and ${NAME:-default} in the XML scene's
# attribute values (Mitsuba's -D): a sweep renders what the same scene with the values written
# in gives, bit for bit; an unset name without a default is exit 2 naming it, file:line.
source "$(dirname "$0")/common.bash"

# scene RADIUS RED FOV: one sphere and a light.
scene() {
    cat <<XML
<scene>
  <camera fov="$3"><origin x="0" y="1" z="-6"/><destination/></camera>
  <materials><material name="m" r="$2" g="0.6" b="0.3"/></materials>
  <objects><sphere r="$1" material="m"/></objects>
  <lights><light x="-3" y="5" z="-6"/></lights>
</scene>
XML
}
scene '${radius}' '$red' '${fov:-40}' >"$WORK/sweep.xml"
opts=(-q -s -x 48 -y 36 --exr-pixels float)

for radius in 0.5 1.5; do
    scene "$radius" 0.9 40 >"$WORK/fixed.xml"
    "$RT_RENDER" "$WORK/fixed.xml" "${opts[@]}" -f "$WORK/fixed.exr"
    expect_exit 0 "$RT_RENDER" "$WORK/sweep.xml" "${opts[@]}" --set radius=$radius --set red=0.9 -f "$WORK/sweep.exr"
    idiff -fail 0 -warn 0 "$WORK/fixed.exr" "$WORK/sweep.exr" >/dev/null || fail "--set radius=$radius is not the written scene"
done
# The default gives way to a value; a later --set of a name wins.
scene 1 0.9 25 >"$WORK/fixed.xml"
"$RT_RENDER" "$WORK/fixed.xml" "${opts[@]}" -f "$WORK/fixed.exr"
expect_exit 0 "$RT_RENDER" "$WORK/sweep.xml" "${opts[@]}" --set radius=1 --set red=0.2 --set red=0.9 --set fov=25 -f "$WORK/sweep.exr"
idiff -fail 0 -warn 0 "$WORK/fixed.exr" "$WORK/sweep.exr" >/dev/null || fail "--set fov=25 did not replace the default"

expect_exit 2 "$RT_RENDER" "$WORK/sweep.xml" -q --set red=1
expect_one_error rt-render "$WORK/sweep.xml:4: attribute 'r': parameter \$radius has no value"
expect_exit 2 "$RT_RENDER" "$WORK/sweep.xml" -q --set 1radius=1
expect_one_error rt-render "--set: expected NAME=VALUE"
expect_exit 2 "$RT_RENDER" "$WORK/sweep.xml" -q --set radius=big --set red=1
expect_one_error rt-render "$WORK/sweep.xml:4: <sphere> attribute 'r': 'big' is not a number"
echo "render_parameters: ok"
