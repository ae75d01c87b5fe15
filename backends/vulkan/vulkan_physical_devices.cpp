#include "vulkan_physical_devices.hpp"

#include <cstring>
#include <utility>

namespace sfx::vulkan {
namespace {

int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        default: return 1;
    }
}

std::string typeName(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
        default: return "other";
    }
}

std::string listing(const std::vector<PhysicalDeviceCandidate>& candidates) {
    std::string text;
    for (const PhysicalDeviceCandidate& c : candidates)
        text += (text.empty() ? "" : ", ") + std::to_string(c.info.index) + " '" + c.info.name + "'" +
            (c.info.usable ? "" : " (unusable: " + c.info.unusableReason + ")");
    return text.empty() ? "none" : text;
}

bool isIndex(const std::string& s) {
    if (s.empty() || s.size() > 9) return false;
    for (char ch : s)
        if (ch < '0' || ch > '9') return false;
    return true;
}

}  // namespace

std::vector<PhysicalDeviceCandidate> describePhysicalDevices(const Functions& vk, VkInstance instance, uint32_t apiVersion) {
    uint32_t count = 0;
    vk.vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> gpus(count);
    vk.vkEnumeratePhysicalDevices(instance, &count, gpus.data());
    gpus.resize(count);
    std::vector<PhysicalDeviceCandidate> out;
    for (uint32_t i = 0; i < gpus.size(); ++i) {
        PhysicalDeviceCandidate c;
        c.handle = gpus[i];
        VkPhysicalDeviceProperties p;
        vk.vkGetPhysicalDeviceProperties(gpus[i], &p);
        c.info.index = i;
        c.info.name = p.deviceName;
        c.info.type = typeName(p.deviceType);
        c.info.apiVersion = vkVersionString(p.apiVersion);
        c.info.typeRank = typeRank(p.deviceType);
        uint32_t extCount = 0;
        vk.vkEnumerateDeviceExtensionProperties(gpus[i], nullptr, &extCount, nullptr);
        std::vector<VkExtensionProperties> exts(extCount);
        vk.vkEnumerateDeviceExtensionProperties(gpus[i], nullptr, &extCount, exts.data());
        bool khrDynamic = false;
        for (const auto& e : exts) khrDynamic |= std::strcmp(e.extensionName, VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME) == 0;
        const bool core13 = p.apiVersion >= VK_API_VERSION_1_3 && apiVersion >= VK_API_VERSION_1_3;
        c.needsKhrDynamicRendering = !core13;
        uint32_t qCount = 0;
        vk.vkGetPhysicalDeviceQueueFamilyProperties(gpus[i], &qCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(qCount);
        vk.vkGetPhysicalDeviceQueueFamilyProperties(gpus[i], &qCount, families.data());
        int family = -1;
        for (uint32_t q = 0; q < qCount && family < 0; ++q)
            if ((families[q].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) == (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT))
                family = int(q);
        if (!core13 && !(khrDynamic && p.apiVersion >= VK_API_VERSION_1_1)) {
            c.info.unusableReason = "no dynamic rendering";
        } else if (family < 0) {
            c.info.unusableReason = "no graphics+compute queue";
        } else {
            c.info.usable = true;
            c.queueFamily = uint32_t(family);
        }
        out.push_back(std::move(c));
    }
    return out;
}

Result<size_t> choosePhysicalDevice(const std::vector<PhysicalDeviceCandidate>& candidates, const std::string& wanted, std::string& reason) {
    if (candidates.empty()) return Status{StatusCode::BackendUnavailable, "Vulkan reports no physical device (no ICD installed?)"};
    if (!wanted.empty()) {
        size_t match = candidates.size();
        if (isIndex(wanted)) {
            size_t index = std::stoul(wanted);
            if (index < candidates.size()) match = index;
        } else {
            for (size_t i = 0; i < candidates.size() && match == candidates.size(); ++i)
                if (candidates[i].info.name.find(wanted) != std::string::npos) match = i;
        }
        if (match == candidates.size())
            return Status{StatusCode::InvalidArgument,
                          "DeviceOptions.physicalDevice is '" + wanted + "'; allowed an index or part of the name of one of: " + listing(candidates)};
        if (!candidates[match].info.usable)
            return Status{StatusCode::InvalidArgument,
                          "DeviceOptions.physicalDevice '" + wanted + "' names '" + candidates[match].info.name +
                              "', which the SDK cannot use: " + candidates[match].info.unusableReason};
        reason = "asked for by DeviceOptions.physicalDevice '" + wanted + "'";
        return match;
    }
    size_t best = candidates.size();
    for (size_t i = 0; i < candidates.size(); ++i)
        if (candidates[i].info.usable && (best == candidates.size() || candidates[i].info.typeRank > candidates[best].info.typeRank)) best = i;
    if (best == candidates.size()) return Status{StatusCode::BackendUnavailable, "no Vulkan device is usable: " + listing(candidates)};
    size_t usable = 0;
    for (const PhysicalDeviceCandidate& c : candidates) usable += c.info.usable ? 1 : 0;
    reason = usable == 1 ? "the only usable device of " + std::to_string(candidates.size())
                         : "the first of the best type (" + candidates[best].info.type + ") among " + std::to_string(usable) +
            " usable devices (discrete before integrated, virtual, CPU)";
    return best;
}

Result<std::vector<PhysicalDeviceInfo>> listPhysicalDevices() {
    Functions vk;
    void* library = nullptr;
    Status opened = openLoader(vk, library);
    if (!opened.isOk()) {
        closeLoader(library);
        return opened;
    }
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "ScalableFX";
    app.apiVersion = instanceApiVersion(vk);
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    VkInstance instance = VK_NULL_HANDLE;
    VkResult r = vk.vkCreateInstance(&ci, nullptr, &instance);
    if (r != VK_SUCCESS) {
        closeLoader(library);
        return instanceCreationFailed(r);
    }
    std::vector<PhysicalDeviceInfo> out;
    if (loadInstanceFn(vk, instance, "vkDestroyInstance", &vk.vkDestroyInstance) &&
        loadInstanceFn(vk, instance, "vkEnumeratePhysicalDevices", &vk.vkEnumeratePhysicalDevices) &&
        loadInstanceFn(vk, instance, "vkGetPhysicalDeviceProperties", &vk.vkGetPhysicalDeviceProperties) &&
        loadInstanceFn(vk, instance, "vkEnumerateDeviceExtensionProperties", &vk.vkEnumerateDeviceExtensionProperties) &&
        loadInstanceFn(vk, instance, "vkGetPhysicalDeviceQueueFamilyProperties", &vk.vkGetPhysicalDeviceQueueFamilyProperties)) {
        for (PhysicalDeviceCandidate& c : describePhysicalDevices(vk, instance, app.apiVersion)) out.push_back(std::move(c.info));
    }
    if (vk.vkDestroyInstance) vk.vkDestroyInstance(instance, nullptr);
    closeLoader(library);
    return out;
}

}  // namespace sfx::vulkan
