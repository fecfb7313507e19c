#!/usr/bin/env bash
# Installs what is missing, builds rt, and renders a bundled scene to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
build/release/tools/render/rt-render --version
