#!/usr/bin/env bash
# Runs one libFuzzer target with ASan and UBSan: scripts/fuzz.sh TARGET [MINUTES].
# TARGET: xml_scene, raw_model, camera_3ds, obj_import, gltf_import, image_texture, render_options
# or assimp_reply (fuzz/*_fuzz.cpp).
# New inputs go to build/fuzz/corpus/TARGET; the run also starts from the checked-in seeds of
# fuzz/corpus/TARGET and the matching shared test models. A finding is written as
# build/fuzz/findings/TARGET/crash-* (or leak-, timeout-, oom-): fix it and add the input to
# fuzz/corpus/TARGET, which CI replays (docs/robustness.md).
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:?usage: scripts/fuzz.sh TARGET [MINUTES]}
minutes=${2:-10}
[ -f "fuzz/${target}_fuzz.cpp" ] || { echo "fuzz.sh: no target '$target' (see fuzz/*_fuzz.cpp)" >&2; exit 2; }
scripts/install-deps.sh --checks
scripts/build.sh fuzz "fuzz_$target" >&2

shared=../shared/models
case $target in
    xml_scene) seeds=(scenes) ;;
    raw_model) seeds=(scenes/models) ;;
    camera_3ds) seeds=("$shared/3ds" "$shared/bad/derived-3ds") ;;
    obj_import) seeds=("$shared/bad/obj-tinyobjloader" "$shared/bad/derived-obj") ;;
    # The small broken files only, for OBJ and glTF: the shared models of up to 4 MB take seconds
    # each under ASan (OBJ ran at 18 inputs a second from them).
    gltf_import) seeds=("$shared/bad/gltf-tinygltf-fuzz" "$shared/bad/glb-validator" "$shared/bad/gltf-json-validator") ;;
    # The others start from fuzz/corpus/TARGET alone: an image texture's first byte picks its
    # extension, the option lists have no shared files, and the Assimp replies of the shared 3DS
    # models are in fuzz/corpus/assimp_reply.
    *) seeds=() ;;
esac
existing=()
for dir in "${seeds[@]}"; do [ -d "$dir" ] && existing+=("$dir"); done

corpus=build/fuzz/corpus/$target
findings=build/fuzz/findings/$target
mkdir -p "$corpus" "$findings"
# -rss_limit_mb is the bound of docs/robustness.md, 2 GB. -timeout is wall-clock time, 30 s: a
# 290 KB GLB that takes 1.2 s of CPU under ASan took 9.7 s on a 2-core machine at load 20; a
# timeout input is replayed alone (its CPU time against 5 s) before it counts. Inputs stay below 1 MiB (the largest seed
# would set the length otherwise).
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp"
exec "build/fuzz/fuzz/fuzz_$target" "$corpus" "fuzz/corpus/$target" "${existing[@]}" \
    -max_total_time=$((minutes * 60)) -timeout=30 -rss_limit_mb=2048 -max_len=1048576 \
    -artifact_prefix="$findings/" -print_final_stats=1
