#!/usr/bin/env bash
# The soak run of docs/robustness.md ("Soak"): builds samples/soak and runs it, by default 10000
# frames on every compiled backend. Exit status: the soak's (0 every backend passed, 1 one failed).
# Usage: tools/run_soak.sh [--frames N] [--backends vulkan,gles,gl-egl,gl-osmesa] [--progress N]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${SFX_BUILD_DIR:-build}
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$BUILD_DIR" -j"$(nproc)" --target soak >/dev/null
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp/xdg-$USER}
mkdir -p "$XDG_RUNTIME_DIR"
exec "$BUILD_DIR"/samples/soak "$@"
