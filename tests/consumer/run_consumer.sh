#!/bin/sh
# The installed package as a host sees it, end to end:
#   run_consumer.sh package|subdirectory <SDK build dir> <SDK source dir> <work dir> [compiler launcher]
# package: cmake --install into <work dir>/prefix; checks what is there (headers, libraries,
# CMake package with version file, scalablefx.pc, sfx and sfxc) and that no installed library
# needs glslang, SPIRV-Tools or SPIRV-Cross; compiles every installed header alone against the
# exported targets; builds and runs this folder's project through find_package(ScalableFX
# CONFIG) and through pkg-config.
# subdirectory: builds and runs the same project with add_subdirectory(<SDK source dir>),
# compiling the shaders with the installed sfxc (SFX_SFXC_EXECUTABLE, as a cross build does).
set -eu
mode=$1 build=$2 source=$3 work=$4 launcher=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
prefix=$work/prefix
launch=""
[ -n "$launcher" ] && launch="-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher -DCMAKE_C_COMPILER_LAUNCHER=$launcher"
fail() { echo "run_consumer: FAILED: $*" >&2; exit 1; }

run() {  # the consumer exits 77 when this machine has no GL ES device
    status=0
    "$@" || status=$?
    [ "$status" -eq 0 ] || exit "$status"
}

if [ "$mode" = package ]; then
    rm -rf "$work"
    mkdir -p "$work"
    cmake --install "$build" --prefix "$prefix" >"$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
    libdir=$(dirname "$(find "$prefix" -name ScalableFXConfig.cmake)")/../..
    for f in include/sfx/ao.hpp include/sfx/motion_blur.hpp include/sfx/tiers.hpp include/sfx/budget.hpp include/sfx/backends.hpp \
             include/sfx/vulkan_device.hpp include/sfx/gl_device.hpp include/sfx_shaders.hpp \
             include/sfx/shader_include/sfx_shared.h bin/sfx bin/sfxc; do
        [ -e "$prefix/$f" ] || fail "$f is not installed"
    done
    for f in cmake/ScalableFX/ScalableFXConfig.cmake cmake/ScalableFX/ScalableFXConfigVersion.cmake \
             pkgconfig/scalablefx.pc libsfx.a libsfx_core.a libsfx_backends.a libsfx_budget.a; do
        [ -e "$libdir/$f" ] || fail "lib/$f is not installed"
    done
    [ ! -e "$prefix/include/sfx/reference" ] || fail "the CPU references (test code) are installed"
    # Shaders are embedded at build time: no installed library or link interface names a shader
    # compiler, and no library has an undefined symbol of one.
    if grep -il 'glslang\|SPIRV-Tools\|spirv-cross\|spirv_cross' "$libdir"/cmake/ScalableFX/*.cmake "$libdir/pkgconfig/scalablefx.pc"; then
        fail "the package's link interface names a shader compiler"
    fi
    for lib in "$libdir"/libsfx*.a; do
        if nm -C --undefined-only "$lib" 2>/dev/null | grep -q 'spvtools::\|glslang::\|spirv_cross::\|spv[A-Z][a-zA-Z]*Validate'; then
            fail "$(basename "$lib") needs a shader compiler or SPIRV-Tools at link or run time"
        fi
    done
    if ldd "$prefix/bin/sfx" | grep -i 'glslang\|SPIRV'; then fail "bin/sfx loads a shader compiler"; fi

    # With the prefix's include folder named, the project also compiles every installed header
    # on its own against the exported targets (sfx_header_check).
    cmake -S "$here" -B "$work/package" -DCMAKE_PREFIX_PATH="$prefix" -DSFX_CONSUMER_INCLUDE_DIR="$prefix/include" \
          $launch >"$work/configure.log" || { cat "$work/configure.log"; fail "configure with find_package(ScalableFX CONFIG)"; }
    grep 'sfx_header_check:' "$work/configure.log"
    cmake --build "$work/package" --parallel 2 >"$work/build.log" ||
        { cat "$work/build.log"; fail "build against the package (sfx_header_check: every installed header alone)"; }
    "$work/package/sfx_header_check" || fail "sfx_header_check"
    run "$work/package/sfx_consumer"

    # pkg-config, as a build without CMake would use it.
    PKG_CONFIG_PATH=$libdir/pkgconfig
    export PKG_CONFIG_PATH
    # shellcheck disable=SC2046
    ${launcher:+$launcher} c++ -o "$work/sfx_consumer_pc" "$here/main.cpp" $(pkg-config --cflags --libs scalablefx) ||
        fail "build through pkg-config"
    run "$work/sfx_consumer_pc"
elif [ "$mode" = subdirectory ]; then
    [ -x "$prefix/bin/sfxc" ] || fail "no installed sfxc under $prefix (run the package mode first)"
    rm -rf "$work/subdirectory"
    cmake -S "$here" -B "$work/subdirectory" -DSFX_CONSUMER_SOURCE_DIR="$source" \
          -DSFX_SFXC_EXECUTABLE="$prefix/bin/sfxc" $launch >"$work/subdirectory.log" ||
        { cat "$work/subdirectory.log"; fail "configure with add_subdirectory"; }
    ! grep -q '^glslang_DIR\|^SPIRV-Tools_DIR\|^spirv_cross_core_DIR' "$work/subdirectory/CMakeCache.txt" ||
        fail "add_subdirectory with an outside sfxc still looked for the shader compiler's libraries"
    cmake --build "$work/subdirectory" --target sfx_consumer -j2 >"$work/subdirectory-build.log" ||
        { cat "$work/subdirectory-build.log"; fail "build through add_subdirectory"; }
    [ ! -e "$work/subdirectory/scalablefx/tools/sfxc" ] || fail "sfxc was built although SFX_SFXC_EXECUTABLE names one"
    run "$work/subdirectory/sfx_consumer"
else
    fail "mode '$mode'; allowed package, subdirectory"
fi
