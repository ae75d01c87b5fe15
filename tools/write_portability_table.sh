#!/usr/bin/env bash
# Writes the measured table of docs/portability.md from the rows the conformance runs wrote
# (portability_rows.md under each run's output directory: build/test-output/<run>/ and
# build/test-output-swiftshader/<run>/), between its "measured: begin" and "measured: end" lines.
#   tools/write_portability_table.sh [BUILD_DIR] [DOC]
# Run the test command first (every backend, both drivers, both tiers).
set -euo pipefail
build=${1:-build} doc=${2:-docs/portability.md}
shopt -s nullglob
files=("$build"/test-output/*/portability_rows.md "$build"/test-output-swiftshader/*/portability_rows.md)
if [ ${#files[@]} -eq 0 ]; then
  echo "write_portability_table: no portability_rows.md under $build: run the conformance tests first" >&2
  exit 1
fi
table=$(mktemp)
{
  echo '| driver | backend | tier | effect | worst pixel | mean error |'
  echo '|---|---|---|---|---|---|'
  cat "${files[@]}" | LC_ALL=C sort -t'|' -k5,5 -k2,2 -k3,3 -k4,4
} > "$table"
awk -v table="$table" '
  /<!-- measured: begin -->/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
  /<!-- measured: end -->/ { skip = 0 }
  !skip { print }' "$doc" > "$doc.new"
mv "$doc.new" "$doc"
rm -f "$table"
echo "write_portability_table: $(cat "${files[@]}" | wc -l) rows from ${#files[@]} runs into $doc"
