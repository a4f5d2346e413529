#!/usr/bin/env bash
# Issue 30 item 4's goals, measured for this tree and for an earlier commit side by side
# in the same run (benchmarks, not timed tests):
#   one flight        `aloft diagnose` of practice/case00 (1.2 s at 1 kHz, one thread)
#                     under callgrind: instructions (repeatable whatever the load), goal
#                     <= 300 M, with its verdict line;
#   60-flight session diagnose_benchmark's session_of_60 on 2 threads: wall, and the CPU
#                     of the whole process (/usr/bin/time), goal <= 5 s wall;
#   10-minute log     200 throws at 1 kHz through `aloft diagnose --segments` on 2 threads
#                     (long_log_benchmark.sh's log), goal <= 15 s wall.
# The earlier commit (default HEAD~1) is built in a temporary worktree beside this
# checkout (so that a ccache with CCACHE_BASEDIR above both reuses this tree's objects),
# removed at the end. The two builds
# run one after the other for each case, so both see the same machine; the load average
# is printed with each wall time (CPU time is the steadier figure on a shared machine).
#
# Usage, from the source tree after building this tree's programs
# (cmake --build --preset host --target aloft diagnose_benchmark aloft_long_session_log):
#   tests/diagnose/speed_against_commit.sh [COMMIT [SHARED_DIR]]   (default HEAD~1, ../shared)
set -euo pipefail
commit=${1:-HEAD~1}
shared=${2:-../shared}
case00="$shared/data/practice/case00"
[ -f "$case00/imu.csv" ] || { echo "speed_against_commit: $case00: not found" >&2; exit 2; }
for tool in valgrind callgrind_annotate /usr/bin/time; do
  command -v "$tool" >/dev/null || { echo "speed_against_commit: $tool: not installed" >&2; exit 2; }
done
targets=(aloft diagnose_benchmark aloft_long_session_log)
this_build=build/host
peer_tree=$(mktemp -d "$(cd .. && pwd)/aloft-speed-peer.XXXXXX")
work=$(mktemp -d)
trap 'git worktree remove --force "$peer_tree" >/dev/null 2>&1 || true; rm -rf "$peer_tree" "$work"' EXIT

rmdir "$peer_tree"
git worktree add --detach "$peer_tree" "$commit" >/dev/null
echo "building $commit ($(git rev-parse --short "$commit")) in $peer_tree ..." >&2
(cd "$peer_tree" && cmake --preset host >/dev/null && cmake --build --preset host -j2 --target "${targets[@]}" >/dev/null)
peer_build="$peer_tree/build/host"
for build in "$this_build" "$peer_build"; do
  for program in host_sim/aloft tests/diagnose/diagnose_benchmark tests/diagnose/generator/aloft_long_session_log; do
    [ -x "$build/$program" ] || { echo "speed_against_commit: $build/$program: not built" >&2; exit 2; }
  done
done

# Instructions of one flight, and its verdict line.
one_flight() {
  local build=$1 out="$work/cg.$RANDOM"
  valgrind --tool=callgrind --callgrind-out-file="$out" "$build/host_sim/aloft" diagnose \
    --body "$case00/body.json" --imu "$case00/imu.csv" --threads 1 >"$out.txt" 2>/dev/null
  local ir
  ir=$(callgrind_annotate "$out" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
  printf '%s %s\n' "$ir" "$(grep -m1 -o 'verdict: [a-z_]*' "$out.txt" || echo 'verdict: ?')"
}

# Wall and whole-process CPU seconds of a command, after the load average.
timed() {
  local out="$work/time.$RANDOM"
  /usr/bin/time -v "$@" >/dev/null 2>"$out"
  awk -F': ' '/Elapsed/ {n = split($2, a, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + a[i]; w = s}
              /User time|System time/ {c += $2}
              END {printf "%.1f %.1f\n", w, c}' "$out"
}

session_of_60() {
  timed "$1/tests/diagnose/diagnose_benchmark" --benchmark_filter=session_of_60
}

log_of_200() {
  local build=$1 log="$work/log200"
  [ -d "$log" ] || "$this_build/tests/diagnose/generator/aloft_long_session_log" --out "$log" --flights 200 >/dev/null
  timed "$build/host_sim/aloft" diagnose --body "$log/body.json" --imu "$log/imu.csv" \
    --segments "$log/segments.csv" --threads 2 --json "$work/report.$RANDOM.json"
}

load() { awk '{print $1}' /proc/loadavg; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", (a > 0 ? b / a : 0)}'; }

read -r ir_this verdict_this < <(one_flight "$this_build")
read -r ir_peer verdict_peer < <(one_flight "$peer_build")
printf '%-34s %16s %16s %8s  %s\n' "case" "this tree" "$commit" "peer/this" "goal"
printf '%-34s %14s M %14s M %8s  <= 300 M: %s\n' "one flight, instructions" \
  "$((ir_this / 1000000))" "$((ir_peer / 1000000))" "$(ratio "$ir_this" "$ir_peer")" \
  "$([ "$ir_this" -le 300000000 ] && echo met || echo 'NOT met')"
printf '%-34s %16s %16s\n' "one flight, verdict" "${verdict_this#verdict: }" "${verdict_peer#verdict: }"

for case in session_of_60 log_of_200; do
  l1=$(load); read -r wall_this cpu_this < <($case "$this_build")
  l2=$(load); read -r wall_peer cpu_peer < <($case "$peer_build")
  goal=$([ $case = session_of_60 ] && echo 5 || echo 15)
  printf '%-34s %10s s wall %10s s wall %8s  <= %s s: %s (load %s, %s)\n' "$case" "$wall_this" "$wall_peer" \
    "$(ratio "$wall_this" "$wall_peer")" "$goal" \
    "$(awk -v w="$wall_this" -v g="$goal" 'BEGIN {print (w <= g ? "met" : "NOT met")}')" "$l1" "$l2"
  printf '%-34s %11s s CPU %11s s CPU %8s\n' "" "$cpu_this" "$cpu_peer" "$(ratio "$cpu_this" "$cpu_peer")"
done
