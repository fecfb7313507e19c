#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test in both geometry precisions
# (double, the default, and float: thesis 3.3.1). With CI=true (.ci/run) also: warnings are
# errors in the release builds and the tsan build (GCC and clang); the whole suite and the fuzz
# corpora run under ASan and UBSan in the debug configuration (asan), and the multi-threaded
# tests under ThreadSanitizer (tsan). Each stage is timed on standard error; docs/robustness.md
# says why each runs and what it costs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
presets=(release release-float)
if [ "${CI:-}" = true ]; then
    export RT_WERROR=ON
    presets+=(asan tsan)
fi
for preset in "${presets[@]}"; do
    echo "== $preset $(date +%T)" >&2
    targets=()
    # ThreadSanitizer runs the multi-threaded tests only (the tsan test preset names them).
    [ "$preset" = tsan ] && targets=(trace_tests rt-render)
    time scripts/build.sh "$preset" "${targets[@]}"
    filter=()
    # CI's float stage leaves out the command-line scripts: they test the tools' plumbing, which the
    # release and asan stages run; the unit and image tests hold the answers that depend on the
    # precision. Without CI=true every test runs in both precisions.
    [ "$preset" = release-float ] && [ "${CI:-}" = true ] && filter=(-LE cli)
    time ctest --preset "$preset" "${filter[@]}"
done
echo "== done $(date +%T)" >&2
