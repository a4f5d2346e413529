#!/usr/bin/env bash
# A lab's archive on a scheduler (docs/diagnose.md): GNU parallel runs `aloft diagnose` on
# each session with 2 jobs at once; then the same sessions run one after another. There
# must be one report per session, and `aloft summarize` of the two sets must be equal.
#   parallel_archive.sh ALOFT DATA_DIR WORK_DIR SESSION...
# Exit 77 (skipped) when the data folder or GNU parallel is missing.
set -euo pipefail
aloft=$1 data=$2 work=$3
shift 3
if [ ! -d "$data" ]; then echo "skipped: $data not found (../shared beside the tree)"; exit 77; fi
if ! parallel --version 2>/dev/null | grep -q "GNU parallel"; then
  echo "skipped: GNU parallel not installed (scripts/install-deps.sh host)"; exit 77
fi
rm -rf "$work"
mkdir -p "$work/parallel" "$work/serial"
diagnose() {  # diagnose SESSION OUT_DIR
  "$aloft" diagnose --body "$data/$1/body.json" --imu "$data/$1/imu.csv" \
    --segments "$data/$1/segments.csv" --json "$2/$1.json" > /dev/null
}
export -f diagnose
export aloft data
start=$SECONDS
parallel --halt now,fail=1 -j 2 diagnose {} "$work/parallel" ::: "$@"
echo "parallel, 2 jobs: $((SECONDS - start)) s for $# sessions"
start=$SECONDS
for session in "$@"; do diagnose "$session" "$work/serial"; done
echo "serial: $((SECONDS - start)) s"

reports=$(find "$work/parallel" -name '*.json' | wc -l)
if [ "$reports" -ne $# ]; then echo "FAIL: $reports reports for $# sessions"; exit 1; fi
names=("$@")
(cd "$work/parallel" && "$aloft" summarize --flights "${names[@]/%/.json}") > "$work/parallel.csv"
(cd "$work/serial" && "$aloft" summarize --flights "${names[@]/%/.json}") > "$work/serial.csv"
if ! diff "$work/serial.csv" "$work/parallel.csv"; then echo "FAIL: the summaries differ"; exit 1; fi
echo "one report per session ($#); summaries equal ($(($(wc -l < "$work/serial.csv") - 1)) rows)"
cat "$work/serial.csv"
