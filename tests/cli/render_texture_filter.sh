# rt-render --texture-filter nearest|bilinear|trilinear|anisotropic (docs/rt-render.md, "Textures"):
# a fine checker floor seen towards the horizon, where many texels fall in a pixel, shimmers most
# when point-sampled (nearest), less with four texels (bilinear), least with the MIP map; the
# anisotropic filter keeps more of the floor's near detail than trilinear, which blurs along the
# footprint's shorter side too. Any other name is a usage error. Reading the textures is said on stderr, not with -q.
source "$(dirname "$0")/common.bash"
oiiotool --pattern checker:width=1:height=1 256x256 3 -d uint8 -o "$WORK/checker.png"
printf 'newmtl m\nKa 0 0 0\nKd 0 0 0\nKe 1 1 1\nmap_Ke checker.png\n' >"$WORK/floor.mtl"
printf 'mtllib floor.mtl\nv -50 0 10\nv 50 0 10\nv 50 0 -200\nv -50 0 -200\nvt 0 0\nvt 10 0\nvt 10 20\nvt 0 20\nusemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' \
    >"$WORK/floor.obj"
# render FILTER: the floor, one sample a pixel, to FILTER.png; prints the standard deviation of
# its green channel, the shimmer.
render() {
    expect_exit 0 "$RT_RENDER" "$WORK/floor.obj" --look-from 0,1,2 --look-at 0,0.4,-10 --fov 60 -x 96 -y 64 \
        --texture-filter "$1" -f "$WORK/$1.png" --progress lines
    python3 - "$WORK/$1.png" <<'PY'
import subprocess, sys
out = subprocess.run(["oiiotool", "--stats", sys.argv[1]], capture_output=True, text=True).stdout
print([l for l in out.splitlines() if "Stats StdDev" in l][0].split()[3])
PY
}
nearest=$(render nearest)
grep -q "^rt-render: reading 1 texture picture (.* MB with MIP levels)" "$WORK/stderr" ||
    fail "no line saying the textures are read: $(cat "$WORK/stderr")"
bilinear=$(render bilinear)
trilinear=$(render trilinear)
anisotropic=$(render anisotropic)
awk -v n="$nearest" -v b="$bilinear" -v t="$trilinear" -v a="$anisotropic" 'BEGIN {
    if (!(b < n && a < b && t < a)) { printf "shimmer: nearest %s bilinear %s trilinear %s anisotropic %s\n", n, b, t, a; exit 1 } }' ||
    fail "the MIP map does not filter the distant checker"
cmp -s "$WORK/trilinear.png" "$WORK/anisotropic.png" && fail "anisotropic renders as trilinear"
expect_exit 0 "$RT_RENDER" "$WORK/floor.obj" -x 16 -y 12 -o null -q
[ ! -s "$WORK/stderr" ] || fail "-q: $(cat "$WORK/stderr")"
expect_exit 2 "$RT_RENDER" "$WORK/floor.obj" --texture-filter box -o null
expect_one_error rt-render "--texture-filter: box not in {nearest,bilinear,trilinear,anisotropic}"
echo "render_texture_filter: ok"
