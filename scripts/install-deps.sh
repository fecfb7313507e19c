#!/usr/bin/env bash
# Installs the Debian 12 packages rt builds with, if any is missing. Needs root (or sudo).
#   scripts/install-deps.sh           what rt builds, tests and runs with
#   scripts/install-deps.sh --build   only what building the tools needs (scripts/demo.sh: no test
#                                     runners, sanitizers, Slurm or window system to install)
#   scripts/install-deps.sh --checks  also clang 14 with its sanitizer runtimes and OpenMP, for the
#                                     asan, tsan and fuzz presets (CI, where CI=true, installs them)
#   scripts/install-deps.sh --bench   also what only the benchmarks use: Intel Embree 3 for
#                                     bench/vs_embree, clang 14 and its OpenMP for the compiler
#                                     table of bench/thesis_tables.sh (CI does not install Embree)
set -euo pipefail
packages=(
    cmake ninja-build g++ pkg-config ccache
    libassimp-dev libtinygltf-dev libtinyobjloader-dev libopenimageio-dev libopencolorio-dev libcli11-dev
    libpugixml-dev libgtest-dev libbenchmark-dev  # configuring the release preset finds these two
    openimageio-tools  # Debian's OpenImageIO CMake package names its programs: configuring fails without them
)
if [ "${1:-}" != --build ]; then
    packages+=(
        opencolorio-tools
        clang-format-14  # the `format` test: scripts/check-format.sh against .clang-format
        python3 python3-jsonschema  # tests/cli: JSON checks; json_schema.sh validates against docs/schema
        libsdl2-dev xvfb  # rt-render -o sdl; tests/cli/render_sdl.sh opens its window in Xvfb
        slurm-wlm munge  # tests/cli/farm_slurm.sh starts a one-node Slurm cluster (as root) for rt-farm
    )
fi
if [ "${1:-}" = --checks ] || [ "${CI:-}" = true ]; then
    packages+=(clang-14 libclang-rt-14-dev libomp-14-dev)
fi
[ "${1:-}" = "--bench" ] && packages+=(libembree-dev clang-14 libomp-14-dev)
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
