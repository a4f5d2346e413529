#!/usr/bin/env bash
# A spin-up session whose body file names the wheel and whose log gives its speed (what a
# user with a logged reaction wheel hands `aloft diagnose`): the report sets the log's h
# beside the h it found at each flight's end and at the headline's, and on the generator's
# session they agree (found 0.98-1.02 times the log's, under a degree apart), while the
# verdict is the one the same session gives without the wheel's files (diagnose leaves the
# body file's rotor out of its model).
#
# Usage: logged_rotor_report.sh ALOFT GENERATOR
set -euo pipefail
aloft=${1:?usage: logged_rotor_report.sh ALOFT GENERATOR}
generator=${2:?usage: logged_rotor_report.sh ALOFT GENERATOR}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$generator" --out "$dir/with" --flight-controller --log-rotor >/dev/null
"$generator" --out "$dir/without" --flight-controller >/dev/null
for kind in with without; do
  s="$dir/$kind/spin_up_0"
  "$aloft" diagnose --body "$s/body.json" --imu "$s/imu.csv" --segments "$s/segments.csv" >"$dir/$kind.txt"
done
grep -q '"rotor"' "$dir/with/spin_up_0/body.json" && head -1 "$dir/with/spin_up_0/imu.csv" | grep -q rotor_rad_s
agree="the log's rotor [0-9.e-]* N m s there: found (0\.9[89]|1\.0[0-2]) x it, 0\.[0-9] deg apart"
found=$(grep -oE "$agree" "$dir/with.txt" | wc -l)
flights=$(grep -c "^  flight flight[0-9]*: .*; the log's rotor |h| [0-9.e-]* N m s at its end$" "$dir/with.txt" || true)
echo "logged_rotor_report: $found agreeing comparisons (the headline and 4 flights), $flights flight lines"
[ "$found" -eq 5 ] && [ "$flights" -eq 4 ] || { cat "$dir/with.txt"; exit 1; }
# Everything else word for word the same.
diff <(sed -e "s/, the log's rotor [^;)]*//g" -e "s/; the log's rotor |h| .* at its end$//" "$dir/with.txt") \
  "$dir/without.txt"
