// Misuse of the Vulkan host-integration entry points (wrapDevice, setCommandBuffer, importImage,
// nativeImage): each refusal is a row of the validation table (sfx/validation_errors.hpp) with
// its code and its whole message checked here. The rows need a host's Vulkan objects, so the
// device-independent parity cases (tests/conformance/validation_cases.cpp) list them as covered
// here. What the physical device reports that lavapipe never does (Vulkan 1.0, a family without
// graphics) comes through a host loader that changes those answers, as a driver could give them.
#include <catch2/catch.hpp>

#include <vulkan/vulkan.h>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "host_vulkan.hpp"
#include "sfx/null_device.hpp"
#include "sfx/validation_errors.hpp"
#include "sfx/vulkan_device.hpp"
#include "skips.hpp"

using namespace sfx;
using hostvk::Host;
using validation::Error;

namespace {

void checkRefusal(const Status& s, Error rule, const std::string& expected) {
    INFO(validation::entry(rule).name << " -> " << s.toString());
    CHECK(s.code() == validation::entry(rule).code);
    CHECK(s.message() == expected);
}

// The host loader seen through a driver that reports Vulkan 1.0, or queue families without
// graphics: what the SDK is told decides its answer.
bool gReportVulkan10 = false;
bool gReportNoGraphics = false;
bool gHideBarrier2 = false;  // the device lacks vkCmdPipelineBarrier2, as a 1.1 device without the extension
PFN_vkGetPhysicalDeviceProperties gRealProperties = nullptr;
PFN_vkGetDeviceProcAddr gRealDeviceProcAddr = nullptr;
PFN_vkGetPhysicalDeviceQueueFamilyProperties gRealFamilies = nullptr;

VKAPI_ATTR void VKAPI_CALL reportedProperties(VkPhysicalDevice physical, VkPhysicalDeviceProperties* out) {
    gRealProperties(physical, out);
    if (gReportVulkan10) out->apiVersion = VK_API_VERSION_1_0;
}
VKAPI_ATTR void VKAPI_CALL reportedFamilies(VkPhysicalDevice physical, uint32_t* count, VkQueueFamilyProperties* out) {
    gRealFamilies(physical, count, out);
    if (gReportNoGraphics && out)
        for (uint32_t i = 0; i < *count; ++i) out[i].queueFlags &= ~VkQueueFlags(VK_QUEUE_GRAPHICS_BIT);
}
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL reportedDeviceFunction(VkDevice device, const char* name) {
    if (gHideBarrier2 && std::strncmp(name, "vkCmdPipelineBarrier2", 21) == 0) return nullptr;
    return gRealDeviceProcAddr(device, name);
}
VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL reportingLoader(VkInstance instance, const char* name) {
    if (std::strcmp(name, "vkGetDeviceProcAddr") == 0) {
        gRealDeviceProcAddr = reinterpret_cast<PFN_vkGetDeviceProcAddr>(vkGetInstanceProcAddr(instance, name));
        return reinterpret_cast<PFN_vkVoidFunction>(&reportedDeviceFunction);
    }
    if (std::strcmp(name, "vkGetPhysicalDeviceProperties") == 0) {
        gRealProperties = reinterpret_cast<PFN_vkGetPhysicalDeviceProperties>(vkGetInstanceProcAddr(instance, name));
        return reinterpret_cast<PFN_vkVoidFunction>(&reportedProperties);
    }
    if (std::strcmp(name, "vkGetPhysicalDeviceQueueFamilyProperties") == 0) {
        gRealFamilies = reinterpret_cast<PFN_vkGetPhysicalDeviceQueueFamilyProperties>(vkGetInstanceProcAddr(instance, name));
        return reinterpret_cast<PFN_vkVoidFunction>(&reportedFamilies);
    }
    return vkGetInstanceProcAddr(instance, name);
}

}  // namespace

