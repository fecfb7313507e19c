# Every JSON document the tools write (rt-render --stats-json, rt-inspect --json and --dump json,
# rt-convert --json) is valid against docs/schema/rt.schema.json, whose every field docs/json.md
# documents; and the check is strict: a field of the wrong type, an undocumented field or a
# missing version is rejected.
source "$(dirname "$0")/common.bash"
source "$(dirname "$0")/inspect_scenes.bash"
python3 -c 'import jsonschema' 2>/dev/null || fail "needs python3-jsonschema (scripts/install-deps.sh)"
SCHEMA="$RT_SOURCE_DIR/docs/schema/rt.schema.json"
CHECK="$RT_SOURCE_DIR/tests/cli/json_schema.py"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
small=(-x 32 -y 24 -q)

# valid DEFINITION FILE...: each file is a valid DEFINITION document.
valid() { python3 "$CHECK" "$SCHEMA" "$@" || fail "not a valid $1 document: ${*:2}"; }
# invalid DEFINITION FILE PYTHON: FILE changed by the Python statement (on `d`) must be rejected.
invalid() {
    python3 -c "import json,sys; d=json.load(open(sys.argv[1])); $3; json.dump(d, open(sys.argv[2], 'w'))" \
        "$2" "$WORK/changed.json"
    ! python3 "$CHECK" "$SCHEMA" "$1" "$WORK/changed.json" 2>"$WORK/check.txt" || fail "accepted: $3"
    grep -q "json_schema ERROR: $WORK/changed.json: " "$WORK/check.txt" || fail "no error line for: $3"
}

python3 "$CHECK" --documented "$SCHEMA" "$RT_SOURCE_DIR/docs/json.md" || fail "docs/json.md misses fields"

# rt-render: every tree, supersampling and distributed rays in a region, preprocessing only,
# and a render with non-finite samples (firstNonFinitePixel is then [x, y], not null).
n=0
for options in "--accel naive" "-B -s -d 3" "-K -S 2 -D b -r 2 --region 4,4,20,12" "-p --kd-max-depth 9"; do
    n=$((n + 1))
    expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" $options --stats-json "$WORK/render$n.json"
done
cat >"$WORK/overflow.xml" <<'XML'
<scene>
  <camera fov="50"><origin x="0" y="0" z="-5" /><destination x="0" y="0" z="0" /></camera>
  <materials><material name="white" r="1e15" g="1e15" b="1e15" ambient="0.1" diffuse="1e15" /></materials>
  <objects><sphere x="0" y="0" z="0" r="1" material="white" /></objects>
  <lights><light x="0" y="5" z="-5" r="1e15" g="1e15" b="1e15" /></lights>
</scene>
XML
expect_exit 0 "$RT_RENDER" "$WORK/overflow.xml" "${small[@]}" --stats-json "$WORK/render_overflow.json"
grep -q '"firstNonFinitePixel": \[' "$WORK/render_overflow.json" || fail "the overflow scene had no non-finite sample"
# Each record repeats its run: rt's version, the command line, every option given or defaulted,
# and with --orbit one record per frame, which says its frame.
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -S 2 --seed 7 --orbit 2 -f "$WORK/o_#.png" -f "$WORK/o_#.exr" \
    --stats-json "$WORK/render_orbit_#.json"
version=$("$RT_RENDER" --version | awk 'NR == 1 {print $2}')
for frame in 0 1; do
    python3 - "$WORK/render_orbit_$frame.json" "$frame" "$version" <<'PY' || fail "frame $frame's record: $(cat "$WORK/render_orbit_$frame.json")"
