# A progressive (path-traced) render asked to end keeps its work (docs/rt-render.md, "Interrupted
# renders"): SIGUSR1 at any time, and with --on-interrupt write the first SIGINT or SIGTERM, end it
# after the pass under way and write the passes done, atomically, the EXR's rt:samplesPerPixel
# saying how many (the bits of -S K). By default SIGINT writes nothing and leaves the old file; a
# second SIGINT, here during the write, abandons it too.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
path=(-x 32 -y 24 --integrator path --max-bounces 3 --exr-pixels float --progress lines)
samples_of() { iinfo -v "$1" | sed -n 's/.*rt:samplesPerPixel: \([0-9]*\).*/\1/p'; }
mkdir -p "$WORK/out"
"$RT_RENDER" "$scene" -q -x 32 -y 24 -f "$WORK/out/picture.exr"
cp "$WORK/out/picture.exr" "$WORK/before.exr"

# rendering: waits until the render whose standard error is $WORK/stderr has built its tree,
# and a little more (a pass takes about 15 ms).
rendering() {
    for _ in $(seq 600); do grep -q 'tree built' "$WORK/stderr" && break; sleep 0.1; done
    sleep 0.5
}

# signal_render SIGNAL STATUS OPTIONS...: starts a render of picture.exr, sends SIGNAL once it
# renders, and checks its exit status.
signal_render() {
    local signal=$1 want=$2 got=0
    shift 2
    # A background job of a script starts with SIGINT ignored; env gives it the default back.
    env --default-signal=INT "$RT_RENDER" "$scene" "${path[@]}" -S 1000000 "$@" -f "$WORK/out/picture.exr" \
        2>"$WORK/stderr" &
    local pid=$!
    rendering
    kill "-$signal" "$pid"
    wait "$pid" || got=$?
    [ "$got" = "$want" ] || fail "$signal $*: exited $got, expected $want: $(cat "$WORK/stderr")"
}

# written SIGNAL: picture.exr holds K whole passes, K in the file and on standard error, the bits of -S K.
written() {
    local k
    k=$(samples_of "$WORK/out/picture.exr")
    [ -n "$k" ] && [ "$k" -ge 1 ] && [ "$k" -lt 1000000 ] || fail "$1: rt:samplesPerPixel '$k'"
    grep -q "^rt-render: $1: ended after $k of 1000000 samples per pixel, written$" "$WORK/stderr" ||
        fail "$1: standard error does not say what was written: $(cat "$WORK/stderr")"
    "$RT_RENDER" "$scene" "${path[@]}" -q -S "$k" -f "$WORK/k.exr"
    idiff -fail 0 -warn 0 "$WORK/k.exr" "$WORK/out/picture.exr" >"$WORK/idiff.txt" ||
        fail "$1: the written picture is not the -S $k one: $(cat "$WORK/idiff.txt")"
    [ -z "$(ls -A "$WORK/out" | grep rt-tmp || true)" ] || fail "$1: temporaries left: $(ls -A "$WORK/out")"
}

# By default SIGINT and SIGTERM write nothing: the old picture stays.
for signal in INT TERM; do
    signal_render "$signal" $((128 + $(kill -l "$signal")))
    cmp -s "$WORK/out/picture.exr" "$WORK/before.exr" || fail "SIG$signal without --on-interrupt wrote the picture"
    grep -q "stopped by SIG$signal at .*; its output is not written" "$WORK/stderr" || fail "$(cat "$WORK/stderr")"
done

# SIGUSR1 needs no option, and exits 0.
signal_render USR1 0
written SIGUSR1

# --on-interrupt write: the first SIGINT or SIGTERM writes, then ends the process by that signal.
for signal in INT TERM; do
    cp "$WORK/before.exr" "$WORK/out/picture.exr"
    signal_render "$signal" $((128 + $(kill -l "$signal"))) --on-interrupt write
    grep -q "^rt-render: SIG$signal: ending after the pass under way and writing the passes done" "$WORK/stderr" ||
        fail "SIG$signal: the signal is not acknowledged: $(cat "$WORK/stderr")"
    written "SIG$signal"
done

# A second SIGINT abandons the write (held by the test hook RT_TEST_WRITE_DELAY_MS, os/atomic_file.h).
cp "$WORK/before.exr" "$WORK/out/picture.exr"
RT_TEST_WRITE_DELAY_MS=60000 env --default-signal=INT "$RT_RENDER" "$scene" "${path[@]}" -S 1000000 --on-interrupt write \
    -f "$WORK/out/picture.exr" 2>"$WORK/stderr" &
pid=$!
rendering
kill -INT "$pid"
wait_for_temporary "$WORK/out" '^\.picture\.rt-tmp-' >/dev/null
kill -INT "$pid"
got=0
wait "$pid" || got=$?
[ "$got" = 130 ] || fail "a second SIGINT: exited $got, expected 130: $(cat "$WORK/stderr")"
cmp -s "$WORK/out/picture.exr" "$WORK/before.exr" || fail "a second SIGINT still wrote the picture"
[ -z "$(ls -A "$WORK/out" | grep rt-tmp || true)" ] || fail "a second SIGINT left: $(ls -A "$WORK/out")"

expect_exit 2 "$RT_RENDER" "$scene" -o null --on-interrupt keep
echo "render_interrupt_write: ok"
