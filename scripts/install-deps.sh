#!/usr/bin/env bash
# Installs the Debian packages aloft needs, and nothing when they are all present.
#   scripts/install-deps.sh host   build and run the host program and its tests (gcc, and
#                                  clang with its sanitizer and libFuzzer runtimes;
#                                  ccache, which the scripts use when it is there)
#   scripts/install-deps.sh all    also Ceres (a comparison test) and the ARM cross
#                                  toolchains and QEMU (target tests: armhf, cortex-m4f,
#                                  stm32f405 on netduinoplus2)
# Needs root; uses sudo when not root.
set -euo pipefail

host_packages=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev catch2 nlohmann-json3-dev libcli11-dev libboost-dev libbenchmark-dev
  libcairo2-dev libxsimd-dev libpugixml-dev zlib1g-dev
  clang libclang-rt-dev clang-format
  parallel
  python3-dev python3-numpy pybind11-dev python3-pytest python3-matplotlib
  ccache
)
# Tests only, never linked into aloft: the fitter weighed against Ceres (tests/diagnose/ceres/).
comparison_packages=(libceres-dev)
target_packages=(
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib
  g++-arm-linux-gnueabihf qemu-user qemu-system-arm
)

case "${1:-host}" in
  host) packages=("${host_packages[@]}") ;;
  all) packages=("${host_packages[@]}" "${comparison_packages[@]}" "${target_packages[@]}") ;;
  *) echo "usage: $0 [host|all]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "aloft: installing ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
  "${missing[@]}" >&2
