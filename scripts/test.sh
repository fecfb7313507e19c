#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test in both geometry precisions
# (double, the default, and float: thesis 3.3.1). With CI=true (.ci/run) also: warnings are
# errors in the release builds and the tsan build (GCC and clang); the unit tests, the fuzz
# corpora and the hostile-input scripts run under ASan and UBSan in the debug configuration
# (asan), and the multi-threaded tests under ThreadSanitizer (tsan). Each stage is timed on
# standard error; docs/robustness.md says why each runs and what it costs.
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
    filter=()
    if [ "${CI:-}" = true ]; then
        case $preset in
            # The float stage builds and runs the unit and image tests, which hold the answers that
            # depend on the precision, and checks its SIMD objects' isolation. The command-line
            # scripts test the tools' plumbing, and the format and layering checks the sources:
            # the release stage runs those once.
            release-float) targets=(trace_tests image_tests) filter=(-L 'unit|image|isolation') ;;
            # ASan and UBSan: the unit and image tests, the fuzz corpora, and the command-line
            # scripts that feed the tools hostile input (label `hostile`, tests/CMakeLists.txt).
            asan) filter=(-L 'unit|image|fuzz|hostile') ;;
            # ThreadSanitizer: the multi-threaded tests only (the tsan test preset names them).
            tsan) targets=(trace_tests rt-render) ;;
        esac
    fi
    time scripts/build.sh "$preset" "${targets[@]}"
    time ctest --preset "$preset" "${filter[@]}"
done
echo "== done $(date +%T)" >&2
