#!/usr/bin/env bash
# Installs what only the benchmarks need, beyond scripts/install-deps.sh: Intel Embree 3
# (Debian 12: 3.13.5) for bench/vs_embree. rt never needs it to build, test or run, and CI
# does not install it. Reconfigure afterwards (scripts/build.sh release) to build vs_embree.
set -euo pipefail
dpkg-query -W -f='${Status}' libembree-dev 2>/dev/null | grep -q "ok installed" && exit 0
echo "installing: libembree-dev" >&2
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends \
    -o DPkg::Lock::Timeout=600 libembree-dev
