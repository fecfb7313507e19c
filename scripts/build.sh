#!/usr/bin/env bash
# Configures and builds one preset: scripts/build.sh [PRESET [TARGET...]], PRESET one of
# release (the default), release-float, debug, asan, tsan, fuzz (CMakePresets.json); without
# targets it builds everything the preset holds.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
shift || true
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" ${1:+--target "$@"}
