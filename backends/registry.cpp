#include "sfx/backends.hpp"

#include "sfx/null_device.hpp"
#ifdef SFX_HAS_VULKAN
#include "sfx/vulkan_device.hpp"
#endif
#ifdef SFX_HAS_GL
#include "sfx/gl_device.hpp"
#endif

namespace sfx {

std::string toString(const BackendConfig& c) {
    if (c.backend == BackendKind::GL) return "gl-" + (c.platform.empty() ? std::string("osmesa") : c.platform);
    return toString(c.backend);
}

bool parseBackendConfig(const std::string& text, BackendConfig* out) {
    if (text == "vulkan")
        *out = {BackendKind::Vulkan, ""};
    else if (text == "gles")
        *out = {BackendKind::GLES, "egl"};
    else if (text == "gl" || text == "gl-osmesa")
        *out = {BackendKind::GL, "osmesa"};
    else if (text == "gl-egl")
        *out = {BackendKind::GL, "egl"};
    else if (text == "null")
        *out = {BackendKind::Null, ""};
    else
        return false;
    return true;
}

std::vector<BackendConfig> compiledBackends() {
    std::vector<BackendConfig> list;
#ifdef SFX_HAS_VULKAN
    list.push_back({BackendKind::Vulkan, ""});
#endif
#ifdef SFX_HAS_GL
    list.push_back({BackendKind::GLES, "egl"});
    list.push_back({BackendKind::GL, "egl"});
    list.push_back({BackendKind::GL, "osmesa"});
#endif
    return list;
}

Result<std::unique_ptr<Device>> openDevice(const BackendConfig& config, const DeviceOptions& options) {
    if (!options.physicalDevice.empty() && config.backend != BackendKind::Vulkan)
        return Status{StatusCode::InvalidArgument,
                      "DeviceOptions.physicalDevice is '" + options.physicalDevice + "'; backend '" + toString(config) +
                          "' has no choice of device: allowed only empty"};
    switch (config.backend) {
        case BackendKind::Null: return null::createDevice(options);
        case BackendKind::Vulkan:
#ifdef SFX_HAS_VULKAN
            return vulkan::createDevice(options);
#else
            break;
#endif
        case BackendKind::GLES:
        case BackendKind::GL: {
#ifdef SFX_HAS_GL
            const gl::Platform platform = config.platform == "osmesa" ? gl::Platform::OSMesa : gl::Platform::EGL;
            const gl::Api api = config.backend == BackendKind::GLES ? gl::Api::GLES : gl::Api::DesktopGL;
            return gl::createDevice(platform, api, options);
#else
            break;
#endif
        }
    }
    return Status{StatusCode::InvalidArgument, "backend '" + toString(config) + "' is not compiled into this build"};
}

Result<std::vector<std::string>> describeVulkanDevices() {
#ifdef SFX_HAS_VULKAN
    Result<std::vector<vulkan::PhysicalDeviceInfo>> devices = vulkan::listPhysicalDevices();
    if (!devices) return devices.status();
    std::vector<std::string> lines;
    for (const vulkan::PhysicalDeviceInfo& d : devices.value())
        lines.push_back(std::to_string(d.index) + ": " + d.name + ", " + d.type + ", Vulkan " + d.apiVersion + ", " +
                        (d.usable ? std::string("usable") : "unusable: " + d.unusableReason));
    return lines;
#else
    return Status{StatusCode::InvalidArgument, "backend 'vulkan' is not compiled into this build"};
#endif
}

Result<DeviceSelection> openBestDevice(const DeviceOptions& options) {
    DeviceSelection best;
    std::vector<std::string> rejected;
    for (const BackendConfig& config : compiledBackends()) {
        Result<std::unique_ptr<Device>> device = openDevice(config, options);
        if (!device) {
            rejected.push_back(toString(config) + ": " + device.status().toString());
            continue;
        }
        Result<tiers::TierChoice> tier = tiers::choose(device.value()->caps());
        if (!tier) {
            rejected.push_back(toString(config) + ": " + tier.status().toString());
            continue;
        }
        if (best.device && uint32_t(tier->tier) <= uint32_t(best.tier.tier)) {
            rejected.push_back(toString(config) + ": reaches tier '" + toString(tier->tier) + "', no better than " + toString(best.config));
            continue;
        }
        if (best.device) rejected.push_back(toString(best.config) + ": reaches only tier '" + toString(best.tier.tier) + "'");
        best.device = std::move(device.value());
        best.config = config;
        best.tier = tier.value();
    }
    if (!best.device) {
        std::string why;
        for (const auto& r : rejected) why += "\n  " + r;
        return Status{StatusCode::BackendUnavailable, "no backend could be opened:" + why};
    }
    best.rejected = std::move(rejected);
    best.reason = "backend '" + toString(best.config) + "' (" + best.device->caps().summary() + "); " + best.tier.reason;
    return best;
}

}  // namespace sfx
