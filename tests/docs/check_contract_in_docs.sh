#!/usr/bin/env bash
# The contract lives in the repository (issue 26 item 5): every report key and effect
# name of the outside interface contract (../shared/SPEC.md, which a user who clones the
# repository does not have) is written in docs/file-formats.md. Prints each one missing
# and exits 1 if any is; exits 77 (skipped) when SPEC.md is not beside the repository.
#   tests/docs/check_contract_in_docs.sh REPO_DIR
set -euo pipefail
repo=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
spec="$repo/../shared/SPEC.md"
[ -f "$spec" ] || { echo "no $spec: skipped"; exit 77; }
docs="$repo/docs/file-formats.md"
# Quoted JSON keys in the contract's examples, and the effect names of its table.
mapfile -t words < <({ grep -o '"[a-z][a-z0-9_]*":' "$spec" | tr -d '":'
                       grep -o '^| `[a-z_]*`' "$spec" | tr -d '|` '; } | sort -u)
missing=0
for w in "${words[@]}"; do
  grep -q -- "$w" "$docs" || { echo "docs/file-formats.md does not name $w"; missing=$((missing + 1)); }
done
echo "${#words[@]} keys and effect names of the contract, $missing missing from docs/file-formats.md"
[ "$missing" -eq 0 ]
