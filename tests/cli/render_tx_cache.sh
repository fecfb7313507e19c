# rt-render's tx cache (docs/rt-render.md, "Texture copies"): a PNG texture is read through a
# tiled, MIP-mapped copy made once in --tx-cache, else $RT_TX_CACHE; "off" makes none; a folder
# that cannot be made is one warning and the same picture.
source "$(dirname "$0")/common.bash"
oiiotool --pattern checker:width=4:height=4 16x16 3 -d uint8 -o "$WORK/checker.png"
printf 'newmtl m\nKd 1 1 1\nmap_Kd checker.png\n' >"$WORK/square.mtl"
printf 'mtllib square.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' \
    >"$WORK/square.obj"
# render NAME OPTION...: the scene to NAME.png; exit 0 required.
render() {
    local name=$1
    shift
    "$RT_RENDER" "$WORK/square.obj" --look-from 0,0,3 --look-at 0,0,0 --fov 60 -x 40 -y 30 -f "$WORK/$name.png" --progress none "$@" 2>"$WORK/stderr" ||
        fail "exit $?: $(cat "$WORK/stderr")"
}
copies() { find "$1" -name '*.tx' 2>/dev/null | wc -l; }

render plain --tx-cache off
[ ! -e "$WORK/tx" ] || fail "--tx-cache off made a folder"
render first --tx-cache "$WORK/tx"
[ "$(copies "$WORK/tx")" = 1 ] || fail "expected one copy in $WORK/tx: $(ls -a "$WORK/tx")"
copy=$(find "$WORK/tx" -name '*.tx')
touch -d '2000-01-01' "$copy"
render again --tx-cache "$WORK/tx"
[ "$(stat -c %Y "$copy")" = "$(date -d 2000-01-01 +%s)" ] || fail "the copy was made again"
RT_TX_CACHE="$WORK/env" render fromEnv
[ "$(copies "$WORK/env")" = 1 ] || fail "\$RT_TX_CACHE: no copy in $WORK/env"
render fallback --tx-cache "$WORK/checker.png/tx"
grep -q "warning: texture 'checker': no tiled copy (.*): textures are read as they are" "$WORK/stderr" ||
    fail "no fallback warning: $(cat "$WORK/stderr")"
for name in first again fromEnv fallback; do
    idiff -fail 0.004 "$WORK/plain.png" "$WORK/$name.png" >/dev/null || fail "$name.png differs from plain.png"
done
echo "render_tx_cache: ok"
