#!/usr/bin/env bash
# Fuzzes every target of tests/fuzz (or the ones named: tools/run_fuzz.sh pfm obj) for
# SFX_FUZZ_RUNS executions each (default 1e6), starting from its seed corpus. A benchmark,
# not CI: CI only replays the corpora (tools/run_sanitizers.sh).
#
# libFuzzer prints its progress (#executions, coverage, exec/s) as it goes. A crash, hang
# (-timeout) or out-of-memory input is copied into tests/fuzz/corpus/<target>/ as
# regression-<kind>-<hash>, so the corpus replay fails until the bug is fixed; the script
# then goes on with the next target and exits non-zero. A table of the results is printed
# at the end and written to build-fuzz/fuzz-results.md (every target run so far; docs/robustness.md
# quotes it).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
RUNS=${SFX_FUZZ_RUNS:-1000000}
source tools/sanitizers/common.sh
sfx_sanitizer_env "$ROOT"
sfx_build_fuzzers

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for dir in tests/fuzz/corpus/*/; do targets+=("$(basename "$dir")"); done
fi

# One row per target (build-fuzz/fuzz-result-<target>.md), so runs of different targets add up.
failed=0
for target in "${targets[@]}"; do
  binary=build-fuzz/tests/fuzz/fuzz_$target
  seeds=tests/fuzz/corpus/$target
  work=build-fuzz/fuzz-work/$target
  artifacts=build-fuzz/fuzz-artifacts/$target
  [ -x "$binary" ] || { echo "run_fuzz: no target $target ($binary)" >&2; exit 2; }
  mkdir -p "$work" "$artifacts"
  nseeds=$(ls "$seeds" | wc -l)
  echo "=== fuzz_$target: $RUNS executions from $nseeds seeds"
  begin=$SECONDS
  status=0
  # New inputs go to the work directory only; the seed corpus stays small.
  "$binary" -runs="$RUNS" -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "$work" "$seeds" 2>&1 | tee "build-fuzz/fuzz-$target.log" || status=$?
  seconds=$((SECONDS - begin))
  log=build-fuzz/fuzz-$target.log
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  found=0
  for input in "$artifacts"/crash-* "$artifacts"/timeout-* "$artifacts"/oom-* "$artifacts"/leak-*; do
    [ -e "$input" ] || continue
    kind=$(basename "$input" | cut -d- -f1)
    cp "$input" "$seeds/regression-$kind-$(sha1sum "$input" | cut -c1-12)"
    rm "$input"
    found=$((found + 1))
  done
  if [ "$status" -ne 0 ] || [ "$found" -ne 0 ]; then
    failed=1
    echo "run_fuzz: fuzz_$target failed (exit $status); $found input(s) added to $seeds as regression-*: fix the bug, then rerun"
  fi
  echo "| $target | ${execs:-?} | ${rate:-?} | $seconds | $nseeds → $(ls "$work" | wc -l) | $found |" >"build-fuzz/fuzz-result-$target.md"
done
results=build-fuzz/fuzz-results.md
{
  echo "| target | executions | exec/s | seconds | corpus (seeds → end) | crashes / hangs |"
  echo "|---|---:|---:|---:|---|---:|"
  cat build-fuzz/fuzz-result-*.md
} >"$results"
echo
cat "$results"
exit "$failed"
