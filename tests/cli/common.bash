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

# wait_for_temporary FOLDER PATTERN: waits up to 60 s for a file matching PATTERN in FOLDER (a
# temporary held by the test hook RT_TEST_WRITE_DELAY_MS, core/atomic_file.h) and prints its name.
wait_for_temporary() {
    local name
    for _ in $(seq 600); do
        name=$(ls -A "$1" | grep "$2" || true)
        [ -n "$name" ] && { echo "$name"; return 0; }
        sleep 0.1
    done
    fail "no temporary '$2' in $1: the write never started"
}
