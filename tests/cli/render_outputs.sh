# rt-render checks its outputs before any work (docs/rt-render.md, "Output and colour"):
# missing folders are created, an output that cannot be written, -o and -f that disagree
# and two outputs on standard output are usage errors (exit 2) naming what the user gave.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
small=(-K -q -x 32 -y 24)
# A render that takes minutes: a check that comes after it times out instead of exiting 2.
huge=(-K -q -x 4000 -y 3000 -S 64 -s -d 10)
before_work() { expect_exit 2 timeout 60 "$RT_RENDER" "$scene" "${huge[@]}" "$@"; }
names() { grep -qF -- "$1" "$WORK/stderr" || fail "the message does not name '$1': $(cat "$WORK/stderr")"; }

# Missing parent folders are created (for the image and for --stats-json).
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -f "$WORK/new/dir/demo.png" --stats-json "$WORK/json/s.json"
[ -s "$WORK/new/dir/demo.png" ] && [ -s "$WORK/json/s.json" ] || fail "no file in the new folders"
[ "$(ls -A "$WORK/new/dir")" = demo.png ] || fail "left behind: $(ls -A "$WORK/new/dir")"

# Outputs that cannot be written, found before rendering.
mkdir "$WORK/folder"
before_work -f "$WORK/folder"
names "$WORK/folder: is a directory"
touch "$WORK/plain"
before_work -f "$WORK/plain/x.png"
names "$WORK/plain/x.png"
before_work -f "$WORK/picture.bmp"
names "$WORK/picture.bmp"
before_work -f "$WORK/picture.png" --stats-json "$WORK/folder"
names "$WORK/folder: is a directory"
if [ "$(id -u)" != 0 ]; then  # root writes into read-only folders
    mkdir "$WORK/readonly" && chmod a-w "$WORK/readonly"
    before_work -f "$WORK/readonly/x.png"
    names "$WORK/readonly/x.png"
fi

# -o and -f: the extension picks the format unless -o names one; a contradiction is an error.
before_work -o png -f "$WORK/m.exr"
names "-o png"
before_work -o exr -f "$WORK/m.png"
before_work -o null -f "$WORK/m.png"
[ ! -e "$WORK/m.exr" ] && [ ! -e "$WORK/m.png" ] || fail "a contradictory command wrote a file"
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}" -o exr -f "$WORK/no-extension"
iinfo "$WORK/no-extension" | grep -q "openexr" || fail "-o exr did not write EXR: $(iinfo "$WORK/no-extension")"

# One output per standard output.
before_work -o png -f - --stats-json -
names "standard output"
before_work -o png -f - -b
before_work -o text -b

# Neither -f nor -o: null output, and stderr says so (unless -q).
expect_exit 0 "$RT_RENDER" "$scene" -K -x 32 -y 24
grep -q "nothing written.*-f out.png" "$WORK/stderr" || fail "no note that nothing was written: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_RENDER" "$scene" "${small[@]}"
[ ! -s "$WORK/stderr" ] || fail "-q still wrote: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_RENDER" "$scene" -K -x 32 -y 24 -o null
if grep -q "nothing written" "$WORK/stderr"; then fail "-o null asked for nothing, yet was told"; fi

# Messages: a folder given as the scene; one thread.
expect_exit 2 "$RT_RENDER" "$WORK/folder/"
names "is a directory"
expect_exit 0 "$RT_RENDER" "$scene" -K -x 32 -y 24 -o null --threads 1
grep -q " on 1 thread:" "$WORK/stderr" || fail "not singular: $(cat "$WORK/stderr")"
echo "render_outputs: ok"
