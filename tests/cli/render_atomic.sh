# A failed or killed render leaves an existing output untouched and no partial file.
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

# A failure found before rendering (bad view) and one found while writing (unwritable folder).
expect_exit 2 "$RT_RENDER" "$scene" -q -x 64 -y 48 --view NoSuchView -f "$out"
unchanged "bad view"
expect_exit 1 "$RT_RENDER" "$scene" -q -x 64 -y 48 -f "$WORK/missing/dir/picture.png"
grep -q "cannot write\|No such file\|Could not open" "$WORK/stderr" || fail "no clear message: $(cat "$WORK/stderr")"

# Killed in the middle of a long render.
"$RT_RENDER" "$scene" -q -x 2000 -y 1500 -s -S 64 -D b -f "$out" &
pid=$!
sleep 1
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
unchanged "killed render"
echo "render_atomic: ok"
