#!/usr/bin/env bash
# Checks that every C and C++ file git tracks follows .clang-format; with --fix, formats
# them in place instead.
#   scripts/check-format.sh [--fix] [CLANG_FORMAT]   (default: clang-format-14)
# Exit 0: the tree follows it (or was fixed); 1: files to format (they are listed).
set -euo pipefail
fix=0
if [ "${1:-}" = "--fix" ]; then fix=1; shift; fi
clang_format="${1:-clang-format-14}"
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.c')
if [ "$fix" -eq 1 ]; then
  "$clang_format" -i "${files[@]}"
  exit 0
fi
# One run over every file; each unformatted line is reported as FILE:LINE:COL: ...
mapfile -t unformatted < <("$clang_format" --dry-run "${files[@]}" 2>&1 |
  sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: .*/\1/p' | sort -u)
if [ ${#unformatted[@]} -gt 0 ]; then
  echo "${#unformatted[@]} files not formatted as .clang-format says (fix: scripts/check-format.sh --fix):" >&2
  printf '  %s\n' "${unformatted[@]}" >&2
  exit 1
fi
echo "${#files[@]} files follow .clang-format"
