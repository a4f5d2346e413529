#!/usr/bin/env bash
# Runs every test of aloft, in stages, and prints how long each took
# (docs/architecture.md, "Tests and CI stages", says which stage runs which test):
#   host        gcc, Release: the whole host suite, with the tests labelled `slow`
#               (statistical and long tests, cmake/aloft_tests.cmake), run only here
#   host-asan   clang, ASan + UBSan with -fno-sanitize-recover=all: the second compiler
#               (the whole tree builds warning-free with both), the host suite under the
#               sanitizers with one small case of each slow test in place of the whole,
#               the fuzz regression corpus, then each libFuzzer harness for
#               ALOFT_FUZZ_SECONDS (default 30) from its corpus
#   armhf       the core suite on 32-bit ARM Linux under qemu-arm
#   cortex-m4f  the core suite and the heap probes on bare metal, the example and replay
#               firmware, under QEMU mps2-an386
#   stm32f405   the STM32F405 flight firmware under QEMU netduinoplus2 and its footprint
# scripts/test.sh --quick: the quick tier to run while working, the host stage without
# the tests labelled `slow` (their small cases still run).
# A failed test, a compiler warning, a sanitizer report or a fuzzer finding fails the run:
# every stage configures with CMAKE_COMPILE_WARNING_AS_ERROR=$ALOFT_WARNINGS_AS_ERRORS
# (default ON). The presets leave it OFF, so that a user's build of the program
# (scripts/study.sh) never stops on a newer compiler's new warning.
# Compiles through ccache when it is installed (a warm cache turns most compiles into
# hits; without it the build is the same, only slower). Installs what it needs.
set -euo pipefail
cd "$(dirname "$0")/.."
quick=false
case "${1:-}" in
  --quick) quick=true ;;
  "") ;;
  *) echo "usage: $0 [--quick]" >&2; exit 2 ;;
esac
if $quick; then scripts/install-deps.sh host; else scripts/install-deps.sh all; fi
jobs=$(nproc)
fuzz_seconds=${ALOFT_FUZZ_SECONDS:-30}
warnings_as_errors=${ALOFT_WARNINGS_AS_ERRORS:-ON}
timings=()

# An empty launcher when ccache is absent, so a build folder configured with it earlier
# does not fail once it is gone. The paths under the clone are hashed relative to it
# (CCACHE_BASEDIR) and the build folder is left out of the hash (CCACHE_NOHASHDIR: the
# host-asan build has debug info), so two clones of the tree share their hits.
launcher=""
if command -v ccache >/dev/null 2>&1; then
  launcher=ccache
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
  export CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-true}
fi

stage() {  # stage NAME COMMAND...: runs and times one stage
  local name=$1 start=$SECONDS
  shift
  echo "== $name ==" >&2
  "$@"
  timings+=("$(printf '%-22s %4d s' "$name" $((SECONDS - start)))")
}

build_and_test() {  # build_and_test CONFIGURE_PRESET TEST_PRESET...
  local preset=$1
  shift
  cmake --preset "$preset" -DCMAKE_COMPILE_WARNING_AS_ERROR="$warnings_as_errors" \
    -DCMAKE_C_COMPILER_LAUNCHER="$launcher" -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" \
    "${configure_args[@]}"
  cmake --build --preset "$preset"
  for test_preset in "$@"; do ctest --preset "$test_preset" -j "$jobs"; done
}

configure_args=()
if $quick; then
  stage quick build_and_test host quick
else
  stage host build_and_test host host
  configure_args=(-DALOFT_FUZZ_SECONDS="$fuzz_seconds")
  stage host-asan build_and_test host-asan host-asan host-asan-fuzz
  configure_args=()
  stage armhf build_and_test armhf armhf
  stage cortex-m4f build_and_test cortex-m4f cortex-m4f
  stage stm32f405 build_and_test stm32f405 stm32f405
fi

echo "== stage times ==" >&2
printf '%s\n' "${timings[@]}" >&2
echo "total                  $SECONDS s" >&2
