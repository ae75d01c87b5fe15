#!/usr/bin/env bash
# A generated page's tables must be exactly the table lines a command prints from the code
# (docs/tiers.md: `sfx info --rules`; docs/settings.md: `sfx info --settings`).
# Usage: check_doc_tables.sh <doc> <command> [args...]
set -euo pipefail
doc=$1
shift
expected=$("$@" | grep '^|')
documented=$(grep '^|' "$doc")
if [ "$expected" != "$documented" ]; then
  echo "$doc differs from '$*'; regenerate its tables:" >&2
  diff <(echo "$documented") <(echo "$expected") >&2 || true
  exit 1
fi
echo "$doc matches '$*'"
