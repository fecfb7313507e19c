# Every format OpenImageIO writes, picked by extension: display-referred ones through the OCIO
# view, scene-referred ones linear; one the installed OpenImageIO cannot write is exit 2 before
# any work.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
opts=(-K -q -x 32 -y 24)

check() {  # check FILE WHAT: iinfo's line for FILE contains WHAT
    "$RT_RENDER" "$scene" "${opts[@]}" "${@:3}" -f "$WORK/$1"
    iinfo "$WORK/$1" | grep -q "32 x   24, $2" || fail "$1: $(iinfo "$WORK/$1")"
}
check a.jpg "3 channel, uint8 jpeg" --jpeg-quality 95
check a.tif "4 channel, uint8 tiff"
check b.tiff "4 channel, uint16 tiff" --tiff-bits 16
check c.tif "4 channel, float tiff" --tiff-bits 32
check a.hdr "3 channel, float hdr"
check b.exr "4 channel, half openexr" --exr-compression piz
iinfo -v "$WORK/b.exr" | grep -q 'compression: "piz"' || fail "--exr-compression piz: $(iinfo -v "$WORK/b.exr")"
# Linear files agree with the EXR, display-referred ones with the PNG.
"$RT_RENDER" "$scene" "${opts[@]}" --exr-pixels float --alpha off -f "$WORK/lin.exr"
"$RT_RENDER" "$scene" "${opts[@]}" --alpha off --tiff-bits 32 -f "$WORK/lin.tif"
idiff -fail 0 -warn 0 "$WORK/lin.exr" "$WORK/lin.tif" >/dev/null || fail "float TIFF is not the linear picture"
"$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/d.png"
idiff -fail 0 -warn 0 "$WORK/d.png" "$WORK/a.tif" >/dev/null || fail "8-bit TIFF is not the PNG's display-referred picture"

# WebP and PFM where this OpenImageIO writes them, else a usage error before rendering.
for name in a.webp a.pfm; do
    if "$RT_RENDER" "$scene" "${opts[@]}" -f "$WORK/$name" 2>"$WORK/stderr"; then
        iinfo "$WORK/$name" | grep -q "32 x   24" || fail "$name: $(iinfo "$WORK/$name")"
    else
        expect_one_error rt-render "the installed OpenImageIO cannot write this format"
    fi
done
expect_exit 2 "$RT_RENDER" "$scene" -q -o bmp -f "$WORK/a.bmp"
expect_one_error rt-render "--output: bmp not in {null,png,exr,tga,text,jpeg,tiff,hdr,pfm,webp,sdl}"
expect_exit 2 "$RT_RENDER" "$scene" -q --alpha on -f "$WORK/a.jpg"
expect_one_error rt-render "--alpha on: jpeg output has no alpha channel"
echo "render_formats: ok"
