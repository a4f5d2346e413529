#!/usr/bin/env bash
# Speed and memory of `aloft diagnose --segments` on one long IMU log (issue 12 item 7):
# 200 throws of 1 s at 1 kHz with 2 s of rest before each (10 minutes, 600,200 samples),
# written by aloft_long_session_log and timed end to end with /usr/bin/time -v (wall,
# CPU, peak resident memory). The peer in the same run is a log of 60 throws: the ratio
# shows how the time grows with the flights (3.3x would be linear). The bar, issue 8's
# "60 flights <= 30 s on 2 threads" taken in proportion: 200 flights <= 100 s wall.
# The machine's load average is printed before and after: wall time on a shared machine
# says little without it (CPU time is the steadier figure).
#
# Usage, from the source tree after building the two programs
# (cmake --build --preset host --target aloft aloft_long_session_log):
#   tests/diagnose/long_log_benchmark.sh [BUILD_DIR [THREADS]]     (default build/host, 2)
set -euo pipefail
build=${1:-build/host}
threads=${2:-2}
writer="$build/tests/diagnose/generator/aloft_long_session_log"
aloft="$build/host_sim/aloft"
for program in "$writer" "$aloft"; do
  [ -x "$program" ] || { echo "long_log_benchmark: $program: not built" >&2; exit 2; }
done
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

declare -A wall_of
run() {
  local flights=$1 out="$dir/log$1"
  "$writer" --out "$out" --flights "$flights" >/dev/null
  /usr/bin/time -v "$aloft" diagnose --body "$out/body.json" --imu "$out/imu.csv" --segments "$out/segments.csv" \
    --threads "$threads" --json "$out/report.json" >"$out/summary.txt" 2>"$out/time.txt"
  local wall cpu rss verdict
  wall=$(awk -F': ' '/Elapsed/ {n = split($2, a, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + a[i]; print s}' "$out/time.txt")
  cpu=$(awk -F': ' '/User time|System time/ {s += $2} END {print s}' "$out/time.txt")
  rss=$(awk -F': ' '/Maximum resident/ {printf "%.0f", $2 / 1024}' "$out/time.txt")
  verdict=$(grep -m1 -o 'verdict: [a-z_]*' "$out/summary.txt" || echo "verdict: ?")
  wall_of[$flights]=$wall
  printf '%4d flights (%s s of log): %7.1f s wall, %7.1f s CPU, peak RSS %4d MB, %s\n' \
    "$flights" "$((flights * 3))" "$wall" "$cpu" "$rss" "$verdict"
}

echo "load before: $(uptime)"
run 60
run 200
echo "load after:  $(uptime)"
awk -v a="${wall_of[200]}" -v b="${wall_of[60]}" 'BEGIN {printf "200 / 60 flights: %.2fx the wall time (3.33x: linear)\n", a / b}'
awk -v w="${wall_of[200]}" -v t="$threads" 'BEGIN {printf "bar (200 flights <= 100 s wall on 2 threads): %s (%.1f s on %d threads)\n", (w <= 100 ? "met" : "NOT met"), w, t}'
