#!/usr/bin/env bash
# Regenerates the trade page (docs/trade.md) and the scene families' page (docs/ao_families.md)
# from a checkout: builds the programs, then
#   1. fit_ao        - refits each technique's look per tier on the training scene families,
#                      starting from the tier table's look, and scores the held-out families
#                      (docs/ao_fit.csv, the fit table of docs/trade.md); three refinement levels,
#                      as it starts where the last adopted fit ended;
#   2. bench_trade   - every technique x tier x blur x backend at its defaults against the truth
#                      (docs/trade.csv, the error tables);
#   3. the peer      - every scene family view's depth and normals written for XeGTAO, which
#                      tools/run_xegtao.sh runs on them and times at 1280x720 (when its harness
#                      builds; the project never links it);
#   4. trade_presets - cost and accuracy of every tier preset (AO on the held-out families, motion
#                      blur), XeGTAO's presets beside them, and the Pareto plots
#                      (docs/trade_presets.csv, docs/images/pareto_*.svg, the preset table);
#   4b. ao_front     - a grid of AO configurations per tier (technique, counts, blur, resolution)
#                      scored on the training families (the front) and the held-out ones (beside)
#                      and timed on every backend: the front the presets are chosen from
#                      (docs/ao_front.csv, docs/images/ao_front_*.svg, the front table of
#                      docs/trade.md; about 6 minutes);
#   5. bench_families - every technique x tier x backend at its defaults per scene family, and the
#                      peer on the same inputs against the same truth (docs/ao_families.md, .csv,
#                      _cost.csv, docs/images/ao_family_*.png).
#   6. bench_mb_families - motion blur per scene family, speed, tier and backend against its
#                      truth (docs/mb_families.csv, and from it the family tables of docs/motion_blur.md
#                      against the 2012 reconstruction's figures in docs/mb_families_2012.csv), and
#                      each family's pictures (docs/images/mb_<family>_<speed>px.png); then with
#                      --raster the rasterised families, drawn by the first backend's raster pass
#                      (docs/mb_raster_families.csv, docs/images/mb_{models,camera,turning}_12px.png).
#                      With --sweeps, both every 0.5 px past both tiers' blur, CPU reference
#                      (docs/mb_sweep.csv, docs/mb_raster_sweep.csv and their tables in
#                      docs/motion_blur_studies.md), and every family, 2D
#                      and rasterised, laid out from 16 seeds every 0.5 px from 5 px, where the
#                      tiers' pictures can differ (docs/mb_layouts.csv, docs/mb_raster_layouts.csv
#                      and their tables there; two processes each).
#   7. bench_mb_flicker - motion blur's frame-to-frame change against the truth's over frame
#                      sequences of the same families, and both jitter patterns (docs/mb_flicker.csv and
#                      its tables in "Stable under motion" in docs/motion_blur.md);
#   8. fit_mb        - motion blur's accuracy on the training and held-out families and its cost
#                      per taps x maximum radius at 720 rows, the front its presets are chosen from,
#                      and each tier's default at five tile edges (docs/mb_fit.csv, its grid and
#                      tile table in docs/motion_blur.md; about 5 minutes).
# Truth images are traced once and cached by scene, view, size, radius, sample count and seed
# under $SFX_TRUTH_CACHE (default build/truth-cache): a second run only renders the effects.
# The fitted looks are data of the tier table: fit_ao prints them, and adopting them is an edit of
# tiers/src/tier_table.cpp (with the preset accuracies trade_presets prints), then a rerun; so are
# the motion blur presets fit_mb's front gives, and the AO presets ao_front's front gives.
# Usage: tools/run_trade.sh [--backends vulkan,gles] [--sweeps]
# --sweeps adds the motion blur speed sweeps of step 6 (30-35 minutes on 2 cores, beyond the
# rest's 20-minute budget); without it they are skipped, and the script says so.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${SFX_BUILD_DIR:-build}
CACHE=${SFX_TRUTH_CACHE:-$BUILD_DIR/truth-cache}
BACKENDS=vulkan,gles
SWEEPS=0
while [ $# -gt 0 ]; do
    case "$1" in
        --backends) BACKENDS=${2:?--backends needs a list}; shift 2 ;;
        --sweeps) SWEEPS=1; shift ;;
        *) echo "run_trade.sh: unknown argument '$1' (allowed: --backends LIST, --sweeps)" >&2; exit 2 ;;
    esac
done
start=$(date +%s)
step() { echo "== [$(( $(date +%s) - start )) s] $*"; }
# bench_mb_families over layouts 1-16 from 5 px (below it the tiers' pictures are the same at any
# layout), as two processes of 8 layouts; their CSVs joined into $1. Further arguments go to both.
layouts_run() {
    local csv=$1 dir second
    shift
    dir=$(mktemp -d)
    "$BUILD_DIR"/tools/bench/bench_mb_families "$@" --sweep --sweep-from 5 --layouts 8 --seed 9 --instants 64 --backends none \
        --csv "$dir/b.csv" > "$dir/b.log" 2>&1 &
    second=$!
    "$BUILD_DIR"/tools/bench/bench_mb_families "$@" --sweep --sweep-from 5 --layouts 8 --seed 1 --instants 64 --backends none \
        --csv "$dir/a.csv"
    wait "$second" || { cat "$dir/b.log" >&2; exit 1; }
    { cat "$dir/a.csv"; tail -n +2 "$dir/b.csv"; } > "$csv"
    rm -rf "$dir"
}
# The layouts' sections of docs/motion_blur_studies.md from their CSVs.
layouts_doc() {
    "$BUILD_DIR"/tools/bench/bench_mb_families --sweep --layouts 16 --instants 64 --csv docs/mb_layouts.csv --doc docs/motion_blur_studies.md --doc-only
    "$BUILD_DIR"/tools/bench/bench_mb_families --raster --raster-backend "${BACKENDS%%,*}" --sweep --layouts 16 --instants 64 \
        --csv docs/mb_raster_layouts.csv --doc docs/motion_blur_studies.md --doc-only
}
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}

