# Everything the tools print on standard output is checked: the -b line, rt-inspect's table
# and JSON, rt-convert --json and rt-render's text output written to a full device (/dev/full)
# exit 1 with one error line, never 0.
source "$(dirname "$0")/common.bash"
[ -c /dev/full ] || { echo "SKIP: no /dev/full on this machine"; exit 77; }
scene="$RT_SOURCE_DIR/scenes/demo.xml"
raw="$RT_SOURCE_DIR/scenes/models/octahedron.raw"

# to_full TOOL ARGS...: runs the tool with standard output on /dev/full; exit 1, one error line.
to_full() {
    local got=0
    "$@" >/dev/full 2>"$WORK/stderr" || got=$?
    [ "$got" = 1 ] || { cat "$WORK/stderr" >&2; fail "'$*' >/dev/full exited $got, expected 1"; }
    [ "$(grep -c ' ERROR: ' "$WORK/stderr")" = 1 ] || fail "'$*': not one error line: $(cat "$WORK/stderr")"
    grep -q "ERROR: .*standard output" "$WORK/stderr" || fail "'$*': $(cat "$WORK/stderr")"
}
to_full "$RT_RENDER" "$scene" -q -x 16 -y 12 -b
to_full "$RT_RENDER" "$scene" -q -x 16 -y 12 -o text -f -
to_full "$RT_RENDER" "$scene" -q -x 16 -y 12 --stats-json -
to_full "$RT_INSPECT" "$scene"
to_full "$RT_INSPECT" "$scene" --json
to_full "$RT_CONVERT" "$raw" --json
to_full "$RT_CONVERT" "$raw" -o -
echo "output_full_device: ok"
