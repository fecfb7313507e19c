# The files of shared/models/hostile/assimp-mutants make Assimp abort, crash, hang or ask for
# tens of gigabytes; rt reads through Assimp in a child process (os/contained.h), so each
# tool answers every one with exit 2 and one "TOOL ERROR: FILE: ..." line, within 10 s and 1 GB
# (peak resident memory of the tool and its child; not measured in a sanitizer build), and
# writes nothing.
source "$(dirname "$0")/common.bash"
need_shared_models
MUTANTS="$RT_SHARED_DIR/models/hostile/assimp-mutants"
[ -d "$MUTANTS" ] || fail "no $MUTANTS"
sanitized=false
{ built_with "$RT_CONVERT" asan || built_with "$RT_CONVERT" tsan; } && sanitized=true

# check TOOL FILE command...: exit 2, one error line naming FILE, in time and memory.
check() {
    local tool=$1 file=$2 got=0
    shift 2
    /usr/bin/time -f '%e %M' -o "$WORK/usage" "$@" >"$WORK/stdout" 2>"$WORK/stderr" || got=$?
    local name
    name=$(basename "$file")
    [ "$got" = 2 ] || { cat "$WORK/stderr" >&2; fail "$tool $name: exit $got, expected 2"; }
    [ "$(wc -l <"$WORK/stderr")" = 1 ] && grep -q "^$tool ERROR: $file: " "$WORK/stderr" ||
        fail "$tool $name: expected one line '$tool ERROR: $file: ...', got: $(cat "$WORK/stderr")"
    read -r seconds kilobytes < <(tail -n 1 "$WORK/usage")  # after "Command exited with ..."
    awk -v s="$seconds" 'BEGIN { exit !(s < 10) }' || fail "$tool $name: took $seconds s"
    $sanitized || [ "$kilobytes" -lt 1000000 ] || fail "$tool $name: peak memory $kilobytes KB"
    echo "$tool $name: $seconds s, $kilobytes KB: $(cut -c1-160 "$WORK/stderr")"
}

count=0
for file in "$MUTANTS"/*; do
    [ "$(basename "$file")" = README.md ] && continue
    mkdir -p "$WORK/out"
    check rt-convert "$file" "$RT_CONVERT" "$file" -o "$WORK/out/scene.xml"
    check rt-render "$file" "$RT_RENDER" "$file" -f "$WORK/out/image.png"
    check rt-inspect "$file" "$RT_INSPECT" "$file"
    [ -z "$(ls -A "$WORK/out")" ] || fail "$file: left output: $(ls -A "$WORK/out")"
    count=$((count + 1))
done
[ "$count" -ge 14 ] || fail "only $count files under $MUTANTS"
echo "bad_files_assimp_mutants: $count files ok"
