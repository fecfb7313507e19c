#!/usr/bin/env bash
# Installs what only the benchmarks need (scripts/install-deps.sh --bench). Reconfigure
# afterwards (scripts/build.sh release) to build bench/vs_embree.
exec "$(dirname "${BASH_SOURCE[0]}")/install-deps.sh" --bench
