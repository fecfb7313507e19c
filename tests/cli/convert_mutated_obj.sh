# Mutated OBJ files (a byte replaced, the file cut short, a line repeated or dropped, a
# number negated): rt-convert either converts them (exit 0) or refuses them with one
# "rt-convert ERROR:" line (exit 2), and never crashes, hangs or fails otherwise. The mutations
# are drawn from a fixed seed, so a failure reproduces; the file that failed is kept.
source "$(dirname "$0")/common.bash"
need_shared_models
MODELS="$RT_SHARED_DIR/models/obj"
sources=(box/box.obj cube_usemtl/cube_usemtl.obj cornell_box-tinyobj/cornell_box.obj spd-teapot/teapot_s2.obj)
replacements=(0 1 9 - + / . e E n f v " " $'\t' $'\r' $'\n' '#' x)
RANDOM=20081122
runs=120

mutate() {  # mutate SOURCE KIND: the mutated text on stdout
    local text size at line
    text=$(cat "$1")
    size=${#text}
    at=$((RANDOM * 32768 + RANDOM))
    at=$((at % size))
    case $2 in
        0) printf '%s' "${text:0:at}${replacements[RANDOM % ${#replacements[@]}]}${text:at+1}" ;;
        1) printf '%s' "${text:0:at}" ;;
        2) line=$((RANDOM % $(wc -l <"$1") + 1)); sed "${line}p" "$1" ;;
        3) line=$((RANDOM % $(wc -l <"$1") + 1)); sed "${line}d" "$1" ;;
        4) printf '%s' "${text:0:at}-${text:at}" ;;
    esac
}

for ((i = 0; i < runs; i++)); do
    src=${sources[RANDOM % ${#sources[@]}]}
    dir="$WORK/$i"
    mkdir -p "$dir"
    cp "$MODELS/$(dirname "$src")"/*.mtl "$dir"/ 2>/dev/null || true
    mutate "$MODELS/$src" $((RANDOM % 5)) >"$dir/m.obj"
    got=0
    timeout 20 "$RT_CONVERT" "$dir/m.obj" -o "$dir/out/scene.xml" >"$WORK/stdout" 2>"$WORK/stderr" || got=$?
    case $got in
        0) [ -s "$dir/out/scene.xml" ] || fail "mutation $i of $src: converted but wrote no scene" ;;
        2) [ "$(grep -c '^rt-convert ERROR: ' "$WORK/stderr")" = 1 ] || fail "mutation $i of $src: not one error line" ;;
        *)
            cat "$WORK/stderr" >&2
            cp "$dir/m.obj" "${TMPDIR:-/tmp}/rt-mutated.obj"
            fail "mutation $i of $src: exit $got (the file is kept as ${TMPDIR:-/tmp}/rt-mutated.obj)"
            ;;
    esac
    rm -rf "$dir"
done
echo "convert_mutated_obj: $runs files ok"
