# Each tool's --help starts with its one-line purpose and then three to five example command
# lines, as oiiotool's and pbrt's do; every option an example uses is one of the tool's, and
# every example runs when its files exist (here: made in a scratch folder). rt-inspect's help
# says it reads models as well as XML scenes. --spp is rt-render's -S (issue 36, items 9 and 13).
source "$(dirname "$0")/common.bash"
need_shared_models
scene="$RT_SOURCE_DIR/scenes/demo.xml"
# The examples call the tools by name.
for tool in "$RT_RENDER" "$RT_CONVERT" "$RT_INSPECT"; do PATH="$(dirname "$(realpath "$tool")"):$PATH"; done
# The files the examples name, in a scratch folder where they run.
cp "$RT_SHARED_DIR/models/glb/BoxTextured/BoxTextured.glb" "$WORK/model.glb"
cp -r "$RT_SOURCE_DIR/scenes" "$WORK/scenes"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$WORK/model.obj"
cp "$RT_SOURCE_DIR/scenes/demo.xml" "$WORK/scene.xml"
cp "$RT_SHARED_DIR/models/3ds/fels/fels.3ds" "$WORK/room.3ds"

for tool in "$RT_RENDER" "$RT_CONVERT" "$RT_INSPECT"; do
    name=$(basename "$tool")
    expect_exit 0 "$tool" --help
    # The lines between "Examples:" and the next blank or unindented line, before "Usage".
    awk '/^Usage/ {exit} /^Examples:/ {on = 1; next} on && /^  / {print; next} on {exit}' "$WORK/stdout" \
        >"$WORK/examples"
    count=$(wc -l <"$WORK/examples")
    [ "$count" -ge 3 ] && [ "$count" -le 5 ] || fail "$name --help: $count examples before Usage: $(cat "$WORK/stdout")"
    grep -vq "$name " "$WORK/examples" && fail "$name --help: an example that does not run $name: $(cat "$WORK/examples")"
    while read -r example; do
        for word in $example; do
            [[ "$word" == -?* ]] || continue
            option=${word%%=*}
            grep -q -- "$option[, =]" "$WORK/stdout" || fail "$name --help: the example '$example' uses $option, not an option"
        done
        # Run it without its comment (two spaces or more after the command), quietly and small.
        command=$(sed -E 's/  +[A-Za-z].*$//; s/^ +//' <<<"$example")
        # Small pictures, so that the examples run in a second or two.
        command=${command/--spp 64/--spp 2}
        command=${command/-x 1280 -y 720/-x 32 -y 18}
        command=${command/-x 320 -y 240/-x 32 -y 24}
        [[ "$command" == rt-render* && "$command" != *" -x "* ]] && command="$command -x 16 -y 12"
        (cd "$WORK" && eval "$command" >"$WORK/out" 2>"$WORK/err" </dev/null) ||
            fail "$name --help: the example '$command' failed: $(cat "$WORK/err")"
    done <"$WORK/examples"
done
# rt-farm's too, before its usage; its options are rt-render's and its own.
farm="$RT_SOURCE_DIR/tools/farm/rt-farm"
expect_exit 0 "$farm" --help
count=$(awk '/^Usage/ {exit} /^Examples:/ {on = 1; next} on && /^  rt-farm / {n++} END {print n + 0}' "$WORK/stdout")
[ "$count" -ge 3 ] && [ "$count" -le 5 ] || fail "rt-farm --help: $count examples before Usage: $(cat "$WORK/stdout")"

expect_exit 0 "$RT_INSPECT" --help
grep -q "scene TEXT REQUIRED *Scene: rt XML (- reads standard input) or any model rt-convert reads" "$WORK/stdout" ||
    fail "rt-inspect --help does not say that it reads models: $(grep -i scene "$WORK/stdout")"

# --spp N is -S N: the same bits, and the record names the option by its long name.
expect_exit 0 "$RT_RENDER" "$scene" -q -x 32 -y 24 -S 3 -f "$WORK/S.exr"
expect_exit 0 "$RT_RENDER" "$scene" -q -x 32 -y 24 --spp 3 -f "$WORK/spp.exr" --stats-json "$WORK/spp.json"
idiff -fail 0 -warn 0 "$WORK/S.exr" "$WORK/spp.exr" >/dev/null || fail "--spp 3 and -S 3 rendered different pictures"
grep -q '"supersample": 3' "$WORK/spp.json" || fail "--spp 3 is not recorded as supersample 3"
echo "tools_help: ok"
