# rt-inspect fails like rt-render: 2 for bad usage or input, 1 for runtime failures, one
# "rt-inspect ERROR:" line on stderr, and no partial output files.
source "$(dirname "$0")/common.bash"
source "$(dirname "$0")/inspect_scenes.bash"

# expect_error CODE ARGS...: rt-inspect ARGS exits with CODE and says why on stderr.
expect_error() {
    local code=$1; shift
    expect_exit "$code" "$RT_INSPECT" "$@"
    [ -s "$WORK/stderr" ] || fail "no message for: $*"
    [ ! -s "$WORK/stdout" ] || [ "$code" = 2 ] || fail "output on stdout despite failing: $*"
}

expect_error 2 --tree nosuch "$WORK/one_sphere.xml"
expect_error 2 --dump svg "$WORK/one_sphere.xml"
expect_error 2 --leaves some "$WORK/one_sphere.xml"
expect_error 2 -x 0 --rays "$WORK/one_sphere.xml"
expect_error 2 -d 11 --rays "$WORK/one_sphere.xml"
expect_error 2 --kd-split fastest "$WORK/one_sphere.xml"
expect_error 2 --heatmap-scale cubic "$WORK/one_sphere.xml"
expect_error 2                                    # no scene
expect_error 2 "$WORK/no_such_scene.xml"
grep -q "^rt-inspect ERROR: .*no_such_scene.xml" "$WORK/stderr" || fail "missing file not named: $(cat "$WORK/stderr")"

printf '<?xml version="1.0" ?>\n<scene>\n  <objects>\n    <sphere x="0" y="0" z="1" r="oops" />\n' >"$WORK/broken.xml"
expect_error 2 "$WORK/broken.xml"
grep -q "^rt-inspect ERROR: .*broken.xml" "$WORK/stderr" || fail "broken scene not named: $(cat "$WORK/stderr")"

# Options that cannot go together.
expect_error 2 --tree all --dump dot "$WORK/one_sphere.xml"
grep -q "ERROR: --dump with several trees" "$WORK/stderr" || fail "unclear message: $(cat "$WORK/stderr")"
expect_error 2 --heatmap - "$WORK/one_sphere.xml"

# A camera that looks nowhere is bad input once rays are traced.
sed 's|<destination x="0" y="0" z="20" />|<destination x="0" y="0" z="0" />|' "$WORK/one_sphere.xml" >"$WORK/blind.xml"
expect_error 2 --rays "$WORK/blind.xml"
grep -q "camera" "$WORK/stderr" || fail "camera error not explained: $(cat "$WORK/stderr")"

# An output that cannot be written is bad usage, as in rt-render and rt-convert, found before the
# scene is read (tools_unwritable_output.sh), and leaves nothing behind; missing folders are made.
touch "$WORK/file"
expect_error 2 --dump-leaves "$WORK/file/dir/leaves.obj" "$WORK/one_sphere.xml"
expect_error 2 --heatmap "$WORK/file/dir/heat.png" -x 40 -y 30 "$WORK/one_sphere.xml"
expect_exit 0 "$RT_INSPECT" --dump-leaves "$WORK/new/dir/leaves.obj" "$WORK/one_sphere.xml"
[ -s "$WORK/new/dir/leaves.obj" ] || fail "--dump-leaves into a missing folder wrote nothing"
echo "old" >"$WORK/keep.obj"
chmod a-w "$WORK"
if [ ! -w "$WORK" ]; then  # root can write anyway; then this part says nothing
    expect_error 2 --dump-leaves "$WORK/keep.obj" "$WORK/one_sphere.xml"
    [ "$(cat "$WORK/keep.obj")" = "old" ] || fail "a failed write changed the old file"
fi
chmod u+w "$WORK"
[ -z "$(find "$WORK" -name '*.rt-tmp-*')" ] || fail "temporary files left behind"
echo "inspect_errors: ok"
