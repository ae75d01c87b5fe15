// Loading the function table through vkGetInstanceProcAddr / vkGetDeviceProcAddr, and naming
// VkResults in statuses.
#include "vulkan_loader.hpp"

#include <dlfcn.h>

namespace sfx::vulkan {

Status openLoader(Functions& f, void*& library) {
    // The loader is opened here rather than linked, so its absence is a status, not a crash.
    void* lib = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!lib) lib = dlopen("libvulkan.so", RTLD_NOW | RTLD_LOCAL);
    if (!lib)
        return {StatusCode::BackendUnavailable,
                std::string("the Vulkan loader (libvulkan.so.1, package libvulkan1) could not be opened: ") + dlerror()};
    library = lib;
    f.vkGetInstanceProcAddr = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(lib, "vkGetInstanceProcAddr"));
    if (!f.vkGetInstanceProcAddr) return {StatusCode::BackendUnavailable, "the Vulkan loader has no vkGetInstanceProcAddr"};
    loadInstanceFn(f, VK_NULL_HANDLE, "vkCreateInstance", &f.vkCreateInstance);
    loadInstanceFn(f, VK_NULL_HANDLE, "vkEnumerateInstanceLayerProperties", &f.vkEnumerateInstanceLayerProperties);
    loadInstanceFn(f, VK_NULL_HANDLE, "vkEnumerateInstanceVersion", &f.vkEnumerateInstanceVersion);
    if (!f.vkCreateInstance || !f.vkEnumerateInstanceLayerProperties)
        return {StatusCode::BackendUnavailable, "the Vulkan loader lacks vkCreateInstance"};
    return Status::ok();
}

void closeLoader(void*& library) {
    if (library) dlclose(library);
    library = nullptr;
}

Status loadInstanceFunctions(Functions& f, VkInstance instance) {
// clang-format off
#define SFX_LOAD(name)                                       \
    if (!loadInstanceFn(f, instance, #name, &f.name))        \
        return {StatusCode::BackendUnavailable, "the Vulkan loader lacks " #name};
    // clang-format on
    SFX_VK_INSTANCE_FUNCTIONS(SFX_LOAD)
#undef SFX_LOAD
    return Status::ok();
}

Status loadDeviceFunctions(Functions& f, VkDevice device) {
// clang-format off
#define SFX_LOAD(name)                                \
    if (!loadDeviceFn(f, device, #name, &f.name))     \
        return {StatusCode::BackendUnavailable, "the Vulkan device lacks " #name};
    // clang-format on
    SFX_VK_DEVICE_FUNCTIONS(SFX_LOAD)
#undef SFX_LOAD
    if (!loadDeviceFn(f, device, "vkCmdBeginRendering", &f.vkCmdBeginRendering))
        loadDeviceFn(f, device, "vkCmdBeginRenderingKHR", &f.vkCmdBeginRendering);
    if (!loadDeviceFn(f, device, "vkCmdEndRendering", &f.vkCmdEndRendering)) loadDeviceFn(f, device, "vkCmdEndRenderingKHR", &f.vkCmdEndRendering);
    if (!loadDeviceFn(f, device, "vkCmdPipelineBarrier2", &f.vkCmdPipelineBarrier2))
        loadDeviceFn(f, device, "vkCmdPipelineBarrier2KHR", &f.vkCmdPipelineBarrier2);
    if (!f.vkCmdBeginRendering || !f.vkCmdEndRendering)
        return {StatusCode::BackendUnavailable, "the Vulkan device has no dynamic rendering (Vulkan 1.3 or VK_KHR_dynamic_rendering)"};
    return Status::ok();
}

std::string vkVersionString(uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) + "." +
        std::to_string(VK_API_VERSION_PATCH(version));
}

uint32_t instanceApiVersion(const Functions& f) {
    uint32_t version = VK_API_VERSION_1_0;
    if (f.vkEnumerateInstanceVersion) f.vkEnumerateInstanceVersion(&version);
    return version >= VK_API_VERSION_1_3 ? VK_API_VERSION_1_3 : version;
}

Status instanceCreationFailed(VkResult r) {
    return {StatusCode::BackendUnavailable, "vkCreateInstance failed (" + vkResultName(r) + "): no usable Vulkan driver (ICD) on this machine"};
}

std::string vkResultName(VkResult r) {
    switch (r) {
        case VK_SUCCESS: return "VK_SUCCESS";
        case VK_NOT_READY: return "VK_NOT_READY";
        case VK_TIMEOUT: return "VK_TIMEOUT";
        case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
        case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
        case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
        case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
        case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
        case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
        case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
        case VK_ERROR_OUT_OF_POOL_MEMORY: return "VK_ERROR_OUT_OF_POOL_MEMORY";
        case VK_ERROR_INVALID_SHADER_NV: return "VK_ERROR_INVALID_SHADER_NV";
        default: return "VkResult " + std::to_string(int(r));
    }
}

Status vkError(const char* call, VkResult r) { return {StatusCode::DeviceError, std::string(call) + " failed: " + vkResultName(r)}; }

}  // namespace sfx::vulkan
