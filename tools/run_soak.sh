#!/usr/bin/env bash
# The soak run of docs/robustness.md ("Soak"): builds tools/bench/soak and runs it, by default 10000
# frames on every compiled backend, each backend in a process of its own so that one backend's
# resident memory is not the baseline of the next. Exit status 0 when every backend passed.
# Vulkan runs twice: with the validation layers (no message, every object back; the layers'
# own memory grows under object churn, so growth is reported, not checked) and without them
# (the 1% resident-memory bound, every object back). The GL backends' validation is the
# backend's own error checks and debug output, so one run checks everything.
# Usage: tools/run_soak.sh [--frames N] [--backends vulkan,gles,gl-egl,gl-osmesa] [--progress N] [--no-validation]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${SFX_BUILD_DIR:-build}
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$BUILD_DIR" -j"$(nproc)" --target soak >/dev/null
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp/xdg-$(id -un)}
mkdir -p "$XDG_RUNTIME_DIR"
backends="vulkan,gles,gl-egl,gl-osmesa"
validation=1
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --backends) backends="$2"; shift 2 ;;
    --no-validation) validation=0; shift ;;
    *) args+=("$1"); shift ;;
  esac
done
status=0
for b in ${backends//,/ }; do
  if [ "$validation" = 0 ]; then
    "$BUILD_DIR"/tools/bench/soak --backends "$b" --no-validation "${args[@]}" || status=1
  elif [ "$b" = vulkan ]; then
    "$BUILD_DIR"/tools/bench/soak --backends "$b" --memory-report-only "${args[@]}" || status=1
    "$BUILD_DIR"/tools/bench/soak --backends "$b" --no-validation "${args[@]}" || status=1
  else
    "$BUILD_DIR"/tools/bench/soak --backends "$b" "${args[@]}" || status=1
  fi
done
exit $status
