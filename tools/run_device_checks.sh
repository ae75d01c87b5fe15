#!/usr/bin/env bash
# The checks that need a real GPU, prepared on this machine and run on one that has a GPU but
# none of Debian's packages (a lent device machine starts bare and reaches nothing outside):
#
#   tools/run_device_checks.sh pack [BUILD_DIR]   here: build what the checks run, write
#                                                 .device/bundle.tar.xz (about 25 MB; git ignores
#                                                 .device, which the device call carries)
#   tools/run_device_checks.sh run OUT_DIR [--quick]
#                                                 there, from the repository's root with .device
#                                                 carried: unpack it, run the checks, write
#                                                 OUT_DIR/summary.txt and OUT_DIR/device_checks.tar.gz
#                                                 (every log); --quick tries the bundle (here, say):
#                                                 conformance's [depth] cases only, no trade_presets,
#                                                 one timed round
#
# The bundle: sfx, sfx_conformance, trade_presets and bench_mb_cost, stripped; the shared
# libraries ldd names beyond glibc; the Vulkan loader and the Khronos validation layer; glibc's
# own loader and libc, used only where the machine's glibc is too old for the binaries; the
# stand-in libOSMesa.so.8 of tests/fallback/osmesa_stub.cpp instead of Mesa's (the conformance
# binary links it, and Mesa's software renderer with its LLVM would not fit: gl-osmesa reports
# unavailable there); and the truth cache trade_presets scores against.
#
# The checks, each under a time limit (the whole run is sized for a few minutes of a GPU):
#   1. sfx info: the devices, their capabilities and tiers;
#   2. conformance (sfx_conformance --backend B --tier T, as CTest runs it, Vulkan under the
#      validation layer) on vulkan, gles and gl-egl at both tiers;
#   3. trade_presets on vulkan and gles: every preset's cost at 1280 x 720 beside its accuracy;
#   4. bench_mb_cost on vulkan and gles: motion blur's 13, 9 and 7 taps at 16 px blurs
#      (exposure 1) and 4 px blurs (exposure 0.25).
# A check that fails or times out is recorded in summary.txt and the next one runs.
set -uo pipefail
cd "$(dirname "$0")/.."
REPO=$PWD
MODE=${1:-}

