// What the loader's physical devices are, whether the SDK can use each, and which one an own
// device opens: the one the host names (DeviceOptions::physicalDevice), else the best by type.
#pragma once

#include <string>
#include <vector>

#include "sfx/vulkan_device.hpp"
#include "vulkan_loader.hpp"

namespace sfx::vulkan {

struct PhysicalDeviceCandidate {
    PhysicalDeviceInfo info;
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    bool needsKhrDynamicRendering = false;
};

// Every physical device of `instance` (made for `apiVersion`), in the loader's order.
std::vector<PhysicalDeviceCandidate> describePhysicalDevices(const Functions& vk, VkInstance instance, uint32_t apiVersion);

// The candidate an own device opens, and why (PhysicalDeviceChoice::reason). `wanted` empty: the
// usable one of the best type (discrete, integrated, virtual, CPU; ties to the earlier);
// otherwise a decimal index in the loader's order or text contained in the device's name.
// InvalidArgument names DeviceOptions.physicalDevice and lists the devices when nothing
// matches or the match cannot be used; BackendUnavailable when no device is usable.
Result<size_t> choosePhysicalDevice(const std::vector<PhysicalDeviceCandidate>& candidates, const std::string& wanted, std::string& reason);

}  // namespace sfx::vulkan
