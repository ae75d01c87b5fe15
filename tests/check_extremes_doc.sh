#!/usr/bin/env bash
# docs/robustness_extremes.md must hold exactly the rows the extremes conformance cases wrote
# (test-output/<backend>-<tier>/extremes_rows.md, one file per run of sfx_conformance).
#   check_extremes_doc.sh TEST_OUTPUT_DIR DOC           compare, for every run that wrote rows
#   check_extremes_doc.sh TEST_OUTPUT_DIR DOC --write   regenerate the table in DOC
# A backend that did not run here (its rows file is missing) is not compared.
set -euo pipefail
out=$1 doc=$2 mode=${3:-}
shopt -s nullglob
files=("$out"/*/extremes_rows.md)
if [ ${#files[@]} -eq 0 ]; then
  echo "no extremes_rows.md under $out: run the conformance tests first" >&2
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
  run=$(basename "$(dirname "$f")")
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
