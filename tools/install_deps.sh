#!/usr/bin/env bash
# Installs ScalableFX's build and test dependencies from Debian's packages.
# Idempotent: when every package is present it installs nothing and touches no network.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  libglm-dev                      # math
  glslang-dev glslang-tools       # GLSL -> SPIR-V (C++ API used by tools/sfxc)
  spirv-tools                     # SPIR-V validation
  libspirv-cross-c-shared-dev     # SPIR-V -> ESSL/GLSL + reflection (static C++ libs)
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers  # loader, lavapipe, validation
  libegl-dev libgles-dev libgl-dev libosmesa6-dev libegl-mesa0 libgl1-mesa-dri  # EGL, GLES, GL, OSMesa
  catch2                          # unit tests (v2)
  libpng-dev libopenexr-dev       # PNG and EXR image files
  libcli11-dev                    # CLI parsing for sfx and sfxc
  libtinyobjloader-dev glmark2-data  # OBJ loading, the Stanford bunny
  libassimp-dev                   # glmark2's 3DS horse and cat (the AO scene families)
  libembree-dev                   # CPU ray tracing: the ambient-occlusion ground truth
  nlohmann-json3-dev              # scene files (sfx render)
  clang-14 libclang-rt-14-dev     # sanitizer builds and libFuzzer targets
  ccache                          # faster rebuilds; used when present
  python3                         # tests only: the layering and documentation checks
  clang-format-14                 # tests only: the layout check (tests/check_format.sh)
  chromium-common                 # tests only: Google's SwiftShader, a second, independent Vulkan driver
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install_deps: done"
