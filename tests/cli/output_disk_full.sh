# A full disk never costs the user the previous output: PNG, TGA and rt-inspect --heatmap written
# into a full file system (a 64 KiB tmpfs), or one with a little space left, exit 1 with the
# reason and leave the old file byte for byte and no temporary. Needs root to mount the tmpfs.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
disk="$WORK/disk"
mkdir -p "$disk"
if [ "$(id -u)" != 0 ] || ! mount -t tmpfs -o size=64k rt-test "$disk" 2>/dev/null; then
    echo "SKIP: mounting a small tmpfs needs root (and permission to mount)"; exit 77
fi
trap 'umount "$disk"; rm -rf "$WORK"' EXIT

# fill KIB: takes all the free space but KIB KiB (a filler file the test can remove).
fill() {
    rm -f "$disk/filler"
    dd if=/dev/zero of="$disk/filler" bs=1k 2>/dev/null || true
    [ "$1" = 0 ] || truncate -s "-$1K" "$disk/filler"
}

# check_full NAME COMMAND...: COMMAND writes $disk/NAME; with the disk full it must fail and keep it.
check_full() {
    local name=$1; shift
    rm -f "$disk/filler"
    expect_exit 0 "$@"
    cp "$disk/$name" "$WORK/before"
    for left in 0 4; do
        fill "$left"
        expect_exit 1 "$@"
        grep -q "ERROR: $disk/$name: cannot write.*\(No space left on device\|bytes reached the disk\)" "$WORK/stderr" ||
            fail "$name with ${left} KiB left: $(cat "$WORK/stderr")"
        cmp -s "$disk/$name" "$WORK/before" || fail "$name with ${left} KiB left: the previous output changed"
        [ "$(ls -A "$disk" | grep -v '^filler$')" = "$name" ] || fail "$name: left behind: $(ls -A "$disk")"
    done
    rm -f "$disk/$name"
}
check_full picture.png "$RT_RENDER" "$scene" -q -x 96 -y 72 -f "$disk/picture.png"
check_full picture.tga "$RT_RENDER" "$scene" -q -x 96 -y 72 -f "$disk/picture.tga"
check_full picture.exr "$RT_RENDER" "$scene" -q -x 96 -y 72 -f "$disk/picture.exr"
check_full heat.png "$RT_INSPECT" "$scene" -x 320 -y 240 --heatmap "$disk/heat.png"
echo "output_disk_full: ok"
