# Outputs that are not regular files are written in place, never replaced by a regular file:
# a full device node reports the error (exit 1), a null device stays a device, and text written
# to a FIFO reaches its reader. Device nodes are made in a scratch folder, which needs root.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"

# A FIFO (any user): rt-render's text and rt-inspect's JSON dump reach the reader.
mkfifo "$WORK/fifo"
for command in "$RT_RENDER $scene -q -x 16 -y 12 -o text -f $WORK/fifo" \
               "$RT_INSPECT $scene --dump json -f $WORK/fifo"; do
    timeout 20 cat "$WORK/fifo" >"$WORK/read" &  # a bounded wait: a replaced FIFO has no writer
    reader=$!
    expect_exit 0 $command
    wait "$reader" || true
    [ -s "$WORK/read" ] || fail "'$command': the FIFO's reader got nothing"
    [ -p "$WORK/fifo" ] || fail "'$command' replaced the FIFO"
done
[ "$(ls -A "$WORK" | grep -c rt-tmp)" = 0 ] || fail "temporaries left: $(ls -A "$WORK")"

if [ "$(id -u)" != 0 ] || ! mknod "$WORK/full" c 1 7 2>/dev/null; then
    echo "SKIP (devices): making device nodes needs root"; echo "output_special_files: ok"; exit 0
fi
mknod "$WORK/null" c 1 3
for option in "-o text -f" "--stats-json"; do
    expect_exit 1 "$RT_RENDER" "$scene" -q -x 16 -y 12 $option "$WORK/full"
    grep -q "ERROR: $WORK/full: cannot write: No space left on device" "$WORK/stderr" || fail "$(cat "$WORK/stderr")"
    expect_exit 0 "$RT_RENDER" "$scene" -q -x 16 -y 12 $option "$WORK/null"
done
expect_exit 1 "$RT_INSPECT" "$scene" --dump json -f "$WORK/full"
expect_exit 1 "$RT_RENDER" "$scene" -q -x 16 -y 12 -f "$WORK/full" -o png
[ -c "$WORK/full" ] && [ -c "$WORK/null" ] || fail "a device node was replaced: $(ls -l "$WORK")"
[ "$(ls -A "$WORK" | grep -c rt-tmp)" = 0 ] || fail "temporaries left: $(ls -A "$WORK")"
echo "output_special_files: ok"
