#!/usr/bin/env bash
# docs/settings.md must hold exactly the table `sfx info --settings` prints from the settings ranges.
set -euo pipefail
sfx=$1 doc=$2
expected=$("$sfx" info --settings | grep '^|')
documented=$(grep '^|' "$doc")
if [ "$expected" != "$documented" ]; then
  echo "docs/settings.md differs from 'sfx info --settings'; regenerate its table:" >&2
  diff <(echo "$documented") <(echo "$expected") >&2 || true
  exit 1
fi
echo "docs/settings.md matches the settings ranges"
