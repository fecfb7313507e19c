# Two rt-convert runs writing the same scene publish it as one unit each (XML and RAW folder,
# under a lock): 20 pairs converting different models to one name all exit 0, every resulting
# XML loads (rt-render -p) and names only RAW files of its folder, and no temporary is left.
source "$(dirname "$0")/common.bash"
models="$RT_SOURCE_DIR/scenes/models"
for pair in $(seq 20); do
    out="$WORK/out$pair"
    mkdir -p "$out"
    "$RT_CONVERT" "$models/octahedron.raw" -o "$out/scene.xml" 2>"$WORK/a.err" & a=$!
    "$RT_CONVERT" "$models/atom.raw" -o "$out/scene.xml" 2>"$WORK/b.err" & b=$!
    wait "$a" || fail "pair $pair: the first run failed: $(cat "$WORK/a.err")"
    wait "$b" || fail "pair $pair: the second run failed: $(cat "$WORK/b.err")"
    expect_exit 0 "$RT_RENDER" "$out/scene.xml" -p -q
    [ "$(ls "$out/scene")" = "$(basename "$(grep -o 'scene/[^"]*\.raw' "$out/scene.xml")")" ] ||
        fail "pair $pair: the XML names $(grep -o 'scene/[^"]*\.raw' "$out/scene.xml"), the folder holds $(ls "$out/scene")"
    [ "$(ls -A "$out")" = "scene
scene.xml" ] || fail "pair $pair: left behind: $(ls -A "$out")"
done
echo "convert_concurrent: ok"
