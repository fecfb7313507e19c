# An output that cannot be written (its folder cannot be made: a file is in the way) is bad
# usage, exit 2 with one line naming the path, in every tool, found before the scene or model
# is read (docs/rt-render.md, "Exit codes"); a failure while writing (a full disk) stays exit 1.
source "$(dirname "$0")/common.bash"
SCENE="$RT_SOURCE_DIR/scenes/demo.xml"
touch "$WORK/file"
blocked="$WORK/file/sub"  # under a file: no folder can be made there, whoever runs the test

expect_exit 2 "$RT_RENDER" "$SCENE" -q -x 8 -y 6 -f "$blocked/out.png"
expect_one_error rt-render "$blocked/out.png: cannot create the folder"
expect_exit 2 "$RT_CONVERT" --generate ships -q -o "$blocked/ships.xml"
expect_one_error rt-convert "$blocked/ships.xml: cannot create the folder"
expect_exit 2 "$RT_INSPECT" "$SCENE" --dump json -f "$blocked/tree.json"
expect_one_error rt-inspect "$blocked/tree.json: cannot create the folder"
expect_exit 2 "$RT_INSPECT" "$SCENE" --heatmap "$blocked/heat.png" -x 8 -y 6
expect_one_error rt-inspect "$blocked/heat.png: cannot create the folder"
expect_exit 2 "$RT_INSPECT" "$SCENE" --dump-leaves "$blocked/leaves.obj"
expect_one_error rt-inspect "$blocked/leaves.obj: cannot create the folder"
# Nothing was read first: a missing model with an unwritable output names the output.
expect_exit 2 "$RT_CONVERT" "$WORK/missing.obj" -o "$blocked/m.xml"
expect_one_error rt-convert "$blocked/m.xml: cannot create the folder"
echo "tools_unwritable_output: ok"