TEST_CASE(
    "vulkan entry points: wrapDevice refuses null objects, a family out of range or without graphics, Vulkan 1.0, "
    "synchronization2 without its entry point",
    "[vulkan][validation]") {
    Host host;
    if (!host.create(false)) SFX_SKIP(host.skipReason);
    const vulkan::ExternalVulkan good = host.external();

    struct NullCase {
        const char* field;
        const char* allowed;
        void (*clear)(vulkan::ExternalVulkan&);
    };
    const NullCase nulls[] = {
        {"ExternalVulkan.getInstanceProcAddr", "the host's vkGetInstanceProcAddr",
         [](vulkan::ExternalVulkan& e) { e.getInstanceProcAddr = nullptr; }},
        {"ExternalVulkan.instance", "the host's VkInstance", [](vulkan::ExternalVulkan& e) { e.instance = VK_NULL_HANDLE; }},
        {"ExternalVulkan.physicalDevice", "the host's VkPhysicalDevice", [](vulkan::ExternalVulkan& e) { e.physicalDevice = VK_NULL_HANDLE; }},
        {"ExternalVulkan.device", "the host's VkDevice", [](vulkan::ExternalVulkan& e) { e.device = VK_NULL_HANDLE; }},
        {"ExternalVulkan.queue", "a queue of the host's device", [](vulkan::ExternalVulkan& e) { e.queue = VK_NULL_HANDLE; }},
    };
    for (const NullCase& n : nulls) {
        vulkan::ExternalVulkan e = good;
        n.clear(e);
        checkRefusal(vulkan::wrapDevice(e).status(), Error::ExternalObjectNull, std::string(n.field) + " is null; allowed " + n.allowed);
    }

    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(host.physical, &families, nullptr);
    vulkan::ExternalVulkan e = good;
    e.queueFamily = families;
    checkRefusal(vulkan::wrapDevice(e).status(), Error::ExternalQueueFamily,
                 "ExternalVulkan.queueFamily is " + std::to_string(families) + "; allowed [0, " + std::to_string(families - 1) +
                     "], the queue families of ExternalVulkan.physicalDevice");

    e = good;
    e.getInstanceProcAddr = &reportingLoader;
    gReportNoGraphics = true;
    Result<std::unique_ptr<Device>> noGraphics = vulkan::wrapDevice(e);
    gReportNoGraphics = false;
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(host.physical, &families, props.data());
    std::string flags;  // the host's family as reported: its real flags less graphics
    for (const auto& [bit, name] :
         {std::pair{VK_QUEUE_COMPUTE_BIT, "compute"}, {VK_QUEUE_TRANSFER_BIT, "transfer"}, {VK_QUEUE_SPARSE_BINDING_BIT, "sparse-binding"}})
        if (props[good.queueFamily].queueFlags & bit) flags += (flags.empty() ? "" : " | ") + std::string(name);
    checkRefusal(noGraphics.status(), Error::ExternalQueueFamilyFlags,
                 "ExternalVulkan.queueFamily is " + std::to_string(good.queueFamily) + ", a family with flags " + (flags.empty() ? "none" : flags) +
                     "; allowed a family with graphics and compute");

    gReportVulkan10 = true;
    Result<std::unique_ptr<Device>> old = vulkan::wrapDevice(e);
    gReportVulkan10 = false;
    checkRefusal(old.status(), Error::ExternalApiVersion,
                 "ExternalVulkan.physicalDevice supports Vulkan 1.0; allowed 1.1 or later (1.3, or 1.1 with VK_KHR_dynamic_rendering)");

    // synchronization2 claimed on a device that has no vkCmdPipelineBarrier2; without the claim
    // the same device wraps (the SDK records per-stage-pair vkCmdPipelineBarrier then).
    gHideBarrier2 = true;
    vulkan::ExternalVulkan sync2 = e;
    sync2.synchronization2Enabled = true;
    Result<std::unique_ptr<Device>> noBarrier2 = vulkan::wrapDevice(sync2);
    Result<std::unique_ptr<Device>> unclaimed = vulkan::wrapDevice(e);
    gHideBarrier2 = false;
    checkRefusal(noBarrier2.status(), Error::ExternalSynchronization2,
                 "ExternalVulkan.synchronization2Enabled is set, but ExternalVulkan.device has no vkCmdPipelineBarrier2; allowed when "
                 "the device was created with the synchronization2 feature (Vulkan 1.3 or VK_KHR_synchronization2)");
    INFO(unclaimed.status().toString());
    CHECK(unclaimed.isOk());

    // The same loader reporting the truth wraps fine: the refusals came from the reports.
    Result<std::unique_ptr<Device>> wrapped = vulkan::wrapDevice(e);
    INFO(wrapped.status().toString());
    CHECK(wrapped.isOk());
}

TEST_CASE("vulkan entry points: a host command buffer only on a wrapped device, Vulkan calls only on Vulkan devices", "[vulkan][validation]") {
    Host host;
    if (!host.create(false)) SFX_SKIP(host.skipReason);
    DeviceOptions options;
    options.validation = host.validation;
    Result<std::unique_ptr<Device>> own = vulkan::createDevice(options);
    if (!own) SFX_SKIP(own.status().toString());
    // The host's command buffer belongs to another VkDevice than the SDK's own device.
    checkRefusal(vulkan::setCommandBuffer(*own.value(), host.cb), Error::HostCommandBufferOwnDevice,
                 "setCommandBuffer: device is the SDK's own Vulkan device (vulkan::createDevice), whose VkDevice no host "
                 "command buffer belongs to; allowed a device from vulkan::wrapDevice");
    CHECK(vulkan::setCommandBuffer(*own.value(), VK_NULL_HANDLE).isOk());  // stopping is always fine
    CHECK(own.value()->takeValidationMessages().empty());

    std::unique_ptr<Device> nullDevice = null::createDevice();
    checkRefusal(vulkan::setCommandBuffer(*nullDevice, host.cb), Error::DeviceWrongApi,
                 "setCommandBuffer: device is a null device; allowed a Vulkan device");
    vulkan::ExternalImage image;
    checkRefusal(vulkan::importImage(*nullDevice, image).status(), Error::DeviceWrongApi,
                 "importImage: device is a null device; allowed a Vulkan device");
    checkRefusal(vulkan::nativeImage(*nullDevice, TextureHandle{}).status(), Error::DeviceWrongApi,
                 "nativeImage: device is a null device; allowed a Vulkan device");
}
