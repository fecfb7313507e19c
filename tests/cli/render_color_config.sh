# rt-render carries its colour configuration inside the binary: a copy alone in a folder
# renders PNGs with $OCIO unset; --color-config and $OCIO still win; the EXR header names
# the config used; display, view and look names are checked for every output type.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
config="$RT_SOURCE_DIR/config/ocio/config.ocio"
small=(-K -q -x 32 -y 24)
mkdir "$WORK/bin"
cp "$RT_RENDER" "$WORK/bin/rt-render"
render() { (cd "$WORK/bin" && env -u OCIO ./rt-render "$scene" "${small[@]}" "$@"); }

# Alone in a folder, with no config anywhere near it.
expect_exit 0 render -f "$WORK/alone.png"
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" --color-config "$config" -f "$WORK/file.png"
idiff -fail 0 -warn 0 "$WORK/alone.png" "$WORK/file.png" >/dev/null || fail "the built-in config encodes otherwise"

# The EXR header records the config in use, never the string "$OCIO".
expect_exit 0 render -f "$WORK/builtin.exr"
iinfo -v "$WORK/builtin.exr" | grep -q 'rt:colorConfig: "rt.s built-in' || fail "$(iinfo -v "$WORK/builtin.exr")"
OCIO="$config" expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -f "$WORK/env.exr"
iinfo -v "$WORK/env.exr" | grep -qF "rt:colorConfig: \"$config" || fail "$(iinfo -v "$WORK/env.exr")"

# $OCIO wins over the built-in config, and its errors name it; the built-in config's do not.
OCIO="$WORK/missing.ocio" expect_exit 2 "$RT_RENDER" "$scene" "${small[@]}" -f "$WORK/x.png"
grep -q 'missing.ocio.*\$OCIO' "$WORK/stderr" || fail "a bad \$OCIO is not named: $(cat "$WORK/stderr")"
expect_exit 2 render --view Filmic -f "$WORK/x.png"
if grep -q 'OCIO' "$WORK/stderr"; then fail "the built-in config's error names \$OCIO: $(cat "$WORK/stderr")"; fi

# Unknown names are errors whatever the output type.
for output in "-f $WORK/x.exr" "-o null" "-o text" "-f $WORK/x.png"; do
    for name in "--display P3" "--view Filmic" "--look Sepia"; do
        # shellcheck disable=SC2086 # each string is an option and its value
        expect_exit 2 render $name $output
    done
done
[ ! -e "$WORK/x.exr" ] || fail "an EXR was written with an unknown view"
# --exposure brightens the display-referred outputs by 2^EV before the view and leaves the linear
# ones as rendered; out of range is a usage error.
expect_exit 0 render -f "$WORK/plain.png" -f "$WORK/plain.exr"
expect_exit 0 render --exposure 1 -f "$WORK/bright.png" -f "$WORK/bright.exr"
idiff -fail 0 -warn 0 "$WORK/plain.exr" "$WORK/bright.exr" >/dev/null || fail "--exposure changed the EXR"
expect_exit 0 render --look Brighter -f "$WORK/look.png"
idiff -fail 0.003 -warn 0.003 "$WORK/look.png" "$WORK/bright.png" >/dev/null ||
    fail "--exposure 1 is not the one-stop look Brighter"
if idiff -fail 0 -warn 0 "$WORK/plain.png" "$WORK/bright.png" >/dev/null; then fail "--exposure 1 changed no pixel"; fi
expect_exit 2 render --exposure 100 -f "$WORK/x.png"
expect_exit 2 render --exposure bright -f "$WORK/x.png"
echo "render_color_config: ok"
