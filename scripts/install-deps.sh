#!/usr/bin/env bash
# Installs the Debian 12 packages rt builds with, if any is missing. Needs root (or sudo).
# With --checks, or in CI (CI=true), also clang and its runtimes for the tsan and fuzz presets.
set -euo pipefail
packages=(
    cmake ninja-build g++ pkg-config ccache
    libassimp-dev libtinygltf-dev libtinyobjloader-dev libopenimageio-dev libopencolorio-dev libcli11-dev
    libpugixml-dev libgtest-dev libbenchmark-dev
    openimageio-tools opencolorio-tools
)
if [ "${1:-}" = --checks ] || [ "${CI:-}" = true ]; then
    packages+=(clang-14 libclang-rt-14-dev libomp-14-dev)
fi
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends \
    -o DPkg::Lock::Timeout=600 "${missing[@]}"
