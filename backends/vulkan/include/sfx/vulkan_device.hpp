// The Vulkan backend: a Device on an instance and device of its own, or on a host engine's
// Vulkan objects. Needs Vulkan 1.3 or VK_KHR_dynamic_rendering (render passes are dynamic).
#pragma once

#include <vulkan/vulkan.h>

#include <memory>

#include "sfx/hal.hpp"

namespace sfx::vulkan {

// Opens the Vulkan loader at run time, creates an instance and a device on the best physical
// device (discrete first). BackendUnavailable with the reason when the loader, an ICD, a 1.3
// device or (with options.validation) VK_LAYER_KHRONOS_validation is missing.
Result<std::unique_ptr<Device>> createDevice(const DeviceOptions& options = {});

// A host engine's Vulkan objects. The SDK uses them but never destroys them; they must outlive
// the Device. The device must have been created with dynamic rendering enabled (Vulkan 1.3
// feature dynamicRendering, or VK_KHR_dynamic_rendering), and, for the high tier,
// fragmentStoresAndAtomics if effects use atomics in fragment shaders.
struct ExternalVulkan {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;  // the SDK submits here when it records into its own command buffers
    uint32_t queueFamily = 0;        // of `queue`; must support graphics and compute
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
    // Set when the host enabled VK_EXT_debug_utils on `instance`: then options.validation adds
    // a messenger whose warnings and errors takeValidationMessages() returns.
    bool debugUtilsEnabled = false;
};
Result<std::unique_ptr<Device>> wrapDevice(const ExternalVulkan& external, const DeviceOptions& options = {});

// Records the SDK's following commands into the host's command buffer, which the host has begun
// and will end and submit itself. flush() then only stops recording into it (the SDK goes back
// to its own command buffers); reads of textures and buffers refuse while it is set, since they
// need a submit. Pass VK_NULL_HANDLE to stop as well. Staging memory and descriptor sets used by
// a host command buffer are released at the next setCommandBuffer call, so the host must have
// finished executing the previous one by then. InvalidArgument when `device` is not Vulkan.
Status setCommandBuffer(Device& device, VkCommandBuffer commandBuffer);

}  // namespace sfx::vulkan
