#!/usr/bin/env bash
# docs/portability.md's measured table must list every (driver, backend, tier, effect) the
# conformance runs of this build wrote (portability_rows.md). The figures themselves are not
# compared: they move in the last digit with the machine's vector width; the page says which
# run wrote them, and tools/write_portability_table.sh rewrites them.
#   check_portability_doc.sh BUILD_DIR DOC
set -euo pipefail
build=$1 doc=$2
shopt -s nullglob
files=("$build"/test-output/*/portability_rows.md "$build"/test-output-swiftshader/*/portability_rows.md)
if [ ${#files[@]} -eq 0 ]; then
  echo "no portability_rows.md under $build: run the conformance tests first" >&2
  exit 1
fi
key() { awk -F' [|] ' '{ sub(/^[|] /, "", $1); print $1 " | " $2 " | " $3 " | " $4 }'; }
missing=$(comm -23 <(cat "${files[@]}" | key | LC_ALL=C sort -u) \
                   <(sed -n '/<!-- measured: begin -->/,/<!-- measured: end -->/p' "$doc" | grep '^| ' | key | LC_ALL=C sort -u))
if [ -n "$missing" ]; then
  echo "docs/portability.md lacks these rows the runs wrote (tools/write_portability_table.sh writes them):" >&2
  echo "$missing" >&2
  exit 1
fi
echo "docs/portability.md lists all $(cat "${files[@]}" | key | sort -u | wc -l) rows the runs wrote"
