#!/bin/sh
# Every `$ aloft replay ...` shown in README.md and docs/ is followed, up to the code block's
# end, by exactly what the program prints for it (run from the repository's root; a
# `--json FILE` goes to a scratch directory instead). Usage: check_shown_replay_output.sh
# ALOFT SOURCE_DIR
set -eu
aloft=$1
source_dir=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
checked=0
failed=0
for page in "$source_dir/README.md" "$source_dir"/docs/*.md; do
  # Each shown command and the lines after it, one pair of files per block.
  awk -v out="$scratch/block" '
    /^\$ aloft replay / { n++; cmd = out n ".cmd"; shown = out n ".shown"; sub(/^\$ aloft /, ""); print > cmd; close(cmd); printf "" > shown; inside = 1; next }
    inside && /^```/ { close(shown); inside = 0; next }
    inside { print >> shown }
  ' "$page"
  for cmd in "$scratch"/block*.cmd; do
    [ -e "$cmd" ] || continue
    shown=${cmd%.cmd}.shown
    arguments=$(sed "s|--json [^ ]*|--json $scratch/report.json|" "$cmd")
    # shellcheck disable=SC2086 # the arguments are words of the shown command
    (cd "$source_dir" && "$aloft" $arguments) > "$scratch/printed" 2>&1 || true
    checked=$((checked + 1))
    if ! diff -u "$shown" "$scratch/printed" > "$scratch/diff"; then
      echo "${page#"$source_dir"/}: \`aloft $(cat "$cmd")\` prints otherwise than shown:"
      cat "$scratch/diff"
      failed=$((failed + 1))
    fi
    rm -f "$cmd" "$shown"
  done
done
echo "shown replay outputs checked: $checked, differing: $failed"
[ "$checked" -gt 0 ] && [ "$failed" -eq 0 ]
