#!/usr/bin/env bash
# Runs every test of aloft: the host suite (lib/, host program, benchmarks as smoke
# runs), and the core suite on the ARM targets under QEMU. Installs what it needs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh all
jobs=$(nproc)
for preset in host armhf cortex-m4f; do
  echo "== $preset ==" >&2
  cmake --preset "$preset"
  cmake --build --preset "$preset"
  ctest --preset "$preset" -j "$jobs"
done
