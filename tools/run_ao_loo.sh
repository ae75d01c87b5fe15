#!/usr/bin/env bash
# Whether the AO calibration generalises (docs/ao_families.md, "Leaving each family out"):
# builds fit_ao and runs it with --leave-one-out, which fits each technique's look per tier on
# every scene family and on every family but one (each fit a search from the tier table's look
# and one from the papers' look, the better kept: how the table's looks were found) and scores
# each family under both (docs/ao_loo.csv and the tables between the page's fit_ao_loo markers).
# About 10 minutes on 2 shared cores: apart from tools/run_trade.sh, which stays within its time.
# Truth images come from the same cache.
# Usage: tools/run_ao_loo.sh [--backend vulkan]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${SFX_BUILD_DIR:-build}
CACHE=${SFX_TRUTH_CACHE:-$BUILD_DIR/truth-cache}
BACKEND=vulkan
if [ "${1:-}" = "--backend" ] && [ -n "${2:-}" ]; then BACKEND=$2; fi
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)" --target fit_ao >/dev/null
"$BUILD_DIR"/tools/bench/fit_ao --leave-one-out --start both --refinements 3 --cache-dir "$CACHE" --out-dir docs --backend "$BACKEND"
