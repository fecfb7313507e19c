# Sourced by the CLI tests: strict mode, a scratch folder, and small assertions.
set -euo pipefail
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }

# expect_exit CODE command...: runs the command and checks its exit code.
expect_exit() {
    local want=$1; shift
    local got=0
    "$@" >"$WORK/stdout" 2>"$WORK/stderr" || got=$?
    [ "$got" = "$want" ] || { cat "$WORK/stderr" >&2; fail "'$*' exited $got, expected $want"; }
}

# built_with BINARY SANITIZER: whether BINARY links the sanitizer's runtime (asan, tsan). The whole
# ldd output is read first: `ldd | grep -q` fails at random under pipefail when grep stops reading early.
built_with() { [[ "$(ldd "$1")" == *"lib$2"* ]]; }

# need_shared_models: for a test that reads $RT_SHARED_DIR/models, which the repository does not
# hold. Without them the test skips (exit 77, SKIP_RETURN_CODE in tests/CMakeLists.txt), or fails
# when RT_REQUIRE_SHARED_MODELS=1 (CI, where they are present).
need_shared_models() {
    [ -d "$RT_SHARED_DIR/models" ] && return 0
    local why="needs the shared test models, not found in $RT_SHARED_DIR/models: configure with -DRT_SHARED_DIR=/path/to/shared or put shared/ beside the checkout"
    [ "${RT_REQUIRE_SHARED_MODELS:-0}" = 1 ] && fail "$why"
    echo "SKIP: $why" >&2
    exit 77
}

# expect_one_error TOOL TEXT: standard error is the one line "TOOL ERROR: ..." and contains TEXT.
expect_one_error() {
    [ "$(wc -l <"$WORK/stderr")" = 1 ] && grep -q "^$1 ERROR: .*$2" "$WORK/stderr" ||
        fail "expected one line '$1 ERROR: ...$2...', got: $(cat "$WORK/stderr")"
}

# wait_for_temporary FOLDER PATTERN: waits up to 60 s for a file matching PATTERN in FOLDER (a
# temporary held by the test hook RT_TEST_WRITE_DELAY_MS, os/atomic_file.h) and prints its name.
wait_for_temporary() {
    local name
    for _ in $(seq 600); do
        name=$(ls -A "$1" | grep "$2" || true)
        [ -n "$name" ] && { echo "$name"; return 0; }
        sleep 0.1
    done
    fail "no temporary '$2' in $1: the write never started"
}
