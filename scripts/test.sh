#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test in both geometry precisions
# (double, the default, and float: thesis 3.3.1). With CI=true (.ci/run) also: warnings are
# errors, the debug build, the whole suite under ASan and UBSan, the multi-threaded tests under
# ThreadSanitizer (docs/robustness.md says why each).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
presets=(release release-float)
if [ "${CI:-}" = true ]; then
    export RT_WERROR=ON
    presets+=(debug asan tsan)
fi
for preset in "${presets[@]}"; do
    echo "== $preset $(date +%T)" >&2
    targets=()
    tests=()
    case $preset in
        # The unit tests check the assertions that a debug build keeps; renders are slow unoptimised.
        debug) tests=(-L unit) ;;
        # ThreadSanitizer runs the multi-threaded tests only (the tsan test preset names them).
        tsan) targets=(trace_tests rt-render) ;;
    esac
    scripts/build.sh "$preset" "${targets[@]}"
    ctest --preset "$preset" "${tests[@]}"
done
echo "== done $(date +%T)" >&2
