// The composition root of the backends: which ones this build has, opening one by name, and
// picking the best one by capability score with fallback. Samples, tools and tests use this;
// the SDK core and the effects never include it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sfx/hal.hpp"
#include "sfx/tiers.hpp"

namespace sfx {

// A backend and, for GL, its platform.
struct BackendConfig {
    BackendKind backend = BackendKind::Null;
    std::string platform;  // "egl" or "osmesa" for BackendKind::GL; "egl" for GLES; "" otherwise
};
std::string toString(const BackendConfig& config);  // "vulkan", "gles", "gl-osmesa", "gl-egl", "null"
// Accepts the names above and "gl" (= gl-osmesa). False for anything else.
bool parseBackendConfig(const std::string& text, BackendConfig* out);

// The backends compiled into this build, best first: vulkan, gles, gl-egl, gl-osmesa.
std::vector<BackendConfig> compiledBackends();

// BackendUnavailable (with the reason: no loader, no ICD, no EGL display...) when the API is
// absent on this machine; InvalidArgument for a backend this build does not include.
Result<std::unique_ptr<Device>> openDevice(const BackendConfig& config, const DeviceOptions& options = {});

// The Vulkan physical devices the loader sees, one line each in the loader's order:
// "0: llvmpipe (LLVM 15.0.6, 256 bits), CPU, Vulkan 1.3.239, usable". DeviceOptions::physicalDevice
// takes the index or part of the name. BackendUnavailable without a loader or driver;
// InvalidArgument when this build has no Vulkan backend.
Result<std::vector<std::string>> describeVulkanDevices();

struct DeviceSelection {
    std::unique_ptr<Device> device;
    BackendConfig config;
    tiers::TierChoice tier;
    std::string reason;                 // why this backend and tier
    std::vector<std::string> rejected;  // each backend tried before it, and why it lost
};

// Opens every compiled backend in preference order and keeps the one whose device reaches the
// highest tier (ties go to the earlier backend); falls back past backends that fail to open.
Result<DeviceSelection> openBestDevice(const DeviceOptions& options = {});

}  // namespace sfx
