# Image textures that must not be read (docs/robustness.md, image/image_header.h): each is refused
# with exit 2 and one error line naming it, before OpenImageIO reads a pixel, within 10 s under
# 1 GB of address space, as a glTF image, an OBJ map_Kd, an XML <environment> or --environment.
# Before: a 349-byte PNG saying 30000 x 30000 ended rt-render with std::bad_alloc (SIGABRT); a TGA
# saying 4 x 0 with SIGFPE in OpenImageIO's lookup; a tiled TIFF of 11 KB declaring 32768 x 32768
# took 6.9 GB and aborted (OpenImageIO asserted with -p); a FIFO blocked the open forever; and
# /dev/zero kept OpenImageIO's format probing reading.
source "$(dirname "$0")/common.bash"
oiiotool --pattern checker:width=2:height=2 4x4 3 -d uint8 -o "$WORK/small.png"
python3 - "$WORK/small.png" "$WORK/huge.png" <<'PY'
import struct, sys, zlib
png = bytearray(open(sys.argv[1], "rb").read())
png[16:24] = struct.pack(">II", 30000, 30000)  # IHDR width and height, then its CRC
png[29:33] = struct.pack(">I", zlib.crc32(bytes(png[12:29])))
open(sys.argv[2], "wb").write(png)
PY
oiiotool --pattern checker:width=2:height=2 4x4 2 -d uint8 -o "$WORK/small.tga"
python3 -c 'import sys; b = bytearray(open(sys.argv[1], "rb").read()); b[14:16] = b"\0\0"; open(sys.argv[2], "wb").write(b)' \
    "$WORK/small.tga" "$WORK/empty.tga"  # the header's height
python3 "$(dirname "$0")/tiled_tiff.py" 32768 32768 "$WORK/tiled.tif"
python3 "$(dirname "$0")/tiled_tiff.py" 100000 100000 "$WORK/tiled100k.tif"
mkfifo "$WORK/fifo.png"
ln -s /dev/zero "$WORK/zero.png"
ln -s /dev/urandom "$WORK/urandom.exr"

# square IMAGE: square.gltf, a square of two triangles with texture coordinates, coloured by IMAGE.
square() {
    python3 - "$WORK/square.gltf" "$1" <<'PY'
import base64, json, struct, sys
data = struct.pack("<12f8f6H", -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 1, 2, 0, 2, 3)
views = [(0, 48), (48, 32), (80, 12)]
json.dump({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
           "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
           "textures": [{"source": 0}], "images": [{"uri": sys.argv[2]}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                          "min": [-1, -1, 0], "max": [1, 1, 0]},
                         {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                         {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
           "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in views],
           "buffers": [{"byteLength": len(data),
                        "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}]},
          open(sys.argv[1], "w"))
PY
}
# The same square as OBJ (map_Kd) and as an XML scene lit by an <environment>.
obj_square() {
    printf 'newmtl m\nKd 1 1 1\nmap_Kd %s\n' "$1" >"$WORK/square.mtl"
    printf 'mtllib square.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' \
        >"$WORK/square.obj"
}
xml_sky() {
    printf '<scene><environment texture="sky"/><textures><texture name="sky" file="%s"/></textures><camera><origin z="-4"/><destination/></camera></scene>\n' \
        "$1" >"$WORK/sky.xml"
}

# refused TEXT SCENE OPTION...: rt-render of SCENE exits 2 with one error line holding TEXT, within
# 10 s and 1 GB of address space (unbounded under ASan, whose shadow memory needs terabytes).
address_space=1000000
built_with "$RT_RENDER" asan && address_space=unlimited
refused() {
    local text=$1 scene=$2 status=0
    shift 2
    (ulimit -v $address_space; exec timeout 10 "$RT_RENDER" "$scene" -x 32 -y 24 -o null --progress none "$@") \
        >"$WORK/stdout" 2>"$WORK/stderr" || status=$?
    [ "$status" = 2 ] || fail "$scene $*: exit $status, expected 2: $(cat "$WORK/stderr")"
    expect_one_error rt-render "$text"
}
square huge.png
refused "texture .*huge.png is 30000 x 30000 pixels of 3 channels, 2.5 GiB decoded, more than the 1.0 GiB an image may take" \
    "$WORK/square.gltf"
square empty.tga
refused "empty.tga is 4 x 0 pixels of 2 channels: no pixels" "$WORK/square.gltf"
square tiled.tif
refused "tiled.tif is 32768 x 32768 pixels of 3 channels, 3.0 GiB decoded" "$WORK/square.gltf"
refused "tiled.tif is 32768 x 32768 pixels" "$WORK/square.gltf" -p  # rt-farm's pre-check
refused "tiled.tif is 32768 x 32768 pixels" "$WORK/square.gltf"
square small.png
refused "environment': $WORK/tiled.tif is 32768 x 32768 pixels" "$WORK/square.gltf" --integrator path --environment "$WORK/tiled.tif"
square tiled100k.tif
refused "tiled100k.tif is 100000 x 100000 pixels" "$WORK/square.gltf"

# A FIFO or a device, named directly, through a link or by an absolute URI, as each kind of reference.
square fifo.png
refused "fifo.png is a FIFO, not a regular file" "$WORK/square.gltf"
refused "fifo.png is a FIFO, not a regular file" "$WORK/square.gltf" --sandbox "$WORK"
square zero.png
refused "zero.png is a character device, not a regular file" "$WORK/square.gltf"
square /dev/urandom
refused "/dev/urandom is a character device, not a regular file" "$WORK/square.gltf"
obj_square fifo.png
refused "fifo.png is a FIFO, not a regular file" "$WORK/square.obj"
obj_square urandom.exr
refused "urandom.exr is a character device, not a regular file" "$WORK/square.obj"
xml_sky fifo.png
refused "fifo.png is a FIFO, not a regular file" "$WORK/sky.xml" --integrator path
xml_sky /dev/zero
refused "/dev/zero is a character device, not a regular file" "$WORK/sky.xml" --integrator path
refused "fifo.png: the environment image is not a regular file" "$WORK/sky.xml" --integrator path --environment "$WORK/fifo.png"

# --sandbox covers --environment, which rt-farm passes through from whoever submits.
mkdir "$WORK/farm"
xml_sky small.png
cp "$WORK/sky.xml" "$WORK/small.png" "$WORK/farm/"
refused "--environment: $WORK/small.png resolves to .*outside the sandbox $WORK/farm" "$WORK/farm/sky.xml" \
    --integrator path --sandbox "$WORK/farm" --environment "$WORK/small.png"
expect_exit 0 "$RT_RENDER" "$WORK/farm/sky.xml" -q -x 8 -y 8 -o null --integrator path --sandbox "$WORK/farm" \
    --environment "$WORK/farm/small.png"
echo "render_texture_limits: ok"
