# scripts/check-layers.sh, the layering check CI runs (ctest test "layers"): a copy of libtrace
# passes, and the same copy with one forbidden include fails, naming the file and line.
source "$(dirname "$0")/common.bash"
check="$RT_SOURCE_DIR/scripts/check-layers.sh"

fresh_copy() {
    rm -rf "$WORK/libtrace"
    cp -r "$RT_SOURCE_DIR/libtrace" "$WORK/libtrace"
}

fresh_copy
expect_exit 0 "$check" "$WORK/libtrace"
[ ! -s "$WORK/stderr" ] || fail "a clean copy should pass silently: $(cat "$WORK/stderr")"

# add_line FILE TEXT: appends TEXT to FILE, printing its line number.
add_line() {
    echo "$2" >>"$1"
    wc -l <"$1"
}

# A layer including one above it.
line=$(add_line "$WORK/libtrace/geometry/overlap.h" '#include "render/renderer.h"')
expect_exit 1 "$check" "$WORK/libtrace"
expect_one_error check-layers "libtrace/geometry/overlap.h:$line: geometry/ may not include \"render/renderer.h\""

# The in-memory model reading a file format: the formats (io/) lie above the scene (scene/).
fresh_copy
line=$(add_line "$WORK/libtrace/scene/scene.cpp" '#include "io/xml_loader.h"')
expect_exit 1 "$check" "$WORK/libtrace"
expect_one_error check-layers "libtrace/scene/scene.cpp:$line: scene/ may not include \"io/xml_loader.h\""

# A third-party library outside the layer that links it.
fresh_copy
line=$(add_line "$WORK/libtrace/render/renderer.cpp" '#include <assimp/scene.h>')
expect_exit 1 "$check" "$WORK/libtrace"
expect_one_error check-layers "libtrace/render/renderer.cpp:$line: render/ may not include <assimp/scene.h> (only io/ may)"

# A sub-folder below the rest of its layer including a header of the layer it may not use: the
# BSDFs (render/materials/) know nothing of the integrators.
fresh_copy
line=$(add_line "$WORK/libtrace/render/materials/bsdf.cpp" '#include "render/integrators/path_tracer.h"')
expect_exit 1 "$check" "$WORK/libtrace"
expect_one_error check-layers "libtrace/render/materials/bsdf.cpp:$line: render/materials/ may not include \"render/integrators/path_tracer.h\""

# Such sub-folders including each other: the lights know nothing of the film, nor the materials of
# the lights (that the integrators may use all three, whole folders in their row, the clean copy
# above shows).
fresh_copy
lights=$(add_line "$WORK/libtrace/render/lights/light_tree.cpp" '#include "render/film/aov.h"')
materials=$(add_line "$WORK/libtrace/render/materials/bsdf.cpp" '#include "render/lights/light_sample.h"')
expect_exit 1 "$check" "$WORK/libtrace"
[ "$(wc -l <"$WORK/stderr")" = 2 ] &&
    grep -q "light_tree.cpp:$lights: render/lights/ may not include \"render/film/aov.h\"" "$WORK/stderr" &&
    grep -q "bsdf.cpp:$materials: render/materials/ may not include \"render/lights/light_sample.h\"" "$WORK/stderr" ||
    fail "expected the two forbidden includes between sub-folders, got: $(cat "$WORK/stderr")"

# A folder the table does not know.
fresh_copy
mkdir "$WORK/libtrace/extra"
echo '#include "core/vec3.h"' >"$WORK/libtrace/extra/extra.h"
expect_exit 1 "$check" "$WORK/libtrace"
expect_one_error check-layers "folder extra/ is not in the layer table"
echo "layers_check: ok"
