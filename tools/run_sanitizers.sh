#!/usr/bin/env bash
# The sanitizer run (.ci/run calls it after the main tests):
#  1. build-asan: every target the selected tests need, with AddressSanitizer (leaks included)
#     and UndefinedBehaviorSanitizer (-DSFX_SANITIZE=address,undefined, GCC); runs the unit
#     tests and the conformance tests of the backends in SFX_SANITIZE_BACKENDS (default: vulkan
#     on lavapipe, gles on llvmpipe), both tiers. Any report fails the run.
#  2. build-fuzz: the libFuzzer targets of tests/fuzz (Clang 14, fuzzer + ASan + UBSan), and
#     CTest replays each target's seed corpus (tests/fuzz/corpus/<target>/).
# Extra arguments go to both ctest runs. SFX_SKIP_FUZZ_REPLAY=1 skips step 2.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BACKENDS=${SFX_SANITIZE_BACKENDS:-vulkan gles}
JOBS=$(nproc)
source tools/sanitizers/common.sh
sfx_sanitizer_env "$ROOT"
sfx_ccache_launcher
start=$SECONDS

# ---- 1. ASan + UBSan: unit and conformance tests ---------------------------------------------
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSFX_WERROR=ON -DSFX_SANITIZE=address,undefined \
      "${SFX_LAUNCHER[@]}" >/dev/null
# Only what the selected tests run (no demo or benchmarks).
TARGETS=(sfx_unit_tests sfx_conformance sfx_cli sfxc)
if grep -q '^SFX_BACKEND_VULKAN:BOOL=ON' build-asan/CMakeCache.txt; then TARGETS+=(sfx_vulkan_external_tests sfx_vulkan_import_tests); fi
TARGETS+=(sfx_best_device_fallback)
cmake --build build-asan -j"$JOBS" --target "${TARGETS[@]}"
conformance=()
for backend in $BACKENDS; do conformance+=("conformance\\.$backend\\."); done
pattern="^($(IFS='|'; echo "${conformance[*]}"))"
# The unit tests (null backend, references, readers, validation) run with leak checking. The
# GPU conformance runs keep every ASan and UBSan check fatal but not the exit-time leak check:
# lavapipe and llvmpipe keep JIT-compiled shaders and context state until the process ends and
# unload their modules first, so LeakSanitizer reports 100+ MB from "<unknown module>" that no
# suppression can name. Leaks in the SDK's own code are caught by the unit run, which drives the
# effects, the validation and the handle pools through the null backend.
# vulkan.external and vulkan.import drive lavapipe through a host's own Vulkan device, and the
# fallback.* entries open real devices with others hidden, so they go with them.
gpu_units='^(vulkan\.external|vulkan\.import|fallback\..*)$'
(cd build-asan && ctest --output-on-failure -j"$JOBS" -L unit -E "$gpu_units" "$@" &&
  ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0" ctest --output-on-failure -j"$JOBS" -R "$pattern|$gpu_units" "$@")
echo "run_sanitizers: ASan+UBSan unit and conformance ($BACKENDS) clean after $((SECONDS - start)) s"

# ---- 2. libFuzzer targets: replay the seed corpora -------------------------------------------
if [ "${SFX_SKIP_FUZZ_REPLAY:-0}" != 1 ]; then
  sfx_build_fuzzers
  (cd build-fuzz && ctest --output-on-failure -j"$JOBS" -L fuzz "$@")
  echo "run_sanitizers: fuzz corpora replayed clean after $((SECONDS - start)) s"
fi
