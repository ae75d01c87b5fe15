#!/usr/bin/env bash
# A page's generated sections must be what the programs that own them write from the CSVs beside
# the page, so a hand edit or a CSV regenerated without its tables fails here.
# Usage: check_generated_sections.sh <page> <command> [args...] [-- <command> [args...]]...
# Each command runs with "--doc <a copy of the page>" appended; the copy must equal the page.
set -euo pipefail
page=$1
shift
copy=$(mktemp)
trap 'rm -f "$copy"' EXIT
cp "$page" "$copy"
run() { "$@" --doc "$copy" >/dev/null; }
cmd=()
for arg in "$@" --; do
  if [ "$arg" = "--" ]; then
    [ ${#cmd[@]} -gt 0 ] && run "${cmd[@]}"
    cmd=()
  else
    cmd+=("$arg")
  fi
done
if ! cmp -s "$page" "$copy"; then
  echo "$page: its generated sections differ from what the CSVs give; regenerate them (tools/run_trade.sh):" >&2
  diff "$page" "$copy" >&2 || true
  exit 1
fi
echo "$page: generated sections match their CSVs"
