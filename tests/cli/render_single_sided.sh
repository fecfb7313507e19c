# Single-sided materials (docs/scene-format.md, "Single-sided materials"): a green quad with
# double_sided="false" is drawn seen from its front and not there seen from its back (the blue
# background shows), in every accelerator and both integrators; two-sided, it is seen from both.
# rt-convert keeps glTF's doubleSided (TextureSettingsTest's single- and double-sided rows).
source "$(dirname "$0")/common.bash"

cat >"$WORK/quad.xml" <<'XML'
<scene><background r="0" g="0" b="1"/>
  <camera fov="5"><origin z="${EYE}"/><destination/></camera>
  <materials><material name="sheet" r="0" g="1" b="0" ambient="0" diffuse="0" emission="0 1 0"
    double_sided="${SIDED}"/></materials>
  <objects><quad material="sheet"><vertex x="-1" y="-1"/><vertex x="1.5" y="-1"/><vertex x="1.5" y="1.3"/>
    <vertex x="-1" y="1.3"/></quad></objects>
</scene>
XML
# (Its diagonal passes beside the picture's centre.) The centre pixel's red, green and blue, seen from z = $1, two-sided or not ($2), with options $3...
centre() {
    local eye=$1 sided=$2
    shift 2
    "$RT_RENDER" "$WORK/quad.xml" -q -x 1 -y 1 --alpha off --exr-pixels float --set EYE="$eye" \
        --set SIDED="$sided" "$@" -f "$WORK/c.exr" || fail "render from z = $eye failed"
    oiiotool --dumpdata "$WORK/c.exr" | awk '/Pixel/ {print $(NF-2), $(NF-1), $NF}'
}
# Whether "r g b" ($1) lies within 0.05 of $2 in every channel (the path tracer's glossy share).
near() { awk -v a="$1" -v b="$2" 'BEGIN {split(a, x, " "); split(b, y, " ");
    for (i = 1; i <= 3; ++i) if (x[i] - y[i] > 0.05 || y[i] - x[i] > 0.05) exit 1}'; }
for options in "--accel naive" "--accel bsp" "--accel kd" "--accel bvh" "--integrator path -S 4"; do
    # shellcheck disable=SC2086
    {
        front=$(centre 5 false $options)
        near "$front" "0 1 0" || fail "$options: the front is not drawn: $front"
        back=$(centre -5 false $options)
        near "$back" "0 0 1" || fail "$options: the back is drawn: $back"
    }
done
both=$(centre -5 true)
near "$both" "0 1 0" || fail "two-sided: the back is not drawn: $both"

need_shared_models
expect_exit 0 "$RT_CONVERT" -q "$RT_SHARED_DIR/models/glb/TextureSettingsTest/TextureSettingsTest.glb" -o "$WORK/tst.xml"
grep 'name="SingleSidedMaterial"' "$WORK/tst.xml" | grep -q 'double_sided="false"' ||
    fail "SingleSidedMaterial is not single-sided: $(grep SingleSidedMaterial "$WORK/tst.xml")"
grep 'name="DoubleSidedMaterial"' "$WORK/tst.xml" | grep -q 'double_sided' &&
    fail "DoubleSidedMaterial is not two-sided: $(grep DoubleSidedMaterial "$WORK/tst.xml")"
echo "render_single_sided: ok"