step "configure and build bench_trade, fit_ao, trade_presets, ao_front, bench_families, bench_mb_families, bench_mb_flicker, fit_mb"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)" --target bench_trade fit_ao trade_presets bench_families bench_mb_families bench_mb_flicker fit_mb ao_front sfx_cli >/dev/null
step "fit_ao: the looks, fitted on the training families, scored on the held-out ones"
"$BUILD_DIR"/tools/bench/fit_ao --start tier --refinements 3 --cache-dir "$CACHE" --out-dir docs --backend "${BACKENDS%%,*}"
step "bench_trade: the defaults against the truth, every backend"
"$BUILD_DIR"/tools/bench/bench_trade --cache-dir "$CACHE" --out-dir docs --backends "$BACKENDS"
PEER_DIR=$BUILD_DIR/families-peer
step "bench_families: each family view's depth and normals for the peer"
"$BUILD_DIR"/tools/bench/bench_families --write-inputs "$PEER_DIR" --backends "${BACKENDS%%,*}"
step "XeGTAO (the peer, measured beside the project) on the same inputs"
tools/run_xegtao.sh "$PEER_DIR"
step "trade_presets: cost and accuracy of every preset and of the peer, Pareto plots"
"$BUILD_DIR"/tools/bench/trade_presets --cache-dir "$CACHE" --out-dir docs --backends "$BACKENDS" --peer-dir "$PEER_DIR"
step "ao_front: the AO front over technique x counts x blur x resolution, every backend"
"$BUILD_DIR"/tools/bench/ao_front --runs 3 --cache-dir "$CACHE" --out-dir docs --backends "$BACKENDS"
step "bench_families: the defaults and the peer against the truth, per scene family"
"$BUILD_DIR"/tools/bench/bench_families --cache-dir "$CACHE" --out-dir docs --backends "$BACKENDS" --peer-dir "$PEER_DIR"
step "bench_mb_families: motion blur on the held-out scene families"
"$BUILD_DIR"/tools/bench/bench_mb_families --csv docs/mb_families.csv --backends "$BACKENDS" --images docs/images \
    --doc docs/motion_blur.md --before docs/mb_families_2012.csv
step "bench_mb_families --raster: motion blur on the rasterised held-out families"
"$BUILD_DIR"/tools/bench/bench_mb_families --raster --raster-backend "${BACKENDS%%,*}" --instants 128 --csv docs/mb_raster_families.csv \
    --backends "$BACKENDS" --images docs/images --image-speeds 12 --doc docs/motion_blur.md
if [ "$SWEEPS" = 1 ]; then
    step "bench_mb_families --sweep: the tier promise every 0.5 px, CPU reference (10-16 minutes)"
    "$BUILD_DIR"/tools/bench/bench_mb_families --sweep --backends none --csv docs/mb_sweep.csv --doc docs/motion_blur_studies.md
    "$BUILD_DIR"/tools/bench/bench_mb_families --sweep --raster --raster-backend "${BACKENDS%%,*}" --instants 64 --backends none \
        --csv docs/mb_raster_sweep.csv --doc docs/motion_blur_studies.md
    step "bench_mb_families --layouts: the tier promise over 16 layouts of each family, CPU reference (about 9 minutes)"
    layouts_run docs/mb_layouts.csv
    step "bench_mb_families --raster --layouts: the same for the rasterised families (about 11 minutes)"
    layouts_run docs/mb_raster_layouts.csv --raster --raster-backend "${BACKENDS%%,*}"
    layouts_doc
else
    step "bench_mb_families --sweep and --layouts: skipped (30-35 minutes; run with --sweeps): docs/mb_sweep.csv, mb_raster_sweep.csv, mb_layouts.csv and mb_raster_layouts.csv keep their last run"
    "$BUILD_DIR"/tools/bench/bench_mb_families --sweep --csv docs/mb_sweep.csv --doc docs/motion_blur_studies.md --doc-only
    "$BUILD_DIR"/tools/bench/bench_mb_families --sweep --raster --raster-backend "${BACKENDS%%,*}" --instants 64 --csv docs/mb_raster_sweep.csv \
        --doc docs/motion_blur_studies.md --doc-only
    layouts_doc
fi
step "bench_mb_flicker: motion blur's flicker over frame sequences of the scene families"
"$BUILD_DIR"/tools/bench/bench_mb_flicker --csv docs/mb_flicker.csv --backends "$BACKENDS" --doc docs/motion_blur.md
step "fit_mb: motion blur's front over taps x maximum radius at 720 rows"
"$BUILD_DIR"/tools/bench/fit_mb --taps 3,5,7,9,11,13,15,17 --radii 8,10,12,14,18,24 --tiles 5,7,10,14,18 --backend "${BACKENDS%%,*}" --csv docs/mb_fit.csv --doc docs/motion_blur.md
step "done: docs/trade.md, docs/trade.csv, docs/ao_fit.csv, docs/trade_presets.csv, docs/images/pareto_*.svg, docs/ao_front.csv, docs/images/ao_front_*.svg, docs/mb_families.csv, docs/mb_raster_families.csv, docs/mb_sweep.csv, docs/mb_raster_sweep.csv, docs/images/mb_*px.png, docs/mb_flicker.csv, docs/mb_fit.csv, docs/ao_families.*"
