// The Vulkan function table. The loader is opened at run time (own device) or the host's
// vkGetInstanceProcAddr is used (wrapped device); every call the backend makes goes through
// the table, so nothing links against libvulkan.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include "sfx/status.hpp"

namespace sfx::vulkan {

// clang-format off
#define SFX_VK_INSTANCE_FUNCTIONS(X)            \
    X(vkDestroyInstance)                        \
    X(vkEnumeratePhysicalDevices)               \
    X(vkGetPhysicalDeviceProperties)            \
    X(vkGetPhysicalDeviceFeatures)              \
    X(vkGetPhysicalDeviceFeatures2)             \
    X(vkGetPhysicalDeviceQueueFamilyProperties) \
    X(vkGetPhysicalDeviceMemoryProperties)      \
    X(vkGetPhysicalDeviceFormatProperties)      \
    X(vkEnumerateDeviceExtensionProperties)     \
    X(vkCreateDevice)                           \
    X(vkGetDeviceProcAddr)
// clang-format on

// clang-format off
#define SFX_VK_DEVICE_FUNCTIONS(X)      \
    X(vkDestroyDevice)                  \
    X(vkGetDeviceQueue)                 \
    X(vkDeviceWaitIdle)                 \
    X(vkQueueWaitIdle)                  \
    X(vkQueueSubmit)                    \
    X(vkCreateFence)                    \
    X(vkDestroyFence)                   \
    X(vkWaitForFences)                  \
    X(vkResetFences)                    \
    X(vkCreateCommandPool)              \
    X(vkDestroyCommandPool)             \
    X(vkAllocateCommandBuffers)         \
    X(vkBeginCommandBuffer)             \
    X(vkEndCommandBuffer)               \
    X(vkResetCommandBuffer)             \
    X(vkAllocateMemory)                 \
    X(vkFreeMemory)                     \
    X(vkMapMemory)                      \
    X(vkUnmapMemory)                    \
    X(vkCreateBuffer)                   \
    X(vkDestroyBuffer)                  \
    X(vkGetBufferMemoryRequirements)    \
    X(vkBindBufferMemory)               \
    X(vkCreateImage)                    \
    X(vkDestroyImage)                   \
    X(vkGetImageMemoryRequirements)     \
    X(vkBindImageMemory)                \
    X(vkCreateImageView)                \
    X(vkDestroyImageView)               \
    X(vkCreateSampler)                  \
    X(vkDestroySampler)                 \
    X(vkCreateShaderModule)             \
    X(vkDestroyShaderModule)            \
    X(vkCreateDescriptorSetLayout)      \
    X(vkDestroyDescriptorSetLayout)     \
    X(vkCreatePipelineLayout)           \
    X(vkDestroyPipelineLayout)          \
    X(vkCreateGraphicsPipelines)        \
    X(vkCreateComputePipelines)         \
    X(vkDestroyPipeline)                \
    X(vkCreateDescriptorPool)           \
    X(vkDestroyDescriptorPool)          \
    X(vkResetDescriptorPool)            \
    X(vkAllocateDescriptorSets)         \
    X(vkUpdateDescriptorSets)           \
    X(vkCreateQueryPool)                \
    X(vkDestroyQueryPool)               \
    X(vkGetQueryPoolResults)            \
    X(vkCmdResetQueryPool)              \
    X(vkCmdWriteTimestamp)              \
    X(vkCmdPipelineBarrier)             \
    X(vkCmdCopyBuffer)                  \
    X(vkCmdCopyBufferToImage)           \
    X(vkCmdCopyImageToBuffer)           \
    X(vkCmdBindPipeline)                \
    X(vkCmdBindDescriptorSets)          \
    X(vkCmdBindVertexBuffers)           \
    X(vkCmdBindIndexBuffer)             \
    X(vkCmdSetViewport)                 \
    X(vkCmdSetScissor)                  \
    X(vkCmdDraw)                        \
    X(vkCmdExecuteCommands)             \
    X(vkCmdDrawIndexed)                 \
    X(vkCmdDispatch)
// clang-format on

struct Functions {
    PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr = nullptr;
    PFN_vkCreateInstance vkCreateInstance = nullptr;
    PFN_vkEnumerateInstanceLayerProperties vkEnumerateInstanceLayerProperties = nullptr;
    PFN_vkEnumerateInstanceVersion vkEnumerateInstanceVersion = nullptr;
#define SFX_DECLARE(name) PFN_##name name = nullptr;
    SFX_VK_INSTANCE_FUNCTIONS(SFX_DECLARE)
    SFX_VK_DEVICE_FUNCTIONS(SFX_DECLARE)
#undef SFX_DECLARE
    // Core in 1.3, or the KHR extension's entry points.
    PFN_vkCmdBeginRendering vkCmdBeginRendering = nullptr;
    PFN_vkCmdEndRendering vkCmdEndRendering = nullptr;
    // Core in 1.3, or VK_KHR_synchronization2; used only where the device enabled the feature.
    PFN_vkCmdPipelineBarrier2 vkCmdPipelineBarrier2 = nullptr;
    // VK_EXT_debug_utils, when enabled.
    PFN_vkCreateDebugUtilsMessengerEXT vkCreateDebugUtilsMessengerEXT = nullptr;
    PFN_vkDestroyDebugUtilsMessengerEXT vkDestroyDebugUtilsMessengerEXT = nullptr;
    PFN_vkSetDebugUtilsObjectNameEXT vkSetDebugUtilsObjectNameEXT = nullptr;
};

template <class F>
bool loadInstanceFn(const Functions& f, VkInstance instance, const char* name, F* out) {
    *out = reinterpret_cast<F>(f.vkGetInstanceProcAddr(instance, name));
    return *out != nullptr;
}
template <class F>
bool loadDeviceFn(const Functions& f, VkDevice device, const char* name, F* out) {
    *out = reinterpret_cast<F>(f.vkGetDeviceProcAddr(device, name));
    return *out != nullptr;
}

// Opens libvulkan and loads vkGetInstanceProcAddr and the global entry points; `library` holds
// the handle (from the moment it is opened, so closeLoader releases it on any later failure).
Status openLoader(Functions& f, void*& library);
void closeLoader(void*& library);

// Every instance- and device-level entry point of the lists above; BackendUnavailable names the
// first one missing (and dynamic rendering, core or KHR, is required).
Status loadInstanceFunctions(Functions& f, VkInstance instance);
Status loadDeviceFunctions(Functions& f, VkDevice device);

std::string vkResultName(VkResult r);
// "1.3.239": a packed Vulkan version as major.minor.patch.
std::string vkVersionString(uint32_t version);
// The API version an own instance is made for: the loader's, at most 1.3.
uint32_t instanceApiVersion(const Functions& f);
// BackendUnavailable for a failed vkCreateInstance: no usable driver.
Status instanceCreationFailed(VkResult r);
// DeviceError naming the call and its result.
Status vkError(const char* call, VkResult r);

// Returns vkError from the enclosing function when `call` does not return VK_SUCCESS.
// clang-format off
#define SFX_VK(call)                                           \
    do {                                                       \
        VkResult sfx_vk_result_ = (call);                      \
        if (sfx_vk_result_ != VK_SUCCESS) return vkError(#call, sfx_vk_result_); \
    } while (0)
// clang-format on

}  // namespace sfx::vulkan
