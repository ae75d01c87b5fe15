# Sourced by tools/run_sanitizers.sh and tools/run_fuzz.sh: the sanitizer environment and the
# libFuzzer build (build-fuzz), written once.

# Every report is fatal; leaks are checked at exit. The suppressions name libraries outside
# this project only (each justified in lsan.supp); project code is never suppressed.
sfx_sanitizer_env() {
  local root=$1
  export ASAN_OPTIONS=halt_on_error=1:abort_on_error=0:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1
  export LSAN_OPTIONS=suppressions=$root/tools/sanitizers/lsan.supp:print_suppressions=0
  export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
  export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
}

sfx_ccache_launcher() {
  SFX_LAUNCHER=()
  if command -v ccache >/dev/null; then
    SFX_LAUNCHER=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
}

# The fuzz targets of tests/fuzz with Clang 14: libFuzzer, ASan and UBSan on every library.
sfx_build_fuzzers() {
  if ! command -v clang++-14 >/dev/null; then
    echo "clang++-14 is missing (tools/install_deps.sh installs it)" >&2
    return 1
  fi
  sfx_ccache_launcher
  cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSFX_WERROR=ON -DCMAKE_C_COMPILER=clang-14 \
        -DCMAKE_CXX_COMPILER=clang++-14 -DSFX_SANITIZE=fuzzer-no-link,address,undefined -DSFX_BUILD_FUZZERS=ON \
        -DSFX_BUILD_TESTS=OFF "${SFX_LAUNCHER[@]}" >/dev/null
  cmake --build build-fuzz -j"$(nproc)" --target sfx_fuzzers
}
