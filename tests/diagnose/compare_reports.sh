#!/usr/bin/env bash
# Compares two folders written by make_reports.sh byte for byte: every NAME.json,
# NAME.txt and NAME.rc of REF_DIR must exist in NEW_DIR with the same bytes, and NEW_DIR
# must hold no trial REF_DIR lacks. Prints one line per difference and a count.
#
# Usage: tests/diagnose/compare_reports.sh REF_DIR NEW_DIR
# Exit 0 when identical, 1 on any difference, 2 on bad use.
set -euo pipefail
ref=${1:?usage: compare_reports.sh REF_DIR NEW_DIR}
new=${2:?usage: compare_reports.sh REF_DIR NEW_DIR}
for d in "$ref" "$new"; do
  [ -d "$d" ] || { echo "compare_reports: $d: not a folder" >&2; exit 2; }
done
compared=0
differ=0
trials=0
for rc in "$ref"/*.rc; do
  [ -e "$rc" ] || { echo "compare_reports: $ref holds no reports" >&2; exit 2; }
  name=$(basename "$rc" .rc)
  trials=$((trials + 1))
  for ext in rc txt json; do
    [ -e "$ref/$name.$ext" ] || [ -e "$new/$name.$ext" ] || continue
    compared=$((compared + 1))
    if ! cmp -s "$ref/$name.$ext" "$new/$name.$ext"; then
      echo "differs: $name.$ext"
      differ=$((differ + 1))
    fi
  done
done
for rc in "$new"/*.rc; do
  name=$(basename "$rc" .rc)
  if [ ! -e "$ref/$name.rc" ]; then
    echo "differs: $name only in $new"
    differ=$((differ + 1))
  fi
done
echo "compare_reports: $trials trials, $compared files compared, $differ differ"
[ "$differ" -eq 0 ]
