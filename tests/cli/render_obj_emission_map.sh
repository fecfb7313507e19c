# An OBJ's emission map (map_Ke, docs/conversion.md "OBJ materials") shows its texture: a black
# screen whose MTL says Ke 1 1 1 and map_Ke of a picture red on the left, blue on the right,
# renders red on the left and blue on the right (not plain white), read from the OBJ and from
# the XML rt-convert writes of it.
source "$(dirname "$0")/common.bash"

printf 'P6\n4 1\n255\n\377\0\0\377\0\0\0\0\377\0\0\377' >"$WORK/tv.ppm"
cat >"$WORK/screen.mtl" <<'MTL'
newmtl screen
Kd 0 0 0
Ks 0 0 0
Ke 1 1 1
map_Ke -clamp on tv.ppm
MTL
cat >"$WORK/screen.obj" <<'OBJ'
mtllib screen.mtl
v -1 -1 0
v 1 -1 0
v 1 1 0
v -1 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl screen
f 1/1 2/2 3/3 4/4
OBJ

# The red, green and blue of the leftmost and rightmost pixels of a 4x1 render of $1 ("r g b;r g b").
ends() {
    "$RT_RENDER" "$1" -q -x 4 -y 1 --look-from 0,0,3 --look-at 0,0,0 --fov 20 --alpha off \
        --exr-pixels float -f "$WORK/s.exr" || fail "the render of $1 failed"
    oiiotool --dumpdata "$WORK/s.exr" | awk '/Pixel \(0, 0\)|Pixel \(3, 0\)/ {printf "%s %s %s;", $(NF-2), $(NF-1), $NF}'
}
# Whether "r g b" ($1) is mostly the channel $2 (1 red, 3 blue): above 0.8, the others below 0.1.
mostly() { awk -v c="$1" -v k="$2" 'BEGIN {split(c, x, " "); for (i = 1; i <= 3; ++i)
    if ((i == k && x[i] < 0.8) || (i != k && x[i] > 0.1)) exit 1}'; }

for scene in "$WORK/screen.obj" xml; do
    if [ "$scene" = xml ]; then
        "$RT_CONVERT" -q "$WORK/screen.obj" -o "$WORK/screen.xml" || fail "rt-convert failed"
        scene="$WORK/screen.xml"
    fi
    pixels=$(ends "$scene")
    mostly "${pixels%%;*}" 1 || fail "$scene: the screen's left is not the map's red: $pixels"
    right=${pixels#*;}
    mostly "${right%;}" 3 || fail "$scene: the screen's right is not the map's blue: $pixels"
done
echo "render_obj_emission_map: ok"
