#!/usr/bin/env bash
# Installs every Debian package aloft builds, tests and cross-compiles with.
# Idempotent: does nothing when all are present. Needs root (uses sudo when not root).
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev catch2 nlohmann-json3-dev libcli11-dev libboost-dev libbenchmark-dev
  libcairo2-dev
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib
  g++-arm-linux-gnueabihf qemu-user qemu-system-arm
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "aloft: installing ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
