#!/usr/bin/env bash
# The tree follows .editorconfig and .clang-format: every tracked text file is UTF-8 with LF line
# ends, a final newline, no trailing whitespace and no tab indentation; every C++ file of sdk/,
# tiers/, backends/, tools/, samples/ and tests/ is what clang-format makes of it.
# Usage: check_format.sh <source dir>   (tools/format.sh rewrites the C++ files in place)
set -uo pipefail
cd "$1" || exit 2
clang_format=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$clang_format" ]; then
  echo "check_format: clang-format-14 is not installed (tools/install_deps.sh installs it)"
  exit 1
fi
if ! git rev-parse --git-dir > /dev/null 2>&1; then
  echo "check_format: $1 is not a git checkout; the check reads the tracked files"
  exit 1
fi
failures=0
mapfile -t text_files < <(git ls-files | grep -Ev '\.(png|exr|pfm|obj|svg)$|^tests/fuzz/corpus/')
for f in "${text_files[@]}"; do
  [ -f "$f" ] || continue
  if grep -qI $'\r' "$f"; then echo "$f: CR line ends"; failures=$((failures + 1)); fi
  if [[ "$f" != *.md ]] && grep -nI ' \+$' "$f" | head -1 | grep -q .; then
    echo "$f:$(grep -nI ' \+$' "$f" | head -1 | cut -d: -f1): trailing whitespace"; failures=$((failures + 1))
  fi
  if grep -nIP '^\t' "$f" | head -1 | grep -q .; then
    echo "$f:$(grep -nIP '^\t' "$f" | head -1 | cut -d: -f1): tab indentation"; failures=$((failures + 1))
  fi
  if [ -s "$f" ] && [ -n "$(tail -c1 "$f")" ]; then echo "$f: no final newline"; failures=$((failures + 1)); fi
done
mapfile -t cpp_files < <(git ls-files 'sdk/*.cpp' 'sdk/*.hpp' 'tiers/*.cpp' 'tiers/*.hpp' 'backends/*.cpp' 'backends/*.hpp' \
  'tools/*.cpp' 'tools/*.hpp' 'samples/*.cpp' 'samples/*.hpp' 'tests/*.cpp' 'tests/*.hpp')
for f in "${cpp_files[@]}"; do
  [ -f "$f" ] || continue
  if ! "$clang_format" --style=file --dry-run --Werror "$f" > /dev/null 2>&1; then
    echo "$f: not as clang-format lays it out (run tools/format.sh)"; failures=$((failures + 1))
  fi
done
echo "check_format: ${#text_files[@]} text files and ${#cpp_files[@]} C++ files checked, $failures problem(s)"
[ "$failures" -eq 0 ]
