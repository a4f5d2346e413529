#!/usr/bin/env bash
# The reports of `aloft diagnose` on every trial and session of the shared data, for
# compare_reports.sh: a refactoring of host_sim/diagnose/ that means to change nothing
# shows it by byte-identical reports before and after (issue 24).
#
# Covered: ../shared/data/practice (one flight per case: imu.csv or markers.trc),
# practice2 and practice3 (with segments.csv a session, else one flight), and the
# racquet sessions of ../shared/data/real/racquet. For each trial NAME the folder OUT_DIR
# gets NAME.json (the --json report), NAME.txt (the summary on stdout) and NAME.rc (the
# exit status; a failure's stderr goes to NAME.txt too), so a refused input is compared
# as well. Warnings on stderr name the files, so make the two folders to compare with
# the same SHARED_DIR.
#
# Usage, from the source tree after `cmake --build --preset host --target aloft`:
#   tests/diagnose/make_reports.sh ALOFT OUT_DIR [SHARED_DIR]
#     ALOFT       the aloft program (e.g. build/host/host_sim/aloft)
#     OUT_DIR     created if missing; keep it outside the repository
#     SHARED_DIR  default ../shared beside the checkout
# Exit 0 when every report was made (whatever each diagnosis exit status), 2 on bad use.
set -euo pipefail
aloft=${1:?usage: make_reports.sh ALOFT OUT_DIR [SHARED_DIR]}
out=${2:?usage: make_reports.sh ALOFT OUT_DIR [SHARED_DIR]}
shared=${3:-$(cd "$(dirname "$0")/../.." && pwd)/../shared}
[ -x "$aloft" ] || { echo "make_reports: $aloft: not an executable" >&2; exit 2; }
data="$shared/data"
[ -d "$data/practice" ] || { echo "make_reports: $data/practice: absent (../shared not beside the checkout)" >&2; exit 2; }
mkdir -p "$out"

# diagnose NAME ARGS...: one run, its report, summary and exit status under NAME.
diagnose() {
  local name=$1
  shift
  local rc=0
  rm -f "$out/$name.json"
  "$aloft" diagnose "$@" --json "$out/$name.json" >"$out/$name.txt" 2>&1 || rc=$?
  echo "$rc" >"$out/$name.rc"
}

for set in practice practice2 practice3; do
  for dir in "$data/$set"/*/; do
    dir=${dir%/}
    name="$set-$(basename "$dir")"
    if [ -f "$dir/markers.trc" ]; then
      diagnose "$name" --body "$dir/body.json" --markers "$dir/markers.trc"
    elif [ -f "$dir/segments.csv" ]; then
      diagnose "$name" --body "$dir/body.json" --imu "$dir/imu.csv" --segments "$dir/segments.csv"
    else
      diagnose "$name" --body "$dir/body.json" --imu "$dir/imu.csv"
    fi
  done
done
racquet="$data/real/racquet"
for dir in "$racquet"/*/; do
  dir=${dir%/}
  diagnose "racquet-$(basename "$dir")" --body "$racquet/body.json" --imu "$dir/gyro.csv" \
    --segments "$dir/segments.csv"
done
echo "make_reports: $(ls "$out"/*.rc | wc -l) trials diagnosed into $out"
