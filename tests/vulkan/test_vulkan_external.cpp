// The Vulkan backend on a host engine's objects: wrapping a host-made VkInstance/VkDevice,
// recording into a host command buffer (steady frames of the effects included), and leaving
// every host object alive and leak-free.
#include <catch2/catch.hpp>

#include <vulkan/vulkan.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analytic_scenes.hpp"
#include "sfx/ao.hpp"
#include "sfx/half.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/tiers.hpp"
#include "sfx/vulkan_device.hpp"
#include "skips.hpp"
#include "steady_frames.hpp"

using namespace sfx;

namespace {

// Errors the host's own messenger sees: at the end, leaks of SDK objects would show here.
struct HostMessages {
    std::vector<std::string> errors;
};

VKAPI_ATTR VkBool32 VKAPI_CALL hostCallback(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    static_cast<HostMessages*>(user)->errors.push_back(data->pMessage ? data->pMessage : "");
    return VK_FALSE;
}

// What a host engine would have made before handing it to the SDK.
struct Host {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t family = 0;
    HostMessages messages;
    bool validation = false;
    std::string skipReason;

    bool create() {
        uint32_t count = 0;
        vkEnumerateInstanceLayerProperties(&count, nullptr);
        std::vector<VkLayerProperties> layers(count);
        vkEnumerateInstanceLayerProperties(&count, layers.data());
        for (const auto& l : layers) validation |= std::strcmp(l.layerName, "VK_LAYER_KHRONOS_validation") == 0;
        const char* layer = "VK_LAYER_KHRONOS_validation";
        const char* exts[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
        // Synchronization validation as well as the core checks, as on the SDK's own devices.
        const VkValidationFeatureEnableEXT syncValidation = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
        VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
        features.enabledValidationFeatureCount = 1;
        features.pEnabledValidationFeatures = &syncValidation;
        VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
        app.apiVersion = VK_API_VERSION_1_3;
        VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
        ci.pApplicationInfo = &app;
        ci.enabledLayerCount = validation ? 1 : 0;
        ci.ppEnabledLayerNames = &layer;
        ci.enabledExtensionCount = validation ? 2 : 0;
        ci.ppEnabledExtensionNames = exts;
        if (validation) ci.pNext = &features;
        if (vkCreateInstance(&ci, nullptr, &instance) != VK_SUCCESS) {
            skipReason = "no Vulkan instance";
            return false;
        }
        if (validation) {
            auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
            VkDebugUtilsMessengerCreateInfoEXT mi{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
            mi.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
            mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
            mi.pfnUserCallback = hostCallback;
            mi.pUserData = &messages;
            create(instance, &mi, nullptr, &messenger);
        }
        count = 0;
        vkEnumeratePhysicalDevices(instance, &count, nullptr);
        std::vector<VkPhysicalDevice> gpus(count);
        vkEnumeratePhysicalDevices(instance, &count, gpus.data());
        for (VkPhysicalDevice gpu : gpus) {
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(gpu, &p);
            if (p.apiVersion >= VK_API_VERSION_1_3) {
                physical = gpu;
                break;
            }
        }
        if (!physical) {
            skipReason = "no Vulkan 1.3 device";
            return false;
        }
        uint32_t qCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(physical, &qCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(qCount);
        vkGetPhysicalDeviceQueueFamilyProperties(physical, &qCount, families.data());
        for (uint32_t i = 0; i < qCount; ++i)
            if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) {
                family = i;
                break;
            }
        VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        v13.dynamicRendering = VK_TRUE;
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        qci.queueFamilyIndex = family;
        qci.queueCount = 1;
        qci.pQueuePriorities = &priority;
        VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        dci.pNext = &v13;
        dci.queueCreateInfoCount = 1;
        dci.pQueueCreateInfos = &qci;
        if (vkCreateDevice(physical, &dci, nullptr, &device) != VK_SUCCESS) {
            skipReason = "vkCreateDevice failed";
            return false;
        }
        vkGetDeviceQueue(device, family, 0, &queue);
        return true;
    }

    ~Host() {
        if (device) vkDestroyDevice(device, nullptr);
        if (messenger) {
            auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
            destroy(instance, messenger, nullptr);
        }
        if (instance) vkDestroyInstance(instance, nullptr);
    }
};

// A host command pool (its buffers resettable by begin) with one primary command buffer.
void makeCommandBuffer(const Host& host, VkCommandPool& pool, VkCommandBuffer& cb) {
    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pci.queueFamilyIndex = host.family;
    REQUIRE(vkCreateCommandPool(host.device, &pci, nullptr, &pool) == VK_SUCCESS);
    VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cai.commandPool = pool;
    cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cai.commandBufferCount = 1;
    REQUIRE(vkAllocateCommandBuffers(host.device, &cai, &cb) == VK_SUCCESS);
}

void clearTo(Device& d, TextureHandle t, float value) {
    RenderPassDesc pass;
    pass.colors = {{t, 0, LoadOp::Clear, {value, value, value, value}}};
    REQUIRE(d.renderPass(pass, {}).isOk());
}

}  // namespace

TEST_CASE("vulkan: wrapped host device, host command buffer, host objects survive the SDK", "[vulkan]") {
    Host host;
    if (!host.create()) SFX_SKIP(host.skipReason);
    vulkan::ExternalVulkan ext;
    ext.instance = host.instance;
    ext.physicalDevice = host.physical;
    ext.device = host.device;
    ext.queue = host.queue;
    ext.queueFamily = host.family;
    ext.getInstanceProcAddr = vkGetInstanceProcAddr;
    ext.debugUtilsEnabled = host.validation;

    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cb = VK_NULL_HANDLE;
    makeCommandBuffer(host, pool, cb);

    std::vector<std::pair<LogSeverity, std::string>> logged;  // DeviceOptions::log
    {
        DeviceOptions options;
        options.validation = true;
        options.log = [&](LogSeverity severity, std::string_view message) { logged.emplace_back(severity, message); };
        Result<std::unique_ptr<Device>> wrapped = vulkan::wrapDevice(ext, options);
        INFO(wrapped.status().toString());
        REQUIRE(wrapped.isOk());
        Device& d = *wrapped.value();
        CHECK(d.caps().backend == BackendKind::Vulkan);
        CHECK(d.caps().dialect == ShaderDialect::Spirv);

        Result<TextureHandle> tex = d.createTexture({4, 4, 1, Format::R32F, kTextureSampled | kTextureRenderTarget});
        REQUIRE(tex.isOk());
        std::vector<float> texels(16);

        // The SDK's own command buffers, submitted to the host's queue.
        clearTo(d, tex.value(), 2.0f);
        REQUIRE(d.readTexture(tex.value(), 0, texels.data(), 64).isOk());
        for (float v : texels) REQUIRE(v == 2.0f);

        // Recording into the host's command buffer: reads refuse until the host has submitted.
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        REQUIRE(vkBeginCommandBuffer(cb, &bi) == VK_SUCCESS);
        REQUIRE(vulkan::setCommandBuffer(d, cb).isOk());
        clearTo(d, tex.value(), 5.0f);
        const float one = 1.0f;
        Result<BufferHandle> buf = d.createBuffer({16, kBufferUniform});
        REQUIRE(buf.isOk());
        REQUIRE(d.writeBuffer(buf.value(), 4, &one, 4).isOk());
        Status refused = d.readTexture(tex.value(), 0, texels.data(), 64);
        CHECK(refused.code() == StatusCode::UnsupportedFeature);
        CHECK(refused.message().find("host command buffer") != std::string::npos);
        REQUIRE(d.flush().isOk());  // stops recording into the host's buffer
        REQUIRE(vkEndCommandBuffer(cb) == VK_SUCCESS);
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cb;
        REQUIRE(vkQueueSubmit(host.queue, 1, &si, VK_NULL_HANDLE) == VK_SUCCESS);
        REQUIRE(vkQueueWaitIdle(host.queue) == VK_SUCCESS);
        REQUIRE(d.readTexture(tex.value(), 0, texels.data(), 64).isOk());
        for (float v : texels) REQUIRE(v == 5.0f);
        float words[4] = {};
        REQUIRE(d.readBuffer(buf.value(), 0, words, 16).isOk());
        CHECK(words[1] == 1.0f);

        // The SDK's messenger on the host's instance reports validation errors.
        if (host.validation) {
            CHECK(d.takeValidationMessages().empty());
            VkSamplerCreateInfo bad{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
            bad.anisotropyEnable = VK_TRUE;  // the host did not enable samplerAnisotropy
            bad.maxAnisotropy = 4.0f;
            auto createBadSampler = [&] {
                VkSampler sampler = VK_NULL_HANDLE;
                vkCreateSampler(host.device, &bad, nullptr, &sampler);
                if (sampler) vkDestroySampler(host.device, sampler, nullptr);
            };
            createBadSampler();
            CHECK_FALSE(d.takeValidationMessages().empty());
            // Left untaken, the next one reaches the log callback when the device goes, not stderr.
            createBadSampler();
            host.messages.errors.clear();
        }
        REQUIRE(d.destroyTexture(tex.value()).isOk());
        CHECK(logged.empty());
    }
    if (host.validation) {
        REQUIRE_FALSE(logged.empty());
        CHECK(logged.front().first == LogSeverity::Error);
        CHECK(logged.front().second.find("untaken validation message at teardown") != std::string::npos);
    }

    // The SDK is gone; every host object still works and nothing of the SDK's leaked.
    REQUIRE(vkDeviceWaitIdle(host.device) == VK_SUCCESS);
    REQUIRE(vkResetCommandPool(host.device, pool, 0) == VK_SUCCESS);
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = 64;
    bci.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    REQUIRE(vkCreateBuffer(host.device, &bci, nullptr, &buffer) == VK_SUCCESS);
    vkDestroyBuffer(host.device, buffer, nullptr);
    vkDestroyCommandPool(host.device, pool, nullptr);
    vkDestroyDevice(host.device, nullptr);  // the layer reports any SDK object still alive
    host.device = VK_NULL_HANDLE;
    for (const auto& m : host.messages.errors) UNSCOPED_INFO("host validation: " << m);
    CHECK(host.messages.errors.empty());
}

TEST_CASE("vulkan: own device opens, and wrapDevice rejects missing host objects", "[vulkan]") {
    DeviceOptions options;
    options.validation = true;  // the tests ask for validation; the default is off
    Result<std::unique_ptr<Device>> own = vulkan::createDevice(options);
    if (!own) {
        CHECK(own.status().code() == StatusCode::BackendUnavailable);
        SFX_SKIP(own.status().toString());
    }
    CHECK(own.value()->caps().platform == "vulkan-loader");
    CHECK(own.value()->caps().apiName.rfind("Vulkan 1.", 0) == 0);
    CHECK(own.value()->takeValidationMessages().empty());

    vulkan::ExternalVulkan empty;
    Result<std::unique_ptr<Device>> bad = vulkan::wrapDevice(empty);
    CHECK(bad.status().code() == StatusCode::InvalidArgument);
}

// Steady frames recorded into the host's command buffer: after warm-up, AO of each technique and
// motion blur make no object and keep resident memory flat, as with the SDK's own command buffers
// (tests/conformance/test_steady_frames.cpp), with synchronization validation watching.
TEST_CASE("vulkan: steady frames in a host command buffer make nothing", "[vulkan][steady]") {
    Host host;
    if (!host.create()) SFX_SKIP(host.skipReason);
    vulkan::ExternalVulkan ext{host.instance, host.physical, host.device, host.queue, host.family,
                               vkGetInstanceProcAddr, host.validation};
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cb = VK_NULL_HANDLE;
    makeCommandBuffer(host, pool, cb);
    VkFence fence = VK_NULL_HANDLE;
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    REQUIRE(vkCreateFence(host.device, &fci, nullptr, &fence) == VK_SUCCESS);
    {
        DeviceOptions options;
        options.validation = true;
        Result<std::unique_ptr<Device>> wrapped = vulkan::wrapDevice(ext, options);
        INFO(wrapped.status().toString());
        REQUIRE(wrapped.isOk());
        Device& d = *wrapped.value();
        const TierProfile& profile = tiers::profile(Tier::High);
        constexpr uint32_t w = 160, h = 90;
        const samples::AnalyticScene scene = samples::cornerScene(w, h);
        const std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
        TextureHandle depthTex = d.createTexture({w, h, 1, Format::R32F, kTextureSampled, "host-depth"}).value();
        REQUIRE(d.writeTexture(depthTex, 0, depth.data(), depth.size() * sizeof(float)).isOk());
        TextureHandle outTex = d.createTexture({w, h, 1, Format::R16F, kTextureSampled | kTextureRenderTarget, "host-ao"}).value();
        std::vector<uint16_t> color(size_t(w) * h * 4, floatToHalf(0.5f));
        TextureHandle colorTex = d.createTexture({w, h, 1, Format::RGBA16F, kTextureSampled, "host-colour"}).value();
        REQUIRE(d.writeTexture(colorTex, 0, color.data(), color.size() * sizeof(uint16_t)).isOk());
        REQUIRE(d.flush().isOk());

        // One host frame: begin, let the SDK record, end, submit, wait (so the next
        // setCommandBuffer may reuse what this one used).
        auto hostFrame = [&](auto record) -> Status {
            VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
            if (vkBeginCommandBuffer(cb, &bi) != VK_SUCCESS) return {StatusCode::DeviceError, "vkBeginCommandBuffer"};
            SFX_TRY(vulkan::setCommandBuffer(d, cb));
            SFX_TRY(record());
            SFX_TRY(d.flush());
            if (vkEndCommandBuffer(cb) != VK_SUCCESS) return {StatusCode::DeviceError, "vkEndCommandBuffer"};
            VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
            si.commandBufferCount = 1;
            si.pCommandBuffers = &cb;
            if (vkQueueSubmit(host.queue, 1, &si, fence) != VK_SUCCESS) return {StatusCode::DeviceError, "vkQueueSubmit"};
            if (vkWaitForFences(host.device, 1, &fence, VK_TRUE, UINT64_MAX) != VK_SUCCESS || vkResetFences(host.device, 1, &fence) != VK_SUCCESS)
                return {StatusCode::DeviceError, "vkWaitForFences"};
            return Status::ok();
        };
        auto steady = [&](const std::string& what, auto record) {
            INFO(what);
            for (int i = 0; i < 5; ++i) REQUIRE(hostFrame(record).isOk());
            const DeviceStats before = d.stats();
            const double rssBefore = test::residentMiB();
            for (int i = 0; i < 300; ++i) {
                Status s = hostFrame(record);
                if (!s) FAIL(what << " frame " << i << ": " << s.toString());
            }
            const double growth = test::residentMiB() - rssBefore;
            std::printf("steady frames vulkan host command buffer %s: resident %+.2f MiB over 300 frames\n", what.c_str(), growth);
            test::checkNothingMade(before, d.stats());
            test::checkResidentFlat(d.caps().backend, growth);
            const std::vector<std::string> messages = d.takeValidationMessages();
            for (const std::string& m : messages) UNSCOPED_INFO("validation: " << m);
            for (const std::string& m : host.messages.errors) UNSCOPED_INFO("host validation: " << m);
            CHECK(messages.empty());
            CHECK(host.messages.errors.empty());
        };
        for (AoTechnique technique : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease}) {
            AoSettings settings;
            settings.technique = technique;
            Result<std::unique_ptr<AmbientObscurance>> ao =
                AmbientObscurance::create(d, {w, h, profile, settings, DepthKind::Hardware});
            REQUIRE(ao.isOk());
            AoInputs in;
            in.depth = DepthSource{depthTex, DepthKind::Linear, scene.camera};
            in.output = outTex;
            steady(std::string("ao ") + toString(technique), [&] { return ao.value()->dispatch(in); });
        }
        Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(d, {w, h, profile, Format::RGBA16F, DepthKind::Hardware});
        REQUIRE(mb.isOk());
        MotionBlurInputs in;
        in.color = colorTex;
        in.depth = DepthSource{depthTex, DepthKind::Linear, scene.camera};
        in.camera.previousViewProjection[3][0] = 0.02;
        steady("motion blur", [&] { return mb.value()->dispatch(in); });
        for (TextureHandle t : {depthTex, outTex, colorTex}) REQUIRE(d.destroyTexture(t).isOk());
    }
    vkDestroyFence(host.device, fence, nullptr);
    vkDestroyCommandPool(host.device, pool, nullptr);
}
