// The device a conformance test run uses, chosen on the command line:
//   sfx_conformance --backend vulkan|gles|gl-egl|gl-osmesa --tier high|current
// The current tier runs under the GL ES 3.0 capability ceiling, so it is really tested.
#pragma once

#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "sfx/backends.hpp"
#include "sfx/hal.hpp"
#include "sfx/tiers.hpp"

namespace sfx::test {

Device& device();  // opened once per process
const BackendConfig& backendConfig();
Tier tier();  // the tier under test
const TierProfile& tierProfile();
std::string label();  // "vulkan/high" for messages and file names

// Validation messages (Vulkan layers, GL errors) seen so far; also fails the run at exit.
std::vector<std::string> takeValidationMessages();

// Where tests write diff images and other artifacts: $SFX_TEST_OUTPUT or the build tree's
// test-output (whatever the working directory, so nothing lands in the source tree).
std::string outputDir();

// The repository's root, where tests read scene files: $SFX_SOURCE_DIR, or the tree the binary was
// built from (a copy of the binary run elsewhere, on a device machine, names its own).
std::string sourceDir();

// The driver's name without its build details ("llvmpipe (LLVM 15.0.6, 256 bits)" is
// "llvmpipe"): the vector width varies with the machine, a documented row's key must not.
inline std::string driverName() {
    const std::string& name = device().caps().deviceName;
    return name.substr(0, name.find(" ("));
}

// A window position (pixels) snapped to the device's sub-pixel grid (to nearest), as its
// rasteriser snaps vertices (DeviceLimits::subPixelPrecisionBits): a CPU rasteriser compared with
// the GPU's covers pixel centres and interpolates from the snapped positions.
inline glm::dvec2 snapToSubPixelGrid(const glm::dvec2& windowPx) {
    const double grid = std::ldexp(1.0, int(device().caps().limits.subPixelPrecisionBits));
    return glm::round(windowPx * grid) / grid;
}

}  // namespace sfx::test

// Fails the test case if the backend reported validation messages since the last check.
// clang-format off
#define SFX_REQUIRE_NO_VALIDATION_MESSAGES()                                  \
    do {                                                                      \
        auto sfx_msgs_ = ::sfx::test::takeValidationMessages();               \
        for (const auto& m : sfx_msgs_) UNSCOPED_INFO("validation: " << m);   \
        REQUIRE(sfx_msgs_.empty());                                           \
    } while (0)
// clang-format on

// clang-format off
#define SFX_REQUIRE_OK(expr)                                                  \
    do {                                                                      \
        ::sfx::Status sfx_st_ = (expr);                                       \
        INFO(#expr << " -> " << sfx_st_.toString());                          \
        REQUIRE(sfx_st_.isOk());                                              \
    } while (0)
// clang-format on
