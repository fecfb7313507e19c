# rt-convert -o replaces a converted scene whole or not at all: a second conversion to the
# same name leaves only its own RAW files, and one that fails while writing (here: a file
# size limit, as a full disk would) exits 1 and leaves the first scene byte for byte.
source "$(dirname "$0")/common.bash"
need_shared_models
MODELS="$RT_SHARED_DIR/models"

snapshot() { (cd "$WORK/out" && find . -type f -print0 | sort -z | xargs -0 md5sum); }

mkdir -p "$WORK/out"
expect_exit 0 "$RT_CONVERT" "$MODELS/obj/CornellBox-Original/CornellBox-Original.obj" -o "$WORK/out/scene.xml"
[ "$(ls "$WORK/out/scene" | wc -l)" = 8 ] || fail "the Cornell box should give 8 RAW files"

# Another model to the same name: its RAW files only.
expect_exit 0 "$RT_CONVERT" "$MODELS/gltf/Duck/Duck.gltf" -o "$WORK/out/scene.xml"
[ "$(ls "$WORK/out/scene" | wc -l)" = 1 ] || fail "stale RAW files left: $(ls "$WORK/out/scene")"
[ "$(ls -A "$WORK/out")" = "scene
scene.xml" ] || fail "unexpected files: $(ls -A "$WORK/out")"
before=$(snapshot)

# The engine's RAW files exceed 64 KiB; with that limit writing fails part way.
got=0
(trap '' XFSZ; ulimit -f 64; exec "$RT_CONVERT" "$MODELS/glb/2CylinderEngine/2CylinderEngine.glb" \
    -o "$WORK/out/scene.xml") >"$WORK/stdout" 2>"$WORK/stderr" || got=$?
[ "$got" = 1 ] || { cat "$WORK/stderr" >&2; fail "a failed write exited $got, expected 1"; }
grep -q "^rt-convert ERROR: " "$WORK/stderr" || fail "no error line: $(cat "$WORK/stderr")"
[ "$(snapshot)" = "$before" ] || fail "the failed conversion changed the previous scene"
[ "$(ls -A "$WORK/out")" = "scene
scene.xml" ] || fail "temporary files left: $(ls -A "$WORK/out")"
echo "convert_atomic: ok"
