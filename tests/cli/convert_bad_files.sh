# Every file under shared/models/bad, companions included: rt-convert exits 2 with one
# "rt-convert ERROR:" line, or 0 for the files docs/conversion.md lists as valid enough
# (their faults lie in data rt does not use). Never a signal, never exit 1.
source "$(dirname "$0")/common.bash"
need_shared_models
BAD="$RT_SHARED_DIR/models/bad"
[ -d "$BAD" ] || fail "no $BAD"

valid_enough=(
    assimp-invalid/malformed2.obj
    derived-obj/box_truncated.obj
    obj-tinyobjloader/missing_material_file.obj
    glb-BoxBadNormals/BoxBadNormals.glb
    gltf-IncorrectVertexArrays/Cube.gltf
    gltf-texcoord_crash/texcoord_crash.gltf
    gltf-tinygltf-bounds/zero-sized-bin-chunk-issue-440.glb
    gltf-wrongTypes/badExtension.gltf
    gltf-wrongTypes/badNumber.gltf
    gltf-wrongTypes/badObject.gltf
    gltf-wrongTypes/badString.gltf
    gltf-wrongTypes/badUint.gltf
)
is_valid_enough() {
    local f
    for f in "${valid_enough[@]}"; do [ "$f" = "$1" ] && return 0; done
    return 1
}

count=0
while IFS= read -r -d '' file; do
    rel=${file#"$BAD"/}
    out="$WORK/out/$(echo "$rel" | tr '/' '_')"
    mkdir -p "$out"
    got=0
    "$RT_CONVERT" "$file" -o "$out/scene.xml" >"$WORK/stdout" 2>"$WORK/stderr" || got=$?
    if is_valid_enough "$rel"; then
        [ "$got" = 0 ] || { cat "$WORK/stderr" >&2; fail "$rel: exit $got, documented as convertible"; }
        [ -s "$out/scene.xml" ] || fail "$rel: converted but wrote no scene"
    else
        [ "$got" = 2 ] || { cat "$WORK/stderr" >&2; fail "$rel: exit $got, expected 2"; }
        [ "$(grep -c '^rt-convert ERROR: ' "$WORK/stderr")" = 1 ] || fail "$rel: not exactly one error line"
        [ -z "$(ls -A "$out")" ] || fail "$rel: failed but left output: $(ls -A "$out")"
    fi
    count=$((count + 1))
done < <(find "$BAD" -type f -print0 | sort -z)
[ "$count" -ge 81 ] || fail "only $count files under $BAD"
echo "convert_bad_files: $count files ok"