pack() {
    local build=${1:-build}
    local stage=.device/stage
    set -e
    echo "== building sfx_cli sfx_conformance trade_presets bench_mb_cost sfx_osmesa_stub in $build"
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
    cmake --build "$build" -j"$(nproc)" --target sfx_cli sfx_conformance trade_presets bench_mb_cost sfx_osmesa_stub >/dev/null
    rm -rf .device && mkdir -p $stage/bin $stage/lib $stage/glibc $stage/layers $stage/truth-cache
    local bins=("$build/tools/sfx" "$build/tests/sfx_conformance" "$build/tools/bench/trade_presets" "$build/tools/bench/bench_mb_cost")
    for b in "${bins[@]}"; do strip -o "$stage/bin/$(basename "$b")" "$b"; done
    # Every library the binaries load beyond glibc's own, Mesa's OSMesa and what only it needs.
    for b in "${bins[@]}"; do ldd "$b"; done | awk '$3 ~ /^\// {print $3}' | sort -u |
        grep -v -E '/(libc|libm|libdl|libpthread|librt|libOSMesa|libLLVM-[0-9.]+|libglapi|libicu[a-z]*|libxml2|libz3|libedit|libffi|libtinfo|libbsd|libmd|liblzma)\.so' |
        while read -r lib; do cp -L "$lib" $stage/lib/; done
    cp -L "$build/tests/osmesa-stub/libOSMesa.so.8" $stage/lib/
    cp -L "$(ldconfig -p | awk '/libvulkan.so.1 .*x86-64/ {print $NF; exit}')" $stage/lib/
    cp -L /usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so $stage/lib/
    cp /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json $stage/layers/
    cp -L /lib64/ld-linux-x86-64.so.2 /lib/x86_64-linux-gnu/libc.so.6 /lib/x86_64-linux-gnu/libm.so.6 $stage/glibc/
    cp "$build"/truth-cache/*.exr $stage/truth-cache/ 2>/dev/null || echo "no truth cache in $build: trade_presets will render it there"
    echo "== writing .device/bundle.tar.xz"
    tar -C .device -cJf .device/bundle.tar.xz stage
    rm -rf $stage
    ls -l .device/bundle.tar.xz
}

run() {
    local out=${1:?usage: tools/run_device_checks.sh run OUT_DIR [--quick]} quick=${2:-}
    local cases=() rounds=()
    [ "$quick" = --quick ] && cases=("[depth]") rounds=(--rounds 1 --runs 1)
    mkdir -p "$out"
    out=$(cd "$out" && pwd)
    local work=${TMPDIR:-/tmp}/sfx-device-checks
    rm -rf "$work" && mkdir -p "$work/logs"
    tar -C "$work" -xJf .device/bundle.tar.xz || {
        echo "no .device/bundle.tar.xz: run 'tools/run_device_checks.sh pack' first" >&2
        return 1
    }
    local b=$work/stage
    local summary=$out/summary.txt
    : >"$summary"
    note() { echo "$*" | tee -a "$summary"; }
    # The GPU's drivers where this workplace's device machines keep them (named only if present).
    local nv=/usr/local/nvidia
    [ -f $nv/share/vulkan/icd.d/nvidia_icd.json ] && export VK_DRIVER_FILES=$nv/share/vulkan/icd.d/nvidia_icd.json
    [ -f $nv/share/glvnd/egl_vendor.d/10_nvidia.json ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$nv/share/glvnd/egl_vendor.d/10_nvidia.json
    export LD_LIBRARY_PATH=$b/lib:$nv/lib64:$nv/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
    export VK_LAYER_PATH=$b/layers SFX_SOURCE_DIR=$REPO SFX_TEST_OUTPUT=$work/test-output XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$work}
    # Run through the machine's glibc if the binaries start there, else through the bundle's.
    local launch=()
    if ! "$b/bin/sfx" --help >/dev/null 2>"$work/logs/start.txt"; then
        launch=("$b/glibc/ld-linux-x86-64.so.2" --library-path "$b/glibc:$LD_LIBRARY_PATH")
        note "the binaries did not start with this machine's glibc ($(head -c 200 "$work/logs/start.txt")); running them through the bundle's"
    fi
    check() {  # check NAME LIMIT_S PROGRAM ARGS...: one check, its log and its line in the summary
        local name=$1 limit=$2
        shift 2
        local start=$SECONDS
        timeout "$limit" "${launch[@]}" "$b/bin/$@" >"$work/logs/$name.txt" 2>&1
        local rc=$?
        local verdict=passed
        case $rc in 0) ;; 77) verdict="skipped (exit 77)" ;; 124) verdict="timed out after $limit s" ;; *) verdict="failed (exit $rc)" ;; esac
        note "$name: $verdict in $((SECONDS - start)) s: $(grep -v "^[[:space:]]*$" "$work/logs/$name.txt" | tail -n 1 | cut -c1-200)"
    }
    note "device checks, $(date -u +%FT%TZ), $(uname -m), $(command -v nvidia-smi >/dev/null && nvidia-smi -L | head -n 1)"
    check info 60 sfx info
    grep -E '^[a-z-]+( \(ceiling[^)]*\))?: ' "$work/logs/info.txt" | cut -c1-200 | tee -a "$summary"
    for backend in vulkan gles gl-egl; do
        for tier in high current; do
            check "conformance.$backend.$tier" 300 sfx_conformance --backend "$backend" --tier "$tier" "${cases[@]}"
        done
    done
    mkdir -p "$work/trade" && cp docs/trade.md "$work/trade/"
    [ "$quick" = --quick ] || check trade_presets 420 trade_presets --backends vulkan,gles --cache-dir "$b/truth-cache" --out-dir "$work/trade"
    for backend in vulkan gles; do
        for exposure in 1 0.25; do
            check "mb_cost.$backend.$exposure" 180 bench_mb_cost --backend "$backend" --exposure "$exposure" --configs 13:18,9:18,7:14 "${rounds[@]}"
        done
    done
    tar -C "$work" -czf "$out/device_checks.tar.gz" logs trade test-output 2>/dev/null || tar -C "$work" -czf "$out/device_checks.tar.gz" logs
    note "logs: $out/device_checks.tar.gz"
}

case $MODE in
pack) pack "${2:-build}" ;;
run) run "${2:-}" "${3:-}" ;;
*)
    echo "usage: tools/run_device_checks.sh pack [BUILD_DIR] | run OUT_DIR [--quick]" >&2
    exit 2
    ;;
esac
