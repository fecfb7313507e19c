# A failed or killed render leaves an existing output untouched and no partial file; a
# temporary left by a process killed mid-write is removed by the next write of that output.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
out="$WORK/out/picture.png"
mkdir -p "$WORK/out"
"$RT_RENDER" "$scene" -q -x 64 -y 48 -f "$out"
cp "$out" "$WORK/before.png"
unchanged() {
    cmp -s "$out" "$WORK/before.png" || fail "$1: the previous output changed"
    [ "$(ls -A "$WORK/out")" = "picture.png" ] || fail "$1: left behind: $(ls -A "$WORK/out")"
}

# A failure found before rendering (bad view).
expect_exit 2 "$RT_RENDER" "$scene" -q -x 64 -y 48 --view NoSuchView -f "$out"
unchanged "bad view"

# Killed in the middle of a long render.
"$RT_RENDER" "$scene" -q -x 2000 -y 1500 -s -S 64 -D b -f "$out" &
pid=$!
sleep 1
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
unchanged "killed render"

# Killed while the file is being written: the test hook RT_TEST_WRITE_DELAY_MS (os/atomic_file.h)
# holds the written temporary before its rename, long enough to kill the process then.
RT_TEST_WRITE_DELAY_MS=60000 "$RT_RENDER" "$scene" -q -x 64 -y 48 -d 1 -f "$out" &
pid=$!
temporary=$(wait_for_temporary "$WORK/out" '^\.picture\.rt-tmp-')
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
cmp -s "$out" "$WORK/before.png" || fail "killed write: the previous output changed"
[ -e "$WORK/out/$temporary" ] || fail "SIGKILL removed the temporary: this test no longer tests the cleanup"

# The next run writing the same output removes the dead process's temporary, and keeps
# a temporary whose process still runs (this shell's).
touch "$WORK/out/.picture.rt-tmp-$$-0.png"
expect_exit 0 "$RT_RENDER" "$scene" -q -x 64 -y 48 -f "$out"
[ ! -e "$WORK/out/$temporary" ] || fail "the stale temporary $temporary is still there"
[ -e "$WORK/out/.picture.rt-tmp-$$-0.png" ] || fail "a running process's temporary was removed"
echo "render_atomic: ok"
