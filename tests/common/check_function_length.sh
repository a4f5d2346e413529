#!/usr/bin/env bash
# No function in lib/, port/, host_sim/ or tests/ longer than 80 lines: a function that
# long does more than one thing, and its parts want names of their own.
#
# A heuristic, not a parser: comments, strings, character literals and preprocessor lines
# are skipped, and braces are matched. A brace opened where only namespaces, classes and
# `extern "C"` blocks are open is a function body when the text before it (since the
# last `;`, `{` or `}`, template parameter lists left out) has a `)` and neither ends in
# `=` (an initializer) nor starts with namespace, class, struct, union or enum; braces
# inside any other block (initializers, enums) are never a function body. Its
# length runs from the first line of the signature to the closing brace. Lambdas and
# blocks inside a function count towards that function.
#
# Prints each function over the limit as FILE:LINE: NAME: N lines, and exits 1 if any.
# Usage: tests/common/check_function_length.sh [SOURCE_DIR [MAX_LINES]]
#   (default: this checkout, 80)
set -euo pipefail
src=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
max=${2:-80}
folders=(lib port host_sim tests)
for folder in "${folders[@]}"; do
  [ -d "$src/$folder" ] || { echo "check_function_length: $src/$folder: absent" >&2; exit 2; }
done
cd "$src"

find "${folders[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.c' -o -name '*.h' \) | sort | xargs awk -v max="$max" '
function reset_header() { header = ""; header_line = 0 }
# The header without template parameter lists, so that "template <class T>" is no class.
function without_templates(h,    out, i, c, depth, rest) {
  out = ""
  while (match(h, /template[ \t]*</)) {
    out = out substr(h, 1, RSTART - 1)
    rest = substr(h, RSTART + RLENGTH)
    depth = 1
    for (i = 1; i <= length(rest) && depth > 0; i++) {
      c = substr(rest, i, 1)
      if (c == "<") depth++
      else if (c == ">") depth--
    }
    h = substr(rest, i)
  }
  return out h
}
function kind_of(h,    t) {
  t = without_templates(h)
  sub(/^[ \t]+/, "", t); sub(/[ \t]+$/, "", t)
  if (t ~ /^(extern[ \t]*|inline[ \t]+namespace|namespace)([^A-Za-z0-9_]|$)/) return "scope"
  if (t ~ /^(class|struct|union)([^A-Za-z0-9_]|$)/ && t !~ /^[^(]*\)/) return "scope"
  if (t ~ /^enum([^A-Za-z0-9_]|$)/) return "other"
  if (t ~ /=$/) return "other"
  if (index(t, ")") > 0) return "function"
  return "other"
}
function name_of(h,    t) {
  t = without_templates(h)
  sub(/\(.*$/, "", t)                      # the name stands just before the first "("
  gsub(/[ \t]+$/, "", t)
  n = split(t, parts, /[ \t*&]+/)
  return parts[n]
}
FNR == 1 { depth = 0; opaque = 0; state = "code"; reset_header(); func_depth = -1 }
{
  line = $0
  if (state == "code" && line ~ /^[ \t]*#/) { reset_header(); next }
  len = length(line)
  for (i = 1; i <= len; i++) {
    c = substr(line, i, 1)
    if (state == "block") {
      if (c == "*" && substr(line, i + 1, 1) == "/") { state = "code"; i++ }
      continue
    }
    if (state == "string" || state == "char") {
      if (c == "\\") { i++; continue }
      if ((state == "string" && c == "\"") || (state == "char" && c == "\047")) state = "code"
      continue
    }
    if (c == "/" && substr(line, i + 1, 1) == "/") break
    if (c == "/" && substr(line, i + 1, 1) == "*") { state = "block"; i++; continue }
    if (c == "\"") { state = "string"; continue }
    # A quote between digits is a digit separator (1\0470000), not a character literal.
    if (c == "\047") {
      if (i > 1 && substr(line, i - 1, 1) ~ /[0-9A-Fa-f]/ && substr(line, i + 1, 1) ~ /[0-9A-Fa-f]/) continue
      state = "char"; continue
    }
    if (c == "{") {
      k = "other"
      if (func_depth < 0 && opaque == 0) {
        k = kind_of(header)
        if (k == "function") { func_depth = depth; func_line = header_line; func_name = name_of(header) }
      }
      depth++
      kinds[depth] = k
      if (k == "other") opaque++
      reset_header()
      continue
    }
    if (c == "}") {
      if (kinds[depth] == "other") opaque--
      depth--
      if (func_depth >= 0 && depth == func_depth) {
        n = FNR - func_line + 1
        if (n > max) { printf "%s:%d: %s: %d lines\n", FILENAME, func_line, func_name, n; over++ }
        functions++
        func_depth = -1
      }
      reset_header()
      continue
    }
    if (c == ";") { reset_header(); continue }
    if (c == ":" && header ~ /^[ \t]*(public|private|protected)[ \t]*$/) { reset_header(); continue }
    if (c !~ /[ \t]/ && header_line == 0) header_line = FNR
    header = header c
  }
  if (state == "string" || state == "char") state = "code"  # no literal spans lines
  header = header " "
}
END {
  printf "check_function_length: %d functions, %d over %d lines\n", functions, over + 0, max
  exit over > 0
}'
