// Platform: the loader, the instance (with the validation layer and its messenger when asked),
// the physical device pick and the logical device, or the host's objects when wrapping; then the
// per-device objects every command needs. Also the backend's public entry points.
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "vulkan_device_impl.hpp"
#include "vulkan_physical_devices.hpp"

#include "sfx/validation_errors.hpp"

namespace sfx::vulkan {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* device = static_cast<VulkanDevice*>(user);
    const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    std::string text = std::string("vulkan ") + level + ": " + (data && data->pMessage ? data->pMessage : "(no text)");
    if (device) device->addValidationMessage(std::move(text));
    return VK_FALSE;  // never abort the call
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(void* user) {
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
        VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = debugCallback;
    info.pUserData = user;
    return info;
}

}  // namespace

Status VulkanDevice::initOwn(const DeviceOptions& options) {
    uint32_t apiVersion = 0;
    SFX_TRY(createInstance(options, apiVersion));
    bool needsKhrDynamicRendering = false;
    SFX_TRY(pickPhysicalDevice(apiVersion, options.physicalDevice, needsKhrDynamicRendering));
    SFX_TRY(createLogicalDevice(needsKhrDynamicRendering));
    return finishInit(options, true);
}

// The loader, then an instance of the highest version up to 1.3 it offers (at least 1.1), with
// the validation layer and debug utils when asked; apiVersion is what the instance was made for.
Status VulkanDevice::createInstance(const DeviceOptions& options, uint32_t& apiVersion) {
    SFX_TRY(openLoader(vk_, setup_.loaderLibrary));
    const uint32_t instanceVersion = instanceApiVersion(vk_);
    if (instanceVersion < VK_API_VERSION_1_1)
        return {StatusCode::BackendUnavailable, "the Vulkan loader supports only Vulkan 1.0; 1.1 or later is needed"};

    std::vector<const char*> layers, extensions;
    if (options.validation) {
        uint32_t count = 0;
        vk_.vkEnumerateInstanceLayerProperties(&count, nullptr);
        std::vector<VkLayerProperties> available(count);
        vk_.vkEnumerateInstanceLayerProperties(&count, available.data());
        bool found = false;
        for (const auto& l : available) found |= std::strcmp(l.layerName, "VK_LAYER_KHRONOS_validation") == 0;
        if (!found)
            return {StatusCode::BackendUnavailable,
                    "DeviceOptions.validation asks for VK_LAYER_KHRONOS_validation, which is not installed "
                    "(Debian/Ubuntu package vulkan-validationlayers)"};
        layers.push_back("VK_LAYER_KHRONOS_validation");
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);  // the layer provides it
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "ScalableFX";
    app.pEngineName = "ScalableFX";
    app.apiVersion = instanceVersion;
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    ci.enabledLayerCount = uint32_t(layers.size());
    ci.ppEnabledLayerNames = layers.data();
    ci.enabledExtensionCount = uint32_t(extensions.size());
    ci.ppEnabledExtensionNames = extensions.data();
    // Chained so that messages of vkCreateInstance / vkDestroyInstance are caught as well.
    VkDebugUtilsMessengerCreateInfoEXT dbg = messengerInfo(this);
    // Synchronization validation as well as the core checks: a missing or wrong barrier is a
    // message like any other.
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;
    features.pNext = &dbg;
    if (options.validation) ci.pNext = &features;
    VkResult r = vk_.vkCreateInstance(&ci, nullptr, &setup_.instance);
    if (r != VK_SUCCESS) return instanceCreationFailed(r);
    setup_.ownsInstance = true;
    setup_.debugUtils = options.validation;
    SFX_TRY(loadInstanceFunctions(vk_, setup_.instance));
    apiVersion = app.apiVersion;
    return Status::ok();
}

Status VulkanDevice::pickPhysicalDevice(uint32_t apiVersion, const std::string& wanted, bool& needsKhrDynamicRendering) {
    std::vector<PhysicalDeviceCandidate> candidates = describePhysicalDevices(vk_, setup_.instance, apiVersion);
    Result<size_t> chosen = choosePhysicalDevice(candidates, wanted, deviceChoice_);
    if (!chosen) return chosen.status();
    physical_ = candidates[chosen.value()].handle;
    queueFamily_ = candidates[chosen.value()].queueFamily;
    needsKhrDynamicRendering = candidates[chosen.value()].needsKhrDynamicRendering;
    return Status::ok();
}

