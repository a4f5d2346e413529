#!/usr/bin/env bash
# The same verdict on every CPU (issue 30): `aloft diagnose` on the withheld-effect flights
# of the generator (70, every effect and noise-only), its five flight-controller sessions (1-8
# kHz logs behind a PT1: a spin-up rotor and its look-alikes, issue 44: the noise
# spectrum's fit and the filter's bend run there) and, where ../shared is present, the
# 16 flights of ../shared/data/practice, once per libm dispatch target, and the verdicts
# compared (diagnose_compare_verdicts: identical verdicts, scores within the ranking's
# rounding tolerance, held-out errors within 1e-4 relative: compare_verdicts.cpp says why).
#
# diagnose has no SIMD dispatch of its own; what differs between CPUs is glibc's libm,
# which picks sin/cos/exp/log/pow/atan2 by the CPU (ifunc: an FMA+AVX2 build or the SSE2
# one). GLIBC_TUNABLES=glibc.cpu.hwcaps=-X masks feature X from that choice (glibc 2.33
# and later name features plainly: AVX2, FMA, AVX512F; the older AVX2_Usable names are
# silently ignored by 2.36). The three targets:
#   baseline  -AVX2,-FMA,-AVX512F,...: the SSE2 libm (what qemu-x86_64 -cpu Nehalem gets)
#   avx2      -AVX512F,...: the FMA libm (what -cpu Haswell gets)
#   avx512    no mask (this CPU; libm has no AVX-512 variant of these functions, so its
#             reports are avx2's when the probe below finds the same last bits)
# The script checks that a mask reached libm (diagnose_compare_verdicts --libm-probe gives
# other last bits) and says so when this CPU has no FMA, so that only one path is run.
#
# Usage: same_verdict_every_cpu.sh ALOFT GENERATOR COMPARE OUT_DIR [SHARED_DIR]
# Exit 0: every target gave the same verdicts; 1: they differ; 2: bad use.
set -euo pipefail
aloft=${1:?usage: same_verdict_every_cpu.sh ALOFT GENERATOR COMPARE OUT_DIR [SHARED_DIR]}
generator=${2:?}
compare=${3:?}
out=${4:?}
shared=${5:-}
for p in "$aloft" "$generator" "$compare"; do
  [ -x "$p" ] || { echo "same_verdict_every_cpu: $p: not an executable" >&2; exit 2; }
done
rm -rf "$out"
mkdir -p "$out/flights"
"$generator" --out "$out/flights" >/dev/null
"$generator" --out "$out/sessions" --flight-controller >/dev/null

# One line per flight or session: NAME BODY --imu|--markers FILE [--segments FILE]
list="$out/flights.txt"
: >"$list"
add_flights() {  # add_flights PREFIX DIR...
  local prefix=$1
  shift
  for dir in "$@"; do
    dir=${dir%/}
    [ -f "$dir/body.json" ] || continue
    if [ -f "$dir/markers.trc" ]; then
      echo "$prefix$(basename "$dir") $dir/body.json --markers $dir/markers.trc" >>"$list"
    elif [ -f "$dir/imu.csv" ] && [ ! -f "$dir/segments.csv" ]; then
      echo "$prefix$(basename "$dir") $dir/body.json --imu $dir/imu.csv" >>"$list"
    fi
  done
}
add_flights "" "$out"/flights/*/
for dir in "$out"/sessions/*/; do
  dir=${dir%/}
  echo "fc-$(basename "$dir") $dir/body.json --imu $dir/imu.csv --segments $dir/segments.csv" >>"$list"
done
if [ -n "$shared" ] && [ -d "$shared/data/practice" ]; then
  add_flights practice- "$shared"/data/practice/*/
else
  echo "same_verdict_every_cpu: ${shared:-../shared}/data/practice absent: the practice flights are skipped," \
    "only the generated ones are compared"
fi

hwcaps_baseline="glibc.cpu.hwcaps=-AVX2,-FMA,-AVX512F,-AVX512DQ,-AVX512CD,-AVX512BW,-AVX512VL"
hwcaps_avx2="glibc.cpu.hwcaps=-AVX512F,-AVX512DQ,-AVX512CD,-AVX512BW,-AVX512VL"
targets="baseline avx2 avx512"
tunables_of() {
  case $1 in
    baseline) echo "$hwcaps_baseline" ;;
    avx2) echo "$hwcaps_avx2" ;;
    *) echo "" ;;
  esac
}

for t in $targets; do
  echo "$t libm probe: $(GLIBC_TUNABLES=$(tunables_of "$t") "$compare" --libm-probe)" >>"$out/probe.txt"
done
if grep -qw fma /proc/cpuinfo 2>/dev/null && grep -qw avx2 /proc/cpuinfo 2>/dev/null; then
  if [ "$(sed -n 1p "$out/probe.txt" | cut -d: -f2)" = "$(sed -n 2p "$out/probe.txt" | cut -d: -f2)" ]; then
    echo "same_verdict_every_cpu: GLIBC_TUNABLES did not change libm's results (not glibc >= 2.33?):" >&2
    cat "$out/probe.txt" >&2
    exit 1
  fi
else
  echo "same_verdict_every_cpu: this CPU has no FMA/AVX2: every target runs the SSE2 libm"
fi
cat "$out/probe.txt"

# Two at a time: the machine has two cores. A target whose libm gives the same last bits
# as one already run (the probe's hash; here AVX-512 beside AVX2: libm has no AVX-512
# variant of these functions) runs the same arithmetic, so that target's reports are
# reused rather than made again.
for t in $targets; do
  mkdir -p "$out/$t"
  hash=$(grep "^$t libm probe" "$out/probe.txt" | cut -d: -f2)
  same=$(grep -v "^$t libm probe" "$out/probe.txt" | grep -- "$hash\$" | head -1 | cut -d' ' -f1 || true)
  if [ -n "$same" ] && [ -n "$(ls "$out/$same" 2>/dev/null)" ]; then
    echo "same_verdict_every_cpu: $t: libm identical to $same's (probe hash$hash): its reports are $same's"
    cp "$out/$same"/* "$out/$t"/
    continue
  fi
  export ALOFT_TUNABLES_FOR_RUN
  ALOFT_TUNABLES_FOR_RUN=$(tunables_of "$t")
  # Each line's fields: the name, the body, the data's options, and the folder to write into.
  xargs -P 2 -L 1 bash -c 'dest=${!#}; GLIBC_TUNABLES=$ALOFT_TUNABLES_FOR_RUN "$0" diagnose --body "$2" \
      "${@:3:$#-3}" --json "$dest/$1.json" >"$dest/$1.txt" 2>&1 || true' "$aloft" <<<"$(sed "s|\$| $out/$t|" "$list")"
done
status=0
"$compare" "$out/baseline" "$out/avx2" || status=1
"$compare" "$out/avx512" "$out/avx2" || status=1
echo "same_verdict_every_cpu: $(wc -l <"$list") flights and sessions under $targets"
exit $status
