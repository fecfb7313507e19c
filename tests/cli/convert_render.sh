# Converted glTF files render with rt-render and match references in tests/golden/
# (linear half-float EXR, 96x72, made by this pipeline and checked by eye): issue-261 with the
# file's camera and point light, Duck with the file's camera and the generated light. The
# tolerance is the golden-image test's (tests/image/render_golden_test.cpp): every channel
# within 2e-3 except at most 1% of the pixels (float geometry moves an edge across a pixel
# centre). The scene piped through -o - renders exactly as the scene written to files, and
# rt-render reading the model file itself (converted in memory) renders the same picture.
# Regenerate: RT_UPDATE_GOLDEN=1 ctest -R cli.convert_render, then look at the pictures.
source "$(dirname "$0")/common.bash"
need_shared_models
MODELS="$RT_SHARED_DIR/models"
GOLDEN="$RT_SOURCE_DIR/tests/golden"
render() { "$RT_RENDER" "$1" -f "$2" -x 96 -y 72 -s -q --alpha off; }  # the references are RGB

for case in issue261:gltf/PointLightCamera-issue261/issue-261.gltf duck:gltf/Duck/Duck.gltf; do
    name=${case%%:*} model="$MODELS/${case#*:}"
    expect_exit 0 "$RT_CONVERT" "$model" -o "$WORK/$name.xml"
    # Relative names, so that the reference's header records no path of the machine that made it.
    (cd "$WORK" && render "$name.xml" "$name-files.exr") || fail "$name: rt-render failed on the converted scene"
    "$RT_CONVERT" "$model" -o - 2>/dev/null | render - "$WORK/$name-piped.exr" || fail "$name: rt-render - failed"
    idiff -fail 0 -warn 0 "$WORK/$name-files.exr" "$WORK/$name-piped.exr" >"$WORK/idiff.txt" ||
        fail "$name: piped and written scenes render differently: $(cat "$WORK/idiff.txt")"
    render "$model" "$WORK/$name-direct.exr" || fail "$name: rt-render failed on the model file itself"
    idiff -fail 0 -warn 0 "$WORK/$name-files.exr" "$WORK/$name-direct.exr" \
        >"$WORK/idiff.txt" || fail "$name: the model file renders differently: $(cat "$WORK/idiff.txt")"
    reference="$GOLDEN/convert_$name.exr"
    if [ -n "${RT_UPDATE_GOLDEN:-}" ]; then
        cp "$WORK/$name-files.exr" "$reference"
        echo "wrote $reference"
        continue
    fi
    idiff -fail 2e-3 -failpercent 1 -warn 2e-3 -warnpercent 1 "$reference" "$WORK/$name-files.exr" >"$WORK/idiff.txt" ||
        fail "$name: differs from $reference: $(cat "$WORK/idiff.txt")"
done
echo "convert_render: ok"