Status VulkanDevice::createLogicalDevice(bool needsKhrDynamicRendering) {
    // Features: dynamic rendering always; stores and atomics outside compute when present.
    VkPhysicalDeviceFeatures supported{};
    vk_.vkGetPhysicalDeviceFeatures(physical_, &supported);
    VkPhysicalDeviceFeatures enabled{};
    enabled.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
    fragmentStoresAndAtomics_ = supported.fragmentStoresAndAtomics == VK_TRUE;
    enabled.vertexPipelineStoresAndAtomics = supported.vertexPipelineStoresAndAtomics;
    enabled.shaderStorageImageWriteWithoutFormat = supported.shaderStorageImageWriteWithoutFormat;
    enabled.shaderStorageImageReadWithoutFormat = supported.shaderStorageImageReadWithoutFormat;
    // Index values are not checked on the host (the index buffer lives on the device); with
    // robust access an out-of-range index reads zeros instead of memory past the vertex buffer.
    enabled.robustBufferAccess = supported.robustBufferAccess;
    VkPhysicalDeviceDynamicRenderingFeatures dynamic{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES};
    dynamic.dynamicRendering = VK_TRUE;
    // synchronization2 on a 1.3 device that has it: one barrier command per SDK command.
    VkPhysicalDeviceSynchronization2Features sync2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES};
    if (!needsKhrDynamicRendering) {
        VkPhysicalDeviceFeatures2 query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        query.pNext = &sync2;
        vk_.vkGetPhysicalDeviceFeatures2(physical_, &query);
        sync2.pNext = nullptr;
        if (sync2.synchronization2) dynamic.pNext = &sync2;
    }
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = queueFamily_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    std::vector<const char*> deviceExtensions;
    if (needsKhrDynamicRendering) deviceExtensions.push_back(VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME);
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.pNext = &dynamic;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    dci.pEnabledFeatures = &enabled;
    dci.enabledExtensionCount = uint32_t(deviceExtensions.size());
    dci.ppEnabledExtensionNames = deviceExtensions.data();
    VkResult r = vk_.vkCreateDevice(physical_, &dci, nullptr, &device_);
    if (r != VK_SUCCESS) return {StatusCode::BackendUnavailable, "vkCreateDevice failed: " + vkResultName(r)};
    ownsDevice_ = true;
    SFX_TRY(loadDeviceFunctions(vk_, device_));
    synchronization2_ = sync2.synchronization2 == VK_TRUE && vk_.vkCmdPipelineBarrier2;
    vk_.vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    return Status::ok();
}

Status VulkanDevice::initWrapped(const ExternalVulkan& ext, const DeviceOptions& options) {
    using validation::Error;
    if (!ext.getInstanceProcAddr)
        return validation::fail(Error::ExternalObjectNull, {"ExternalVulkan.getInstanceProcAddr", "the host's vkGetInstanceProcAddr"});
    if (!ext.instance) return validation::fail(Error::ExternalObjectNull, {"ExternalVulkan.instance", "the host's VkInstance"});
    if (!ext.physicalDevice) return validation::fail(Error::ExternalObjectNull, {"ExternalVulkan.physicalDevice", "the host's VkPhysicalDevice"});
    if (!ext.device) return validation::fail(Error::ExternalObjectNull, {"ExternalVulkan.device", "the host's VkDevice"});
    if (!ext.queue) return validation::fail(Error::ExternalObjectNull, {"ExternalVulkan.queue", "a queue of the host's device"});
    vk_.vkGetInstanceProcAddr = ext.getInstanceProcAddr;
    setup_.instance = ext.instance;
    setup_.ownsInstance = false;
    SFX_TRY(loadInstanceFunctions(vk_, setup_.instance));
    physical_ = ext.physicalDevice;
    queueFamily_ = ext.queueFamily;
    ownsDevice_ = false;
    VkPhysicalDeviceProperties props{};
    vk_.vkGetPhysicalDeviceProperties(physical_, &props);
    if (props.apiVersion < VK_API_VERSION_1_1)
        return validation::fail(Error::ExternalApiVersion,
                                {std::to_string(VK_API_VERSION_MAJOR(props.apiVersion)), std::to_string(VK_API_VERSION_MINOR(props.apiVersion))});
    uint32_t qCount = 0;
    vk_.vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qCount, nullptr);
    if (queueFamily_ >= qCount) return validation::fail(Error::ExternalQueueFamily, {std::to_string(queueFamily_), std::to_string(qCount - 1)});
    std::vector<VkQueueFamilyProperties> families(qCount);
    vk_.vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qCount, families.data());
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if ((families[queueFamily_].queueFlags & needed) != needed) {
        std::string flags;
        for (const auto& [bit, name] : {std::pair{VK_QUEUE_GRAPHICS_BIT, "graphics"},
                                        {VK_QUEUE_COMPUTE_BIT, "compute"},
                                        {VK_QUEUE_TRANSFER_BIT, "transfer"},
                                        {VK_QUEUE_SPARSE_BINDING_BIT, "sparse-binding"}})
            if (families[queueFamily_].queueFlags & bit) flags += (flags.empty() ? "" : " | ") + std::string(name);
        return validation::fail(Error::ExternalQueueFamilyFlags, {std::to_string(queueFamily_), flags.empty() ? "none" : flags});
    }
    // The device only now: a refusal above leaves nothing for the destructor to wait on.
    device_ = ext.device;
    queue_ = ext.queue;
    SFX_TRY(loadDeviceFunctions(vk_, device_));
    if (ext.synchronization2Enabled && !vk_.vkCmdPipelineBarrier2) return validation::fail(Error::ExternalSynchronization2, {});
    synchronization2_ = ext.synchronization2Enabled;
    setup_.debugUtils = ext.debugUtilsEnabled;
    return finishInit(options, false);
}

