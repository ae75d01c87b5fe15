#!/bin/sh
# README.md's "Using it from an engine" code block must be, line for line, the region of
# tests/consumer/main.cpp between "// sfx-readme-begin" and "// sfx-readme-end", which the
# consumer test compiles and runs: so the README's code cannot rot.
#   check_readme_snippet.sh <README.md> <main.cpp>
set -eu
readme=$1 source=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed -n '/^\/\/ sfx-readme-begin$/,/^\/\/ sfx-readme-end$/p' "$source" | sed '1d;$d' >"$tmp/source"
# The block after the marker comment that names the file, up to its closing fence.
awk '/^<!-- compiled: tests\/consumer\/main.cpp/ { marker = 1; next }
     marker && /^```cpp$/ { inside = 1; next }
     inside && /^```$/ { exit }
     inside { print }' "$readme" >"$tmp/readme"
[ -s "$tmp/source" ] || { echo "no sfx-readme region in $source" >&2; exit 1; }
[ -s "$tmp/readme" ] || { echo "no compiled code block in $readme" >&2; exit 1; }
if ! diff -u "$tmp/readme" "$tmp/source"; then
    echo "README.md's engine code differs from $source (diff above: README first)" >&2
    exit 1
fi
echo "README.md's engine code is the compiled region of $source ($(wc -l <"$tmp/source") lines)"
