# Image textures whose headers declare sizes that cannot be decoded (docs/robustness.md): a
# 349-byte PNG saying 30000 x 30000 (2.7 GB decoded) ended rt-render with std::bad_alloc in a
# render thread (SIGABRT); a TGA saying 4 x 0, found by mutating a small one, with SIGFPE in
# OpenImageIO's lookup. Each is now white and a warning.
source "$(dirname "$0")/common.bash"
oiiotool --pattern checker:width=2:height=2 4x4 3 -d uint8 -o "$WORK/small.png"
python3 - "$WORK/small.png" "$WORK/huge.png" <<'PY'
import struct, sys, zlib
png = bytearray(open(sys.argv[1], "rb").read())
png[16:24] = struct.pack(">II", 30000, 30000)  # IHDR width and height, then its CRC
png[29:33] = struct.pack(">I", zlib.crc32(bytes(png[12:29])))
open(sys.argv[2], "wb").write(png)
PY
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
# render_warns TEXT: renders square.gltf under 2 GB of address space (2.7 GB asked for fails at
# once instead of filling the machine): exit 0 and a warning with TEXT. Not under ASan, whose
# shadow memory needs terabytes of address space (the release stage keeps the bound).
address_space=2000000
built_with "$RT_RENDER" asan && address_space=unlimited
render_warns() {
    local status=0
    (ulimit -v $address_space; exec "$RT_RENDER" "$WORK/square.gltf" -x 32 -y 24 -o null --progress none) 2>"$WORK/stderr" ||
        status=$?
    [ "$status" = 0 ] || fail "exit $status: $(cat "$WORK/stderr")"
    grep -q "warning: texture .*$1.*: white is used" "$WORK/stderr" || fail "no warning '$1': $(cat "$WORK/stderr")"
}
square huge.png
render_warns "huge.png is 30000 x 30000 pixels, more than the 1 GiB an untiled image may take"
oiiotool --pattern checker:width=2:height=2 4x4 2 -d uint8 -o "$WORK/small.tga"
python3 -c 'import sys; b = bytearray(open(sys.argv[1], "rb").read()); b[14:16] = b"\0\0"; open(sys.argv[2], "wb").write(b)' \
    "$WORK/small.tga" "$WORK/empty.tga"  # the header's height
square empty.tga
render_warns "empty.tga is 4 x 0 pixels of 2 channels: no pixels"
echo "render_texture_limits: ok"
