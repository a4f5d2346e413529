#!/usr/bin/env bash
# diagnose_compare_verdicts on a verdict's held-out error after: where the candidate the
# verdict took is not identifiable it is compared to 1e-3 (a difference of 3e-5 agrees, of
# 1e-2 does not); where it is identifiable, to the relative tolerance (3e-5 is a difference).
# Usage: compare_verdicts_unidentifiable.sh COMPARE_VERDICTS WORK_DIR
set -euo pipefail
compare=$1
work=$2
rm -rf "$work" && mkdir -p "$work/a" "$work/b"
report() { # IDENTIFIABLE ERROR_AFTER
  echo "{\"verdict\":{\"effect\":\"internal_momentum\",\"params\":{\"profile\":\"p\"},\"heldout_rms_rel_err_after\":$2},\"candidates\":[{\"effect\":\"internal_momentum\",\"params\":{\"profile\":\"p\"},\"identifiable\":$1,\"score\":1.0}]}"
}
expect() { # STATUS WHY
  local status=0
  "$compare" "$work/a" "$work/b" >/dev/null || status=$?
  [ "$status" -eq "$1" ] || { echo "FAIL: $2 (exit $status)"; exit 1; }
}
report false 0.001 > "$work/a/flight.json"
report false 0.00100003 > "$work/b/flight.json"
expect 0 "an unidentifiable verdict's errors 3e-5 apart should agree"
report false 0.00101 > "$work/b/flight.json"
expect 1 "an unidentifiable verdict's errors 1e-2 apart should differ"
report true 0.001 > "$work/a/flight.json"
report true 0.00100003 > "$work/b/flight.json"
expect 1 "an identifiable verdict's errors 3e-5 apart should differ"
echo "PASS"
