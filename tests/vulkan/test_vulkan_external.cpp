// The Vulkan backend on a host engine's objects: wrapping a host-made VkInstance/VkDevice,
// recording into a host command buffer (steady frames of the effects included), and leaving
// every host object alive and leak-free.
#include <catch2/catch.hpp>

#include <vulkan/vulkan.h>

#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analytic_scenes.hpp"
#include "host_vulkan.hpp"
#include "sfx/ao.hpp"
#include "sfx/half.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/tiers.hpp"
#include "sfx/vulkan_device.hpp"
#include "skips.hpp"
#include "steady_frames.hpp"

using namespace sfx;
using hostvk::Host;

namespace {

void clearTo(Device& d, TextureHandle t, float value) {
    RenderPassDesc pass;
    pass.colors = {{t, 0, LoadOp::Clear, {value, value, value, value}}};
    REQUIRE(d.renderPass(pass, {}).isOk());
}

}  // namespace

TEST_CASE("vulkan: wrapped host device, host command buffer, host objects survive the SDK", "[vulkan]") {
    Host host;
    if (!host.create(false)) SFX_SKIP(host.skipReason);  // runs without the layer too
    vulkan::ExternalVulkan ext;
    ext.instance = host.instance;
    ext.physicalDevice = host.physical;
    ext.device = host.device;
    ext.queue = host.queue;
    ext.queueFamily = host.family;
    ext.getInstanceProcAddr = vkGetInstanceProcAddr;
    ext.debugUtilsEnabled = host.validation;

    const VkCommandPool pool = host.pool;
    const VkCommandBuffer cb = host.cb;

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
            (void)host.takeMessages();
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
    host.pool = VK_NULL_HANDLE;
    vkDestroyDevice(host.device, nullptr);  // the layer reports any SDK object still alive
    host.device = VK_NULL_HANDLE;
    const std::vector<std::string> hostErrors = host.takeMessages();
    for (const auto& m : hostErrors) UNSCOPED_INFO("host validation: " << m);
    CHECK(hostErrors.empty());
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

TEST_CASE("vulkan: an own device with DeviceOptions::reuseRecordings off keeps no recordings", "[vulkan]") {
    DeviceOptions options;
    options.validation = true;
    options.reuseRecordings = false;
    Result<std::unique_ptr<Device>> own = vulkan::createDevice(options);
    if (!own) {
        CHECK(own.status().code() == StatusCode::BackendUnavailable);
        SFX_SKIP(own.status().toString());
    }
    Device& d = *own.value();
    CHECK_FALSE(d.caps().reusableRecordings);
    for (const Status& s : {d.beginRecording(), d.endRecording().status(), d.beginReplay({}), d.endReplay(), d.destroyRecording({})}) {
        INFO(s.toString());
        CHECK(s.code() == StatusCode::UnsupportedFeature);
        CHECK(s.message().find("caps().reusableRecordings is false") != std::string::npos);
    }
    CHECK(d.takeValidationMessages().empty());
}

// Steady frames recorded into the host's command buffer: after warm-up, AO of each technique and
// motion blur make no object and keep resident memory flat, as with the SDK's own command buffers
// (tests/conformance/test_steady_frames.cpp), with synchronization validation watching.
TEST_CASE("vulkan: steady frames in a host command buffer make nothing", "[vulkan][steady]") {
    Host host;
    if (!host.create(false)) SFX_SKIP(host.skipReason);  // runs without the layer too
    vulkan::ExternalVulkan ext{host.instance, host.physical, host.device, host.queue, host.family, vkGetInstanceProcAddr, host.validation};
    const VkCommandBuffer cb = host.cb;
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
        const tools::AnalyticScene scene = tools::cornerScene(w, h);
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
            hostvk::checkNoMessages(d, host);
        };
        for (AoTechnique technique : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon}) {
            AoSettings settings;
            settings.technique = technique;
            Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(d, {w, h, profile, settings, DepthKind::Hardware});
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
}
