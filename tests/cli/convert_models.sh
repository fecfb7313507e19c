# Every model of shared/models/MANIFEST.md under {gltf,glb,obj,3ds} converts: exit 0, a
# scene.xml, one RAW file per model (the --json "models"), whose triangle counts (RAW header,
# appendix D) add up to "modelTriangles"; with the degenerate triangles dropped they make the
# manifest's count. The manifest lists every model file there is. Instancing writes a mesh
# once (SharedMesh: 1 RAW for 2 instances, 2CylinderEngine: 34 RAW for 115). -o - writes one
# XML with every model inline, and nothing else.
source "$(dirname "$0")/common.bash"
need_shared_models
MODELS="$RT_SHARED_DIR/models"

json_field() { sed -n "s/.*\"$1\": \([0-9]*\).*/\1/p" "$2"; }

# Sum of the uint32 counts at byte 6 of the RAW files in a folder.
raw_triangles() {
    local total=0 f n
    for f in "$1"/*.raw; do
        [ "$(head -c 6 "$f")" = "raw3dT" ] || fail "$f: not a triangle RAW file"
        n=$(od -An -tu4 -j6 -N4 "$f" | tr -d ' ')
        # Triangles, then any of the per-corner sections: vnrm and vcol 4 + 36n bytes, vtex 4 + 24n, vtan 4 + 48n.
        local rest=$(($(stat -c %s "$f") - 10 - 36 * n)) ok= subset sizes=(36 24 36 48)
        for subset in $(seq 0 15); do
            local sections=0 i
            for i in 0 1 2 3; do ((subset >> i & 1)) && sections=$((sections + 4 + sizes[i] * n)); done
            [ "$rest" = "$sections" ] && ok=1
        done
        [ -n "$ok" ] || fail "$f: size does not match its count $n"
        total=$((total + n))
    done
    echo "$total"
}

# manifest_models: "file triangles" for each row of the manifest's ground-truth tables in the
# folders converted here: the file and Assimp's count of triangles in its mesh data.
manifest_models() {
    awk -F'|' 'NF > 14 && $2 ~ /^ `(gltf|glb|obj|3ds)\// && $5 ~ /^ [0-9]/ {
        gsub(/[ `]/, "", $2); split($5, t, " "); print $2, t[1] }' "$MODELS/MANIFEST.md" | sort
}
model_files() {
    find "$MODELS/gltf" "$MODELS/glb" "$MODELS/obj" "$MODELS/3ds" -type f \( -iname '*.gltf' -o -iname '*.glb' \
        -o -iname '*.obj' -o -iname '*.3ds' -o -name testFormatDetection \) | sed "s|^$MODELS/||" | sort
}
missing=$(comm -3 <(manifest_models | cut -d' ' -f1) <(model_files))
[ -z "$missing" ] || fail "model files and MANIFEST.md rows differ (left: only in the manifest, right: only on disk): $missing"

count=0
while read -r rel triangles <&3; do
    out="$WORK/$count"
    mkdir -p "$out"
    expect_exit 0 "$RT_CONVERT" "$MODELS/$rel" -o "$out/scene.xml" --json
    cp "$WORK/stdout" "$out/summary.json"
    [ -s "$out/scene.xml" ] || fail "$rel: no scene.xml"
    models=$(json_field models "$out/summary.json")
    raws=$(find "$out/scene" -name '*.raw' | wc -l)  # embedded images are written beside them
    [ "$raws" = "$models" ] || fail "$rel: $raws RAW files for $models models"
    kept=$(json_field modelTriangles "$out/summary.json")
    [ "$(raw_triangles "$out/scene")" = "$kept" ] || fail "$rel: RAW triangles differ from the summary"
    dropped=$(json_field degenerate "$out/summary.json")
    [ $((kept + dropped)) = "$triangles" ] ||
        fail "$rel: $kept triangles kept and $dropped degenerate dropped, MANIFEST.md counts $triangles"
    grep -q "^rt-convert: .* -> $out/scene.xml" "$WORK/stderr" || fail "$rel: no summary on stderr"
    rm -rf "$out"
    count=$((count + 1))
done 3< <(manifest_models)
[ "$count" -gt 0 ] || fail "no models in MANIFEST.md"

# Instancing: one RAW per distinct mesh, however often it is placed.
expect_exit 0 "$RT_CONVERT" "$MODELS/gltf/SharedMesh/02_shared_mesh.gltf" -o "$WORK/shared.xml" --json
[ "$(ls "$WORK/shared" | wc -l)" = 1 ] || fail "SharedMesh: $(ls "$WORK/shared" | wc -l) RAW files"
[ "$(json_field instances "$WORK/stdout")" = 2 ] || fail "SharedMesh: not 2 instances"
[ "$(grep -c '<model name=' "$WORK/shared.xml")" = 3 ] || fail "SharedMesh: 1 model declared and placed twice expected"
expect_exit 0 "$RT_CONVERT" "$MODELS/glb/2CylinderEngine/2CylinderEngine.glb" -o "$WORK/engine.xml" --json
[ "$(ls "$WORK/engine" | wc -l)" = 34 ] || fail "2CylinderEngine: $(ls "$WORK/engine" | wc -l) RAW files"
[ "$(json_field instances "$WORK/stdout")" = 115 ] || fail "2CylinderEngine: not 115 instances"

# -o -: the scene on stdout with inline models, no files, the summary on stderr.
cd "$WORK" && mkdir inline && cd inline
expect_exit 0 "$RT_CONVERT" "$MODELS/gltf/Duck/Duck.gltf" -o -
head -1 "$WORK/stdout" | grep -q '^<?xml' || fail "-o - did not write XML first"
grep -q '<model name="[^"]*" type="raw" encoding="base64">' "$WORK/stdout" || fail "-o - has no inline model"
[ -z "$(ls -A .)" ] || fail "-o - wrote files: $(ls -A .)"
grep -q 'triangles  4212 in the models' "$WORK/stderr" || fail "-o -: no summary on stderr"

# --json cannot share stdout with the scene; bad options exit 2.
expect_exit 2 "$RT_CONVERT" "$MODELS/gltf/Duck/Duck.gltf" -o - --json
expect_exit 2 "$RT_CONVERT" "$MODELS/gltf/Duck/Duck.gltf" --up-axis x
expect_exit 2 "$RT_CONVERT" "$MODELS/gltf/Duck/Duck.gltf" --scale 0
expect_exit 2 "$RT_CONVERT" "$MODELS/gltf/Duck/Duck.gltf" --scene 3
expect_exit 2 "$RT_CONVERT" "$MODELS/gltf/Cameras/Cameras.gltf" --camera 1
expect_exit 2 "$RT_CONVERT" "$WORK/absent.gltf" -o "$WORK/absent.xml"
[ ! -e "$WORK/absent.xml" ] && [ ! -e "$WORK/absent" ] || fail "a failed conversion left output"
echo "convert_models: $count models ok"
