#!/usr/bin/env bash
# The stages of host_sim/diagnose/ pass data one way (docs/architecture.md, "diagnose: the
# stages"): a file in folder N_<stage> may include only headers of its own folder or of a
# folder with a smaller number, files beside the folders (the command) may include any
# stage, and no set of units includes itself round in a cycle. A unit is a header with
# its source (effect_fit.hpp and effect_fit.cpp are one), so two units that call each
# other through their headers count as a cycle even when no header includes itself.
#
# Reads every `#include "diagnose/..."` line of host_sim/diagnose/**, prints each include
# that runs against the flow and each cycle, and exits 1 if there is any.
# Usage: tests/diagnose/check_stage_includes.sh [SOURCE_DIR]   (default: this checkout)
set -euo pipefail
src=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
root="$src/host_sim/diagnose"
[ -d "$root" ] || { echo "check_stage_includes: $root: absent" >&2; exit 2; }

# rank PATH (relative to host_sim/diagnose): the folder's number, 99 beside the folders.
rank() {
  case $1 in
  [0-9]_*/*) echo "${1%%_*}" ;;
  */*) echo "check_stage_includes: $1: in a folder without a stage number" >&2; echo -1 ;;
  *) echo 99 ;;
  esac
}
unit() { echo "${1%.*}"; }

bad=0
edges=$(mktemp)
trap 'rm -f "$edges"' EXIT
cd "$root"
while IFS= read -r file; do
  file=${file#./}
  from_rank=$(rank "$file")
  [ "$from_rank" -ge 0 ] || { bad=$((bad + 1)); continue; }
  while IFS= read -r target; do
    [ -n "$target" ] || continue
    if [ ! -e "$target" ]; then
      echo "missing: $file includes diagnose/$target, which does not exist"
      bad=$((bad + 1))
      continue
    fi
    to_rank=$(rank "$target")
    if [ "$to_rank" -gt "$from_rank" ]; then
      echo "against the flow: $file includes diagnose/$target (a later stage)"
      bad=$((bad + 1))
    fi
    [ "$(unit "$file")" = "$(unit "$target")" ] || echo "$(unit "$file") $(unit "$target")" >>"$edges"
  done < <(sed -n 's/^#include "diagnose\/\([^"]*\)".*/\1/p' "$file")
done < <(find . -type f \( -name '*.hpp' -o -name '*.cpp' -o -name '*.def' \) | sort)

# tsort names the units on a loop on stderr ("input contains a loop").
if ! loops=$(tsort "$edges" 2>&1 >/dev/null) || [ -n "$loops" ]; then
  echo "cycle among the units:"
  echo "$loops" | grep -v 'input contains a loop' | sed 's/^tsort: /  /'
  bad=$((bad + 1))
fi
units=$(cut -d' ' -f1 "$edges" | sort -u | wc -l)
echo "check_stage_includes: $(wc -l <"$edges") includes between $units units, $bad problem(s)"
[ "$bad" -eq 0 ]