Status VulkanDevice::finishInit(const DeviceOptions& options, bool) {
    log_ = options.log;
    if (setup_.debugUtils) {
        loadInstanceFn(vk_, setup_.instance, "vkCreateDebugUtilsMessengerEXT", &vk_.vkCreateDebugUtilsMessengerEXT);
        loadInstanceFn(vk_, setup_.instance, "vkDestroyDebugUtilsMessengerEXT", &vk_.vkDestroyDebugUtilsMessengerEXT);
        loadInstanceFn(vk_, setup_.instance, "vkSetDebugUtilsObjectNameEXT", &vk_.vkSetDebugUtilsObjectNameEXT);
        if (options.validation && vk_.vkCreateDebugUtilsMessengerEXT) {
            VkDebugUtilsMessengerCreateInfoEXT info = messengerInfo(this);
            SFX_VK(vk_.vkCreateDebugUtilsMessengerEXT(setup_.instance, &info, nullptr, &messenger_));
        }
    }
    vk_.vkGetPhysicalDeviceProperties(physical_, &props_);
    vk_.vkGetPhysicalDeviceMemoryProperties(physical_, &memProps_);
    uint32_t qCount = 0;
    vk_.vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(qCount);
    vk_.vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qCount, families.data());
    timestampValidBits_ = families[queueFamily_].timestampValidBits;
    fullFeatures_ = options.ceiling == CapabilityCeiling::None;
    fillCaps(options);

    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pci.queueFamilyIndex = queueFamily_;
    SFX_VK(vk_.vkCreateCommandPool(device_, &pci, nullptr, &commandPool_));
    Result<VkCommandBuffer> primary = allocateCommandBuffer(VK_COMMAND_BUFFER_LEVEL_PRIMARY);
    if (!primary) return primary.status();
    commandBuffer_ = primary.value();
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    SFX_VK(vk_.vkCreateFence(device_, &fci, nullptr, &fence_));

    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
    sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sci.maxLod = VK_LOD_CLAMP_NONE;
    SFX_VK(vk_.vkCreateSampler(device_, &sci, nullptr, &defaultSampler_));

    return createTimerPool();
}

void VulkanDevice::setName(VkObjectType type, uint64_t handle, const char* name) {
    if (!vk_.vkSetDebugUtilsObjectNameEXT || !name || !*name) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name;
    vk_.vkSetDebugUtilsObjectNameEXT(device_, &info);
}

namespace {

// A failed open explains itself with what the loader and layers said on the way.
Status withMessages(const Status& s, VulkanDevice& device) {
    std::string text = s.message();
    for (const std::string& m : device.takeValidationMessages()) text += "; " + m;
    return {s.code(), text};
}

}  // namespace

Result<std::unique_ptr<Device>> createDevice(const DeviceOptions& options) {
    auto device = std::make_unique<VulkanDevice>();
    Status s = device->initOwn(options);
    if (!s) return withMessages(s, *device);
    return std::unique_ptr<Device>(std::move(device));
}

Result<std::unique_ptr<Device>> wrapDevice(const ExternalVulkan& external, const DeviceOptions& options) {
    auto device = std::make_unique<VulkanDevice>();
    Status s = device->initWrapped(external, options);
    if (!s) return withMessages(s, *device);
    return std::unique_ptr<Device>(std::move(device));
}

Status setCommandBuffer(Device& device, VkCommandBuffer commandBuffer, bool previousFinished) {
    auto* vk = dynamic_cast<VulkanDevice*>(&device);
    if (!vk) return validation::fail(validation::Error::DeviceWrongApi, {"setCommandBuffer", toString(device.caps().backend), "Vulkan"});
    // Only a wrapped device shares the host's VkDevice; VK_NULL_HANDLE (stop) is fine on either.
    if (vk->ownsDevice_ && commandBuffer) return validation::fail(validation::Error::HostCommandBufferOwnDevice, {});
    return vk->setHostCommandBuffer(commandBuffer, previousFinished);
}

}  // namespace sfx::vulkan
