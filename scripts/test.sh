#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test in both geometry precisions
# (double, the default, and float: thesis 3.3.1). With CI=true (.ci/run) also: warnings are
# errors in the release builds and the tsan build (GCC and clang), and the multi-threaded tests
# run under ThreadSanitizer (the asan preset, below, runs by hand for now). Each stage is timed on standard
# error; docs/robustness.md says why each runs and what it costs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
presets=(release release-float)
if [ "${CI:-}" = true ]; then
    export RT_WERROR=ON
    # asan (the debug configuration under ASan+UBSan) is not in CI yet: OpenImageIO 2.4 frees its
    # TextureSystem with a sized delete ASan reports (the asan test preset now sets
    # new_delete_type_mismatch=0), and the whole suite has not yet passed under it
    # (docs/robustness.md). `scripts/build.sh asan && ctest --preset asan` runs it by hand.
    presets+=(tsan)
fi
for preset in "${presets[@]}"; do
    echo "== $preset $(date +%T)" >&2
    targets=()
    # ThreadSanitizer runs the multi-threaded tests only (the tsan test preset names them).
    [ "$preset" = tsan ] && targets=(trace_tests rt-render)
    time scripts/build.sh "$preset" "${targets[@]}"
    time ctest --preset "$preset"
done
echo "== done $(date +%T)" >&2