import json, sys
d = json.load(open(sys.argv[1]))
o = d["options"]
assert d["frame"] == int(sys.argv[2]), d["frame"]
assert d["rtVersion"] == sys.argv[3], d["rtVersion"]
assert d["commandLine"][1:5] == [d["scene"]["file"], "-x", "32", "-y"], d["commandLine"]
# Typed as the options are: numbers, booleans, lists of strings, names; never a number as a string.
assert (o["supersample"], o["seed"], o["orbit"], o["width"]) == (2, 7, 2, 32), o
assert o["file"] == [sys.argv[1].rsplit("/", 1)[0] + "/o_#.png", sys.argv[1].rsplit("/", 1)[0] + "/o_#.exr"], o["file"]
assert (o["depth"], o["shadows"], o["region"], o["set"]) == (5, False, None, []), o   # defaults, a flag, nothing
assert (o["accel"], o["adaptive-threshold"], o["quiet"]) == ("kd", 0.02, True), o
assert not any(isinstance(v, str) and v.lstrip("-").replace(".", "", 1).isdigit() for v in o.values()), o
assert d["picture"]["seed"] == 7 and d["peakMemoryBytes"] > 1 << 20, d
PY
done
valid renderStats "$WORK"/render*.json

# rt-inspect: each structure, both trees with rays and depth histograms, the scene on standard input.
expect_exit 0 "$RT_INSPECT" "$scene" --tree naive --json
cp "$WORK/stdout" "$WORK/inspect_naive.json"
expect_exit 0 "$RT_INSPECT" "$scene" --tree all --rays -s -D s -r 2 -x 16 -y 12 --depth-histogram --json
cp "$WORK/stdout" "$WORK/inspect_all.json"
expect_exit 0 "$RT_INSPECT" - --tree kd --kd-max-depth 5 --json <"$WORK/two_clusters.xml"
cp "$WORK/stdout" "$WORK/inspect_stdin.json"
valid inspectReport "$WORK"/inspect_*.json
for tree in bsp kd; do
    expect_exit 0 "$RT_INSPECT" "$scene" --tree $tree --dump json -f "$WORK/dump_$tree.json"
    expect_exit 0 "$RT_INSPECT" "$scene" --tree $tree --dump json --max-depth 2 -f "$WORK/dump_${tree}_cut.json"
done
valid inspectTreeDump "$WORK"/dump_*.json

# rt-convert: a generated scene, and a model with a degenerate triangle and a point (notes).
expect_exit 0 "$RT_CONVERT" --generate ships -q --json
cp "$WORK/stdout" "$WORK/convert_ships.json"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\np 1\n' >"$WORK/model.obj"
expect_exit 0 "$RT_CONVERT" "$WORK/model.obj" -o "$WORK/model.xml" -q --json
cp "$WORK/stdout" "$WORK/convert_obj.json"
grep -q '"degenerate": 1' "$WORK/convert_obj.json" || fail "the degenerate triangle was not counted"
valid convertSummary "$WORK"/convert_*.json

# The check is strict: a wrong type, an undocumented field, a missing version, a documented
# field in the wrong document, or the old "auto" depth limit is rejected.
invalid renderStats "$WORK/render1.json" 'd["rays"]["cameraRays"] = str(d["rays"]["cameraRays"])'
invalid renderStats "$WORK/render1.json" 'd["picture"]["maxDepth"] = 5'
invalid renderStats "$WORK/render1.json" 'del d["version"]'
invalid renderStats "$WORK/render1.json" 'd["options"]["width"] = str(d["options"]["width"])'
invalid renderStats "$WORK/render1.json" 'd["options"]["file"] = "[]"'
invalid renderStats "$WORK/render1.json" 'd["trees"] = []'
invalid inspectReport "$WORK/inspect_all.json" 'd["trees"][1]["settings"]["maxDepth"] = "auto"'
invalid inspectReport "$WORK/inspect_all.json" 'd["trees"][0]["settings"]["traversalCost"] = 2'
invalid inspectTreeDump "$WORK/dump_kd_cut.json" 'd["root"]["children"][0]["leaf"] = True'
invalid convertSummary "$WORK/convert_obj.json" 'd["notes"] = "none"'
echo "json_schema: ok"
