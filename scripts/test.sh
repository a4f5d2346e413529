#!/usr/bin/env bash
# Runs every test of aloft, in stages, and prints how long each took:
#   host        gcc, Release: the host suite (lib/, host program, benchmarks as smoke runs)
#   host-asan   clang, ASan + UBSan with -fno-sanitize-recover=all: the second compiler
#               (the whole tree builds warning-free with both),
#               the host suite under the sanitizers, the fuzz regression corpus, then
#               each libFuzzer harness for ALOFT_FUZZ_SECONDS (default 30) from its corpus
#   armhf, cortex-m4f   the core suite on the ARM targets under QEMU
#   stm32f405   the STM32F405 flight firmware under QEMU netduinoplus2 and its footprint
# A failed test, a compiler warning, a sanitizer report or a fuzzer finding fails the run:
# every stage configures with CMAKE_COMPILE_WARNING_AS_ERROR=$ALOFT_WARNINGS_AS_ERRORS (default
# ON; the presets set it too; the project's CMake never forces -Werror on a consumer).
# Installs what it needs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh all
jobs=$(nproc)
fuzz_seconds=${ALOFT_FUZZ_SECONDS:-30}
warnings_as_errors=${ALOFT_WARNINGS_AS_ERRORS:-ON}
timings=()

stage() {  # stage NAME COMMAND...: runs and times one stage
  local name=$1 start=$SECONDS
  shift
  echo "== $name ==" >&2
  "$@"
  timings+=("$(printf '%-22s %4d s' "$name" $((SECONDS - start)))")
}

build_and_test() {  # build_and_test PRESET [TEST PRESET...]
  local preset=$1
  shift
  cmake --preset "$preset" -DCMAKE_COMPILE_WARNING_AS_ERROR="$warnings_as_errors" \
    "${configure_args[@]}"
  cmake --build --preset "$preset"
  for test_preset in "$preset" "$@"; do ctest --preset "$test_preset" -j "$jobs"; done
}

configure_args=()
stage host build_and_test host
configure_args=(-DALOFT_FUZZ_SECONDS="$fuzz_seconds")
stage host-asan build_and_test host-asan host-asan-fuzz
configure_args=()
stage armhf build_and_test armhf
stage cortex-m4f build_and_test cortex-m4f
stage stm32f405 build_and_test stm32f405

echo "== stage times ==" >&2
printf '%s\n' "${timings[@]}" >&2
echo "total                  $SECONDS s" >&2
