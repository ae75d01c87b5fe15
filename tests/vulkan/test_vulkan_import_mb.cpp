// Motion blur into a host image (MotionBlurInputs::output) on a wrapped host device with
// synchronization validation: the SDK records into the host's command buffer, reads the host's
// colour, depth and velocity and writes the host's own image, which the host copies right after
// with no barrier of its own (the state contract of docs/integration.md); the host image holds
// exactly the bits the SDK's own output() gets from the same inputs.
#include <catch2/catch.hpp>

#include <vulkan/vulkan.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "analytic_scenes.hpp"
#include "host_vulkan.hpp"
#include "sfx/half.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/tiers.hpp"
#include "sfx/vulkan_device.hpp"
#include "skips.hpp"

using namespace sfx;
using namespace sfx::hostvk;

TEST_CASE("vulkan import: motion blur writes a host image in the host's command buffer, bit for bit as output()", "[vulkan][import][motion_blur]") {
    Host host;
    if (!host.create()) SFX_SKIP(host.skipReason);
    const std::unique_ptr<Device> wrapped = wrapValidated(host);
    Device& d = *wrapped;
    constexpr uint32_t w = 96, h = 54;
    const CameraProjection camera = tools::AnalyticCamera{}.projection(w, h);

    // Noise colour; a near box moving 12 px a shutter interval to the right over a still far wall.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<uint16_t> color(size_t(w) * h * 4), velocity(size_t(w) * h * 2);
    std::vector<float> depth(size_t(w) * h, 20.0f);
    for (size_t i = 0; i < color.size(); ++i) color[i] = floatToHalf(i % 4 == 3 ? 1.0f : u(rng));
    for (uint32_t y = 16; y < 38; ++y)
        for (uint32_t x = 30; x < 52; ++x) {
            depth[size_t(y) * w + x] = 5.0f;
            velocity[2 * (size_t(y) * w + x)] = floatToHalf(12.0f);
        }

    const VkImageUsageFlags inUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    const VkImageUsageFlags outUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
        VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    HostImage colorImg(host, VK_FORMAT_R16G16B16A16_SFLOAT, inUsage, w, h);
    HostImage depthImg(host, VK_FORMAT_R32_SFLOAT, inUsage, w, h);
    HostImage velocityImg(host, VK_FORMAT_R16G16_SFLOAT, inUsage, w, h);
    HostImage outImg(host, VK_FORMAT_R16G16B16A16_SFLOAT, outUsage, w, h);
    hostUpload(host, colorImg, 0, color.data(), color.size() * 2, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    hostUpload(host, depthImg, 0, depth.data(), depth.size() * 4, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    hostUpload(host, velocityImg, 0, velocity.data(), velocity.size() * 2, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    const std::vector<uint16_t> marker(color.size(), floatToHalf(-3.0f));
    // TRANSFER_SRC_OPTIMAL: the host copies the image out right after the SDK, in the layout its
    // contract names, without a layout change of its own (GENERAL would work too, but the layers
    // rightly warn that a copy from GENERAL is slower).
    hostUpload(host, outImg, 0, marker.data(), marker.size() * 2, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);

    Result<TextureHandle> colorTex = vulkan::importImage(d,
                                                         externalImage(colorImg, inUsage, kTextureSampled, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
    Result<TextureHandle> depthTex = vulkan::importImage(d,
                                                         externalImage(depthImg, inUsage, kTextureSampled, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
    Result<TextureHandle> velocityTex = vulkan::importImage(
        d, externalImage(velocityImg, inUsage, kTextureSampled, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
    Result<TextureHandle> outTex = vulkan::importImage(
        d, externalImage(outImg, outUsage, kTextureSampled | kTextureRenderTarget, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL));
    INFO(colorTex.status().toString() << " / " << depthTex.status().toString() << " / " << velocityTex.status().toString() << " / "
                                      << outTex.status().toString());
    REQUIRE((colorTex.isOk() && depthTex.isOk() && velocityTex.isOk() && outTex.isOk()));

    MotionBlurDesc desc;
    desc.width = w;
    desc.height = h;
    desc.profile = tiers::profile(Tier::High);
    desc.colorFormat = Format::RGBA16F;
    desc.depthInput = DepthKind::Linear;
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(d, desc);
    REQUIRE(mb.isOk());
    MotionBlurSettings settings;
    settings.maxRadiusPx = 8;
    settings.referenceRows = 0;
    MotionBlurInputs in;
    in.color = colorTex.value();
    in.depth = DepthSource{depthTex.value(), DepthKind::Linear, camera};
    in.velocity = velocityTex.value();
    in.output = outTex.value();

    // One host command buffer: the SDK's passes, then the host's copy of the output with no
    // barrier of the host's in between (flush() left the image in the contract's layout, visible to all).
    const size_t bytes = color.size() * 2;
    HostBuffer readback(host, bytes);
    host.begin();
    REQUIRE(vulkan::setCommandBuffer(d, host.cb).isOk());
    REQUIRE(mb.value()->dispatch(in, settings).isOk());
    REQUIRE(d.flush().isOk());
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {w, h, 1};
    vkCmdCopyImageToBuffer(host.cb, outImg.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(host.cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
    host.submitAndWait();
    std::vector<uint16_t> imported(color.size());
    std::memcpy(imported.data(), readback.mapped, bytes);
    checkNoMessages(d, host);

    Result<vulkan::NativeImage> native = vulkan::nativeImage(d, outTex.value());
    REQUIRE(native.isOk());
    CHECK(native->image == outImg.image);
    CHECK(native->layout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);

    // The SDK's own output from the same host inputs, on the SDK's own command buffers.
    in.output = {};
    REQUIRE(mb.value()->dispatch(in, settings).isOk());
    std::vector<uint16_t> own(color.size());
    REQUIRE(d.readTexture(mb.value()->output(), 0, own.data(), bytes).isOk());
    CHECK(imported == own);
    CHECK(imported != color);  // the box blurs: not a copy of the input
    // That dispatch left the host's image alone.
    std::vector<uint8_t> after = hostDownload(host, outImg, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, bytes);
    CHECK(std::memcmp(after.data(), imported.data(), bytes) == 0);
    checkNoMessages(d, host);

    mb.value().reset();
    for (TextureHandle t : {colorTex.value(), depthTex.value(), velocityTex.value(), outTex.value()}) REQUIRE(d.destroyTexture(t).isOk());
    REQUIRE(d.flush().isOk());
    checkNoMessages(d, host);
}
