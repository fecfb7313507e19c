# rt-render keeps no texture cache (docs/rt-render.md, "Textures"): textures are read into memory
# as MIP maps. The old cache's options (--tx-cache, --tx-cache-size, --texture-cache) are
# accepted and each noted once as ignored; $RT_TX_CACHE is ignored. No file is written or removed
# anywhere: not in a --tx-cache folder holding a user's maketx output and a text file named
# project.tx (the cache once removed both, issue 41), nor in $XDG_CACHE_HOME or $HOME. A different
# picture of the same size and modification time (unpacked from an archive, touch -r) renders as
# itself: nothing of an earlier render is reused.
source "$(dirname "$0")/common.bash"
oiiotool --pattern checker:width=4:height=4 16x16 3 -d uint8 -o "$WORK/checker.png"
printf 'newmtl m\nKd 1 1 1\nmap_Kd checker.png\n' >"$WORK/square.mtl"
printf 'mtllib square.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' \
    >"$WORK/square.obj"
export HOME="$WORK/home" XDG_CACHE_HOME="$WORK/xdg"
mkdir -p "$HOME" "$XDG_CACHE_HOME"
# render NAME OPTION...: the scene to NAME.png; exit 0 required.
render() {
    local name=$1
    shift
    "$RT_RENDER" "$WORK/square.obj" --look-from 0,0,3 --look-at 0,0,0 --fov 60 -x 40 -y 30 -f "$WORK/$name.png" --progress none "$@" 2>"$WORK/stderr" ||
        fail "exit $?: $(cat "$WORK/stderr")"
}
# The files under a folder with their sizes, times and checksums.
listing() { (cd "$1" && find . -type f -printf '%p %s %T@\n' -exec md5sum {} + | sort); }

mkdir "$WORK/user"
oiiotool --pattern checker 64x64 3 -d uint8 -otex "$WORK/user/theirs.tx"
printf 'notes, not a texture\n' >"$WORK/user/project.tx"
before=$(listing "$WORK/user")
render plain
RT_TX_CACHE="$WORK/user" render cached --tx-cache "$WORK/user" --tx-cache-size 1 --texture-cache 32
for option in --tx-cache --tx-cache-size --texture-cache; do
    [ "$(grep -c "^rt-render: note: $option is no longer used: textures are read into memory, no copies are made: ignored$" "$WORK/stderr")" = 1 ] ||
        fail "$option: expected one note, got: $(cat "$WORK/stderr")"
done
[ "$(grep -c "note:" "$WORK/stderr")" = 3 ] || fail "expected the three notes alone: $(cat "$WORK/stderr")"
render quiet --tx-cache "$WORK/user" -q
[ ! -s "$WORK/stderr" ] || fail "-q: $(cat "$WORK/stderr")"
[ "$(listing "$WORK/user")" = "$before" ] || fail "the --tx-cache folder changed: $(ls -AlR "$WORK/user")"
[ -z "$(find "$HOME" "$XDG_CACHE_HOME" -mindepth 1)" ] || fail "files written: $(find "$HOME" "$XDG_CACHE_HOME")"
for name in cached quiet; do
    idiff -fail 0 "$WORK/plain.png" "$WORK/$name.png" >/dev/null || fail "$name.png differs from plain.png"
done

# Another picture of the same size and modification time renders as itself.
oiiotool --pattern constant:color=1,0,0 16x16 3 -d uint8 -o "$WORK/red.png"
oiiotool --pattern constant:color=0,0,1 16x16 3 -d uint8 -o "$WORK/blue.png"
python3 - "$WORK/red.png" "$WORK/blue.png" <<'PY'
import sys  # the same size: the shorter is padded after its IEND chunk, which readers ignore
a, b = (open(p, "rb").read() for p in sys.argv[1:])
n = max(len(a), len(b))
for p, data in zip(sys.argv[1:], (a, b)):
    open(p, "wb").write(data + bytes(n - len(data)))
PY
sed 's/checker.png/picture.png/' "$WORK/square.mtl" >"$WORK/picture.mtl"
sed 's/square.mtl/picture.mtl/' "$WORK/square.obj" >"$WORK/picture.obj"
sed 's/checker.png/blue.png/' "$WORK/square.mtl" >"$WORK/blue.mtl"
sed 's/square.mtl/blue.mtl/' "$WORK/square.obj" >"$WORK/blue.obj"
cp -p "$WORK/red.png" "$WORK/picture.png"
expect_exit 0 "$RT_RENDER" "$WORK/picture.obj" -x 40 -y 30 -f "$WORK/red-render.png" -q
cp "$WORK/blue.png" "$WORK/picture.png"
touch -r "$WORK/red.png" "$WORK/picture.png"
expect_exit 0 "$RT_RENDER" "$WORK/picture.obj" -x 40 -y 30 -f "$WORK/picture-render.png" -q
expect_exit 0 "$RT_RENDER" "$WORK/blue.obj" -x 40 -y 30 -f "$WORK/blue-render.png" -q
idiff -fail 0 "$WORK/blue-render.png" "$WORK/picture-render.png" >/dev/null || fail "the old picture was used"
echo "render_tx_cache: ok"
