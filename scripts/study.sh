#!/usr/bin/env bash
# Builds aloft and runs its main job, the paper's cylinder study on the built-in trial,
# writing into aloft-study/. Extra arguments go to `aloft study` (see --help).
# The build's output goes to build/host/study-build.log, not to the terminal: the first
# run compiles the whole program (a few minutes); later runs rebuild only what changed.
# Warnings stay warnings here (scripts/test.sh is where they are errors): a newer
# compiler's new warning must not stop the study. Through ccache when it is installed.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh host
log=build/host/study-build.log
mkdir -p build/host
[ -x build/host/host_sim/aloft ] || echo "aloft: building the aloft program (first run: a few minutes; log in $log)" >&2
launcher=""
command -v ccache >/dev/null 2>&1 && launcher=ccache
if ! { cmake --preset host -DCMAKE_COMPILE_WARNING_AS_ERROR=OFF -DCMAKE_C_COMPILER_LAUNCHER="$launcher" \
         -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" && cmake --build --preset host --target aloft -j "$(nproc)"; } >"$log" 2>&1; then
  echo "aloft: the build failed; the last lines of $log:" >&2
  tail -n 20 "$log" >&2
  exit 1
fi
exec build/host/host_sim/aloft study "$@"
