#!/usr/bin/env bash
# Command 1 of the README: installs what is missing, builds, and runs the demo.
# Usage: tools/run_demo.sh [demo flags...]   (see build/samples/sfx_demo --help)
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
BUILD_DIR=${SFX_BUILD_DIR:-build}
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)" --target sfx_demo sfx_cli sfxc
"$BUILD_DIR"/samples/sfx_demo --out out/demo "$@"
