# Every tool answers --help and --version with exit code 0, and a bad option with 2.
source "$(dirname "$0")/common.bash"
for tool in "$RT_CONVERT" "$RT_RENDER" "$RT_INSPECT"; do
    name=$(basename "$tool")
    expect_exit 0 "$tool" --version
    grep -q "^$name [0-9]" "$WORK/stdout" || fail "$name --version printed: $(cat "$WORK/stdout")"
    grep -q "geometry in $RT_REAL" "$WORK/stdout" || fail "$name --version does not name $RT_REAL"
    expect_exit 0 "$tool" --help
    grep -q "Usage" "$WORK/stdout" || fail "$name --help printed no usage"
    expect_exit 2 "$tool" --no-such-option
done
echo "tools_version: ok"
