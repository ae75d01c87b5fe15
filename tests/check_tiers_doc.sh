#!/usr/bin/env bash
# docs/tiers.md must hold exactly the tables `sfx info --rules` prints from the tier code.
set -euo pipefail
sfx=$1 doc=$2
expected=$("$sfx" info --rules | grep '^|')
documented=$(grep '^|' "$doc")
if [ "$expected" != "$documented" ]; then
  echo "docs/tiers.md differs from 'sfx info --rules'; regenerate its tables:" >&2
  diff <(echo "$documented") <(echo "$expected") >&2 || true
  exit 1
fi
echo "docs/tiers.md matches the tier rules"
