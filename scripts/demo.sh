#!/usr/bin/env bash
# Installs what is missing, builds rt, and renders the bundled demo scene (scenes/demo.xml)
# to out/demo.png (sRGB, for any image viewer) and out/demo.exr (linear half float). It installs
# and builds only what the render needs (rt-render, not the tests and benchmarks: scripts/test.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --build
scripts/build.sh release rt-render
mkdir -p out
render=build/release/tools/render/rt-render
# KD tree, shadows, reflections up to depth 5, 9 jittered samples per pixel.
options=(scenes/demo.xml -K -s -d 5 -S 9 -x 800 -y 600)
# One render, both files; --alpha off keeps the scene's dark blue sky (else transparent).
"$render" "${options[@]}" --alpha off -f out/demo.png -f out/demo.exr
echo "demo: wrote $PWD/out/demo.png and $PWD/out/demo.exr"
