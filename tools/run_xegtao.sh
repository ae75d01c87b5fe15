#!/usr/bin/env bash
# Measures the peer XeGTAO (Intel's unmodified shaders, built for Mesa llvmpipe's GL 4.5 by the
# harness in $XEGTAO_HARNESS, default ../shared/peers/xegtao, see its README) on the inputs
# `bench_families --write-inputs DIR` wrote: every view at the presets low, medium, high and ultra
# (DIR/<view>.xegtao-<preset>.pfm), and the cost view timed at each preset (DIR/xegtao_cost.txt).
# bench_families --peer-dir DIR then scores them against the truth. The harness is a measuring
# instrument beside the project: nothing here builds it into the project or links it. When it is
# missing or does not build, this says so and exits 0 (the peer's rows are then absent).
# Usage: tools/run_xegtao.sh DIR [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
DIR=${1:?usage: tools/run_xegtao.sh DIR [RUNS]}
RUNS=${2:-11}
BUILD_DIR=${SFX_BUILD_DIR:-build}
HARNESS=${XEGTAO_HARNESS:-../shared/peers/xegtao}
PRESETS="low medium high ultra"
RUN="$PWD/$BUILD_DIR/xegtao/xegtao_run"

rm -f "$DIR"/*.xegtao-*.pfm "$DIR/xegtao_cost.txt"  # no stale outputs scored when the peer is not measured
if [ ! -x "$HARNESS/build.sh" ]; then
  echo "run_xegtao: no XeGTAO harness at $HARNESS: the peer is not measured"
  exit 0
fi
if ! BUILD_DIR="$PWD/$BUILD_DIR/xegtao" "$HARNESS/build.sh" >"$DIR/xegtao_build.log" 2>&1; then
  echo "run_xegtao: the XeGTAO harness did not build (see $DIR/xegtao_build.log): the peer is not measured"
  exit 0
fi
while read -r name width height fov radius; do
  for q in $PRESETS; do
    args=(--depth "$DIR/$name.depth.pfm" --normals "$DIR/$name.normals.pfm" --fov-y "$fov" --radius "$radius" --quality "$q")
    if [ "$name" = cost ]; then
      # "prefilter X ms, main Y ms, denoise Z ms, total T ms" -> "preset X Y Z T"
      line=$("$RUN" "${args[@]}" --runs "$RUNS" | grep -m1 '^prefilter')
      echo "$q $(echo "$line" | sed -E 's/[^0-9.]+/ /g')" >>"$DIR/xegtao_cost.txt"
      echo "run_xegtao: ${width}x${height} $q: $line"
    else
      "$RUN" "${args[@]}" --out "$DIR/$name.xegtao-$q.pfm" >/dev/null
    fi
  done
  [ "$name" = cost ] || echo "run_xegtao: $name (${width}x${height}, fov-y $fov, r $radius): $PRESETS"
done <"$DIR/views.txt"
