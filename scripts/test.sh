#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test in both geometry precisions
# (double, the default, and float: thesis 3.3.1).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
for preset in release release-float; do
    echo "== $preset" >&2
    scripts/build.sh "$preset"
    ctest --preset "$preset"
done
