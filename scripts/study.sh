#!/usr/bin/env bash
# Builds aloft and runs its main job, the paper's cylinder study on the built-in trial,
# writing into aloft-study/. Extra arguments go to `aloft study` (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh host
cmake --preset host >/dev/null
cmake --build --preset host --target aloft -j "$(nproc)"
exec build/host/host_sim/aloft study "$@"
