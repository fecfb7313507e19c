# SIGINT and SIGTERM in the middle of a write remove the temporary (a file for rt-render, a file
# and a folder of RAW models for rt-convert), leave the previous output as it was, and end the
# process by that signal (exit status 128+N). The test hook RT_TEST_WRITE_DELAY_MS
# (os/atomic_file.h) holds the written temporaries before their rename, so the kill lands there.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
mkdir -p "$WORK/out"

# interrupt SIGNAL PATTERN COMMAND...: starts COMMAND, waits for a temporary matching PATTERN
# in $WORK/out, sends SIGNAL, and checks the exit status and that no temporary is left.
interrupt() {
    local signal=$1 pattern=$2; shift 2
    # A background job of a script starts with SIGINT ignored; env gives it the default back.
    RT_TEST_WRITE_DELAY_MS=60000 env --default-signal=INT "$@" 2>"$WORK/stderr" &
    local pid=$! got=0
    wait_for_temporary "$WORK/out" "$pattern" >/dev/null
    kill "-$signal" "$pid"
    wait "$pid" || got=$?
    [ "$got" = $((128 + $(kill -l "$signal"))) ] || fail "$signal: exited $got, expected 128+SIG$signal"
    [ -z "$(ls -A "$WORK/out" | grep rt-tmp)" ] || fail "$signal: left behind: $(ls -A "$WORK/out")"
}

"$RT_RENDER" "$scene" -q -x 64 -y 48 -f "$WORK/out/picture.png"
cp "$WORK/out/picture.png" "$WORK/before.png"
for signal in INT TERM; do
    interrupt "$signal" '^\.picture\.rt-tmp-' "$RT_RENDER" "$scene" -q -x 64 -y 48 -d 1 -f "$WORK/out/picture.png"
    cmp -s "$WORK/out/picture.png" "$WORK/before.png" || fail "$signal: the previous picture changed"
done

# SIGTERM during the render (a farm's pre-emption or time limit): the log says where it stopped
# and no file is written. 64 samples a pixel make the render last about 2 s on one thread, so the
# signal sent after the first progress line (polled every 0.1 s) lands well before its end.
"$RT_RENDER" "$scene" -s -x 320 -y 240 -S 64 --threads 1 --progress lines -f "$WORK/out/stopped.exr" \
    2>"$WORK/stderr" &
pid=$!
for _ in $(seq 600); do grep -q '% of' "$WORK/stderr" && break; sleep 0.1; done  # rendering now
kill -TERM "$pid"
got=0
wait "$pid" || got=$?
[ "$got" = 143 ] || fail "SIGTERM during the render: exited $got, expected 143 ($(cat "$WORK/stderr"))"
grep -Eq '^rt-render: stopped by SIGTERM at [0-9]+ of 4915200 samples \([0-9]+%\); its output is not written$' \
    "$WORK/stderr" || fail "the log does not say where the render stopped: $(cat "$WORK/stderr")"
[ -z "$(ls -A "$WORK/out" | grep stopped)" ] || fail "a stopped render wrote: $(ls -A "$WORK/out")"

raw="$RT_SOURCE_DIR/scenes/models/octahedron.raw"
"$RT_CONVERT" "$raw" -o "$WORK/out/scene.xml" 2>/dev/null
snapshot() { (cd "$WORK/out" && find scene.xml scene -type f -print0 | sort -z | xargs -0 md5sum); }
before=$(snapshot)
for signal in INT TERM; do
    interrupt "$signal" '^\.scene\.rt-tmp-' "$RT_CONVERT" "$RT_SOURCE_DIR/scenes/models/atom.raw" -o "$WORK/out/scene.xml"
    [ "$(snapshot)" = "$before" ] || fail "$signal: the previous scene changed"
done
echo "output_signals: ok"
