# The scene's bounding box and centre, as `assimp info` gives them, so that a camera can be
# placed without guessing: in rt-inspect's table and JSON, rt-convert's summary and JSON, and
# rt-render's --stats-json; the same box from the model and from its converted scene
# (issue 36, item 12).
source "$(dirname "$0")/common.bash"
SCHEMA="$RT_SOURCE_DIR/docs/schema/rt.schema.json"
CHECK="$RT_SOURCE_DIR/tests/cli/json_schema.py"
# Two triangles spanning x -1..3, y 0..4, z -2..2.5 (OBJ is Y-up: no turn).
printf 'v -1 0 -2\nv 3 0 -2\nv 0 4 0\nv 0 1 2.5\nf 1 2 3\nf 1 2 4\n' >"$WORK/model.obj"
box="(-1, 0, -2) to (3, 4, 2.5), centre (1, 2, 0.25)"
# bounds_json FILE PYTHON-PATH: the box at that place of the JSON document is the one above.
bounds_json() {
    python3 - "$1" "$2" <<'PY' || fail "$1: wrong bounds: $(cat "$1")"
import json, sys
d = json.load(open(sys.argv[1]))
b = eval("d" + sys.argv[2])
assert (b["min"], b["max"], b["centre"]) == ([-1, 0, -2], [3, 4, 2.5], [1, 2, 0.25]), b
PY
}

expect_exit 0 "$RT_CONVERT" "$WORK/model.obj" -o "$WORK/model.xml"
grep -qF "  bounds     $box" "$WORK/stderr" || fail "rt-convert's summary: no bounds: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_CONVERT" "$WORK/model.obj" -q --json
cp "$WORK/stdout" "$WORK/convert.json"
bounds_json "$WORK/convert.json" '["bounds"]'
python3 "$CHECK" "$SCHEMA" convertSummary "$WORK/convert.json" || fail "rt-convert --json is not valid"

for scene in model.obj model.xml; do
    expect_exit 0 "$RT_INSPECT" "$WORK/$scene" -q
    grep -qxF "bounds $box" "$WORK/stdout" || fail "rt-inspect $scene: no bounds line: $(cat "$WORK/stdout")"
    expect_exit 0 "$RT_INSPECT" "$WORK/$scene" -q --json
    cp "$WORK/stdout" "$WORK/inspect.json"
    bounds_json "$WORK/inspect.json" '["scene"]["bounds"]'
    python3 "$CHECK" "$SCHEMA" inspectReport "$WORK/inspect.json" || fail "rt-inspect --json is not valid"
done
expect_exit 0 "$RT_RENDER" "$WORK/model.xml" -q -x 8 -y 6 --stats-json "$WORK/render.json"
bounds_json "$WORK/render.json" '["scene"]["bounds"]'
echo "tools_scene_bounds: ok"
