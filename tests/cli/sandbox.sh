# --sandbox DIR (docs/robustness.md): a scene from someone else may name only files inside DIR,
# after `..` and symbolic links are resolved; each other reference is refused with exit 2 and one
# error line naming the file and the reference. References inside DIR work as without it.
source "$(dirname "$0")/common.bash"
farm="$WORK/farm"
mkdir -p "$farm/scenes" "$farm/models" "$farm/pictures"
cp "$RT_SOURCE_DIR/scenes/models/octahedron.raw" "$farm/models/"
cp "$RT_SOURCE_DIR/scenes/models/octahedron.raw" "$WORK/outside.raw"
oiiotool --pattern checker 8x8 3 -o "$farm/pictures/checker.png"
cp "$farm/pictures/checker.png" "$WORK/outside.png"
small=(-q -x 32 -y 24 -o null)

# scene_with MODEL_FILE TEXTURE_FILE: farm/scenes/s.xml with an octahedron and a textured material.
scene_with() {
    cat >"$farm/scenes/s.xml" <<XML
<scene>
  <camera><origin z="-4"/><destination/></camera>
  <materials><material name="m" texture="t"/></materials>
  <textures><texture name="t" file="$2"/></textures>
  <models><model name="o" file="$1" type="raw"/></models>
  <objects><model name="o" material="m"/></objects>
</scene>
XML
}

# Relative references inside the sandbox, up and down its folders, still work.
scene_with ../models/octahedron.raw ../pictures/checker.png
expect_exit 0 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}" --sandbox "$farm"
expect_exit 0 "$RT_INSPECT" "$farm/scenes/s.xml" -q --sandbox "$farm"
expect_exit 0 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}" --sandbox "$farm/scenes/.."

# A texture outside: refused under --sandbox (line 4 of the scene), read without it.
scene_with ../models/octahedron.raw ../../outside.png
expect_exit 0 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}"
expect_exit 2 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}" --sandbox "$farm"
expect_one_error rt-render "s.xml:4: texture 't': ../../outside.png resolves to $WORK/outside.png, outside the sandbox $farm (--sandbox)"
expect_exit 2 "$RT_INSPECT" "$farm/scenes/s.xml" -q --sandbox "$farm"
expect_one_error rt-inspect "s.xml:4: texture 't': ../../outside.png resolves to .*outside the sandbox"

# A symbolic link inside the sandbox that leads out of it: refused, as a model and as a texture.
ln -s "$WORK/outside.raw" "$farm/models/link.raw"
ln -s ../../outside.png "$farm/pictures/link.png"
scene_with ../models/link.raw ../pictures/checker.png
expect_exit 0 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}"
expect_exit 2 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}" --sandbox "$farm"
expect_one_error rt-render "s.xml:5: model 'o': ../models/link.raw resolves to $WORK/outside.raw, outside the sandbox"
scene_with ../models/octahedron.raw ../pictures/link.png
expect_exit 2 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}" --sandbox "$farm"
expect_one_error rt-render "s.xml:4: texture 't': ../pictures/link.png resolves to $WORK/outside.png"
# ... and an absolute path
scene_with "$WORK/outside.raw" ../pictures/checker.png
expect_exit 2 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}" --sandbox "$farm"
expect_one_error rt-render "s.xml:5: model 'o': $WORK/outside.raw resolves to .*outside the sandbox"

# The scene itself must be inside, and the sandbox must be a folder.
expect_exit 2 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}" --sandbox "$farm/models"
expect_one_error rt-render "s.xml: the scene resolves to $farm/scenes/s.xml, outside the sandbox $farm/models"
expect_exit 2 "$RT_RENDER" "$farm/scenes/s.xml" "${small[@]}" --sandbox "$WORK/none"
expect_one_error rt-render "--sandbox"

# glTF (the fuzz corpus's triangle, its buffer in a file): a buffer naming ../../etc/passwd, even
# with --allow-outside-files, and an image outside.
base64 -d <<<AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA= >"$farm/models/b.bin"
gltf() {  # gltf BUFFER_URI BYTE_LENGTH [IMAGE_URI]: farm/m.gltf
    python3 - "$RT_SOURCE_DIR/fuzz/corpus/gltf_import/triangle.gltf" "$farm/m.gltf" "$@" <<'PY'
import json, sys
model = json.load(open(sys.argv[1]))
model["buffers"] = [{"uri": sys.argv[3], "byteLength": int(sys.argv[4])}]
if len(sys.argv) > 5:
    model["images"] = [{"uri": sys.argv[5]}]
    model["textures"] = [{"source": 0}]
    model["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
json.dump(model, open(sys.argv[2], "w"))
PY
}
gltf ../../../../../../../../../../etc/passwd "$(stat -c %s /etc/passwd)"
expect_exit 2 "$RT_CONVERT" "$farm/m.gltf" -q --allow-outside-files --sandbox "$farm"
expect_one_error rt-convert "m.gltf: .*buffer .*etc/passwd resolves to /etc/passwd, outside the sandbox $farm"
expect_exit 2 "$RT_RENDER" "$farm/m.gltf" "${small[@]}" --sandbox "$farm"
expect_one_error rt-render "buffer .*etc/passwd resolves to /etc/passwd, outside the sandbox"
# A buffer whose size differs from its byteLength is an error, sandbox or not.
gltf models/b.bin 43
expect_exit 2 "$RT_CONVERT" "$farm/m.gltf" -q
expect_one_error rt-convert "m.gltf: .*b.bin.* 43, but got 44"
# ... and one beyond --max-input is not read whole first.
truncate -s 2M "$farm/models/big.bin"
gltf models/big.bin $((2 << 20))
expect_exit 2 "$RT_CONVERT" "$farm/m.gltf" -q --max-input 1
expect_one_error rt-convert "m.gltf: .*big.bin is larger than the input limit (--max-input)"
gltf models/b.bin 44 ../outside.png
expect_exit 2 "$RT_CONVERT" "$farm/m.gltf" -q --sandbox "$farm"
expect_one_error rt-convert "m.gltf: texture ../outside.png resolves to $WORK/outside.png, outside the sandbox"
gltf models/b.bin 44 pictures/checker.png
expect_exit 0 "$RT_CONVERT" "$farm/m.gltf" -q --sandbox "$farm"
expect_exit 0 "$RT_RENDER" "$farm/m.gltf" "${small[@]}" --sandbox "$farm"

# OBJ: a material file outside.
printf 'newmtl m\nKd 1 1 1\n' >"$WORK/outside.mtl"
printf 'mtllib ../../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n' >"$farm/scenes/m.obj"
expect_exit 0 "$RT_CONVERT" "$farm/scenes/m.obj" -q
expect_exit 2 "$RT_CONVERT" "$farm/scenes/m.obj" -q --sandbox "$farm"
expect_one_error rt-convert "m.obj: material file ../../outside.mtl resolves to $WORK/outside.mtl, outside the sandbox"
echo "sandbox: ok"
