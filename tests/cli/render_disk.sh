# A <disk> (docs/scene-format.md) renders: seen from the front and from the back (two-sided) it
# covers the centre pixel in its material's colour, and edge-on it is not there (no thickness).
source "$(dirname "$0")/common.bash"

cat >"$WORK/disk.xml" <<'XML'
<scene>
  <background r="0" g="0" b="0" />
  <camera fov="30"><origin x="0" y="0" z="4" /><destination x="0" y="0" z="0" /></camera>
  <materials><material name="red" r="1" g="0" b="0" ambient="0.5" diffuse="0.5" /></materials>
  <objects><disk x="0" y="0" z="0" nx="0" ny="0" nz="1" r="1" material="red" /></objects>
  <lights><light x="0" y="3" z="4" /><light x="0" y="3" z="-4" /></lights>
</scene>
XML

# The red of the centre pixel seen from $1 (x,y,z).
red() {
    "$RT_RENDER" "$WORK/disk.xml" -x 1 -y 1 --look-from "$1" --look-at 0,0,0 --alpha off --exr-pixels float \
        -f "$WORK/c.exr" 2>"$WORK/stderr" || fail "the render from $1 failed: $(cat "$WORK/stderr")"
    oiiotool --dumpdata "$WORK/c.exr" | awk '/Pixel/ {print $(NF-2)}'
}
above() { awk -v x="$1" -v t="$2" 'BEGIN {exit !(x > t)}'; }

front=$(red 0,0.5,4)
above "$front" 0.1 || fail "the disk seen from the front is not drawn: red $front"
back=$(red 0,0.5,-4)
above "$back" 0.1 || fail "the disk seen from the back is not drawn: red $back"
edge=$(red 4,0,0)
above "$edge" 0.01 && fail "the disk seen edge-on is drawn: red $edge"
echo "render_disk: ok"
