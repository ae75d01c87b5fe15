#!/usr/bin/env bash
# Command 2 of the README: installs what is missing, builds with warnings as errors, and runs
# every test: unit tests, and conformance on every backend (vulkan, gles, gl) and both tiers.
# Extra arguments go to ctest, e.g. tools/run_tests.sh -L vulkan
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
BUILD_DIR=${SFX_BUILD_DIR:-build}
# ccache (installed by install_deps) makes a rebuild of unchanged sources nearly free.
LAUNCHER=()
if command -v ccache >/dev/null; then
  LAUNCHER=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSFX_WERROR=ON "${LAUNCHER[@]}" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
# Mesa's software drivers want a runtime dir; without one they only complain, but quietly is nicer.
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
cd "$BUILD_DIR"
ctest --output-on-failure -j"$(nproc)" "$@"
