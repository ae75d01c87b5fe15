#!/usr/bin/env bash
# docs/robustness_extremes.md must hold exactly the rows the extremes conformance cases wrote
# (extremes_rows.md, one file per run of sfx_conformance: BUILD_DIR/test-output/<run>/ and, for
# the runs on SwiftShader, BUILD_DIR/test-output-swiftshader/<run>/; a row's backend column
# names its driver when that is not Mesa's, so each driver's rows are compared apart).
#   check_extremes_doc.sh BUILD_DIR DOC           compare, for every run that wrote rows
#   check_extremes_doc.sh BUILD_DIR DOC --write   regenerate the table in DOC
# A backend or driver that did not run here (its rows file is missing) is not compared.
set -euo pipefail
build=$1 doc=$2 mode=${3:-}
shopt -s nullglob
files=("$build"/test-output/*/extremes_rows.md "$build"/test-output-swiftshader/*/extremes_rows.md)
if [ ${#files[@]} -eq 0 ]; then
  echo "no extremes_rows.md under $build/test-output*: run the conformance tests first" >&2
  exit 1
fi
header='| effect | input | rule | backend | tier | result |
|---|---|---|---|---|---|'
if [ "$mode" = "--write" ]; then
  {
    sed '/^| effect |/,$d' "$doc"
    echo "$header"
    cat "${files[@]}" | LC_ALL=C sort -t'|' -k5,5 -k6,6 -k2,2 -k3,3
  } > "$doc.new"
  mv "$doc.new" "$doc"
  echo "wrote $(cat "${files[@]}" | wc -l) rows to $doc"
  exit 0
fi
status=0
for f in "${files[@]}"; do
  run=$(basename "$(dirname "$(dirname "$f")")")/$(basename "$(dirname "$f")")
  backend=$(head -1 "$f" | awk -F' [|] ' '{print $4}')
  tier=$(head -1 "$f" | awk -F' [|] ' '{print $5}')
  expected=$(LC_ALL=C sort "$f")
  documented=$(grep "^| [^|]* | [^|]* | [^|]* | $backend | $tier | " "$doc" | LC_ALL=C sort || true)
  if [ "$expected" != "$documented" ]; then
    echo "docs/robustness_extremes.md differs from the $run run; regenerate it (tests/check_extremes_doc.sh ... --write):" >&2
    diff <(echo "$documented") <(echo "$expected") >&2 || true
    status=1
  fi
  if grep -q "| FAILED |" "$f"; then
    echo "the $run run has failed rows" >&2
    status=1
  fi
done
[ $status -eq 0 ] && echo "docs/robustness_extremes.md matches ${#files[@]} runs"
exit $status
