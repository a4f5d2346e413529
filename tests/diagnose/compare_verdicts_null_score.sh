#!/usr/bin/env bash
# diagnose_compare_verdicts on reports whose candidate score is null (a candidate the
# report had no finite score for): two nulls agree (exit 0), a null against a number is a
# difference (exit 1). It crashed on a null score before (nlohmann type_error).
# Usage: compare_verdicts_null_score.sh COMPARE_VERDICTS WORK_DIR
set -euo pipefail
compare=$1
work=$2
rm -rf "$work" && mkdir -p "$work/a" "$work/b"
report() { # SCORE_OF_IMPULSE
  echo "{\"verdict\":{\"effect\":\"none\"},\"candidates\":[{\"effect\":\"impulse\",\"score\":$1},{\"effect\":\"aero_torque\",\"score\":3.0}]}"
}
report null > "$work/a/flight.json"
report null > "$work/b/flight.json"
"$compare" "$work/a" "$work/b" || { echo "FAIL: two null scores should agree"; exit 1; }
report 2.0 > "$work/b/flight.json"
status=0
"$compare" "$work/a" "$work/b" || status=$?
[ "$status" -eq 1 ] || { echo "FAIL: a null against a number should be a difference (exit 1), got $status"; exit 1; }
echo "PASS"
