#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test in both geometry precisions
# (double, the default, and float: thesis 3.3.1). With CI=true (.ci/run) also: warnings are
# errors in the uninstrumented builds, the debug build, the whole suite under ASan and UBSan, the
# multi-threaded tests under ThreadSanitizer, and each fuzz target over its corpus
# (docs/robustness.md says why each).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
presets=(release release-float)
if [ "${CI:-}" = true ]; then
    export RT_WERROR=ON
    presets+=(debug asan tsan fuzz)
fi
for preset in "${presets[@]}"; do
    echo "== $preset $(date +%T)" >&2
    targets=()
    case $preset in
        # Built, for its warnings; its tests would repeat the release tests' answers, slowly.
        debug) scripts/build.sh debug; continue ;;
        # ThreadSanitizer runs the multi-threaded tests only (the tsan test preset names them).
        tsan) targets=(trace_tests rt-render) ;;
        fuzz) targets=(fuzz_xml_scene fuzz_raw_model fuzz_camera_3ds fuzz_obj_import fuzz_gltf_import) ;;
    esac
    scripts/build.sh "$preset" "${targets[@]}"
    ctest --preset "$preset"
done
echo "== done $(date +%T)" >&2
