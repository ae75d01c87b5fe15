// Caps: what the physical device offers (limits, format features, timestamps) as DeviceCaps,
// cut down to the requested capability ceiling.
#include <algorithm>

#include "vulkan_device_impl.hpp"
#include "vulkan_formats.hpp"

namespace sfx::vulkan {

void VulkanDevice::fillCaps(const DeviceOptions& options) {
    DeviceCaps& c = caps_;
    c.backend = BackendKind::Vulkan;
    c.platform = "vulkan-loader";
    c.apiMajor = VK_API_VERSION_MAJOR(props_.apiVersion);
    c.apiMinor = VK_API_VERSION_MINOR(props_.apiVersion);
    c.apiName = "Vulkan " + vkVersionString(props_.apiVersion);
    c.deviceName = props_.deviceName;
    c.deviceChoice = ownsDevice_ ? deviceChoice_ : "the host's VkPhysicalDevice (wrapDevice)";
    c.dialect = ShaderDialect::Spirv;
    c.ceiling = options.ceiling;
    c.computeShaders = fullFeatures_;
    c.storageBuffers = fullFeatures_;
    c.atomics = fullFeatures_;
    c.storageImages = fullFeatures_;
    c.fragmentStoresAndAtomics = fullFeatures_ && fragmentStoresAndAtomics_;
    c.timing = timestampValidBits_ > 0 ? TimingSource::GpuTimestamps : TimingSource::WallClockAfterFinish;
    c.reusableRecordings = options.reuseRecordings;
    c.clipDepth = ClipDepthRange::ZeroToOne;
    c.origin = FramebufferOrigin::UpperLeft;

    const VkPhysicalDeviceLimits& l = props_.limits;
    c.limits.maxTextureSize = l.maxImageDimension2D;
    c.limits.maxRenderTargetWidth = std::min({l.maxFramebufferWidth, l.maxViewportDimensions[0], l.maxImageDimension2D});
    c.limits.maxRenderTargetHeight = std::min({l.maxFramebufferHeight, l.maxViewportDimensions[1], l.maxImageDimension2D});
    c.limits.maxColorAttachments = std::min<uint32_t>(l.maxColorAttachments, 8);
    c.limits.subPixelPrecisionBits = l.subPixelPrecisionBits;
    c.limits.maxUniformBlockSize = l.maxUniformBufferRange;
    c.limits.maxStorageBufferSize = fullFeatures_ ? l.maxStorageBufferRange : 0;
    // Buffers are one allocation each; keep them well inside what any heap offers.
    uint64_t largestHeap = 0;
    for (uint32_t i = 0; i < memProps_.memoryHeapCount; ++i) largestHeap = std::max(largestHeap, memProps_.memoryHeaps[i].size);
    c.limits.maxBufferSize = std::min<uint64_t>(uint64_t(1) << 30, largestHeap / 4);
    c.limits.maxComputeWorkGroupInvocations = fullFeatures_ ? l.maxComputeWorkGroupInvocations : 0;
    for (int axis = 0; axis < 3; ++axis) c.limits.maxComputeWorkGroupCount[axis] = fullFeatures_ ? l.maxComputeWorkGroupCount[axis] : 0;
    c.limits.maxTextureBindings = std::min<uint32_t>(l.maxPerStageDescriptorSampledImages, 64);
    c.limits.minUniformBufferOffsetAlignment = std::max<uint64_t>(1, l.minUniformBufferOffsetAlignment);
    c.limits.minStorageBufferOffsetAlignment = std::max<uint64_t>(1, l.minStorageBufferOffsetAlignment);
    // VkSampleCountFlags has bit k for 2^k samples, the encoding DeviceLimits records.
    c.limits.framebufferColorSampleCounts = l.framebufferColorSampleCounts;
    c.limits.framebufferDepthSampleCounts = l.framebufferDepthSampleCounts;
    c.limits.sampledImageColorSampleCounts = fullFeatures_ ? l.sampledImageColorSampleCounts : uint32_t(VK_SAMPLE_COUNT_1_BIT);
    c.limits.sampledImageDepthSampleCounts = fullFeatures_ ? l.sampledImageDepthSampleCounts : uint32_t(VK_SAMPLE_COUNT_1_BIT);
    c.limits.maxTexelBufferElements = fullFeatures_ ? l.maxTexelBufferElements : 0;

    for (size_t i = 1; i < size_t(Format::Count); ++i) {
        const Format f = Format(i);
        VkFormatProperties fp{};
        vk_.vkGetPhysicalDeviceFormatProperties(physical_, toVkFormat(f), &fp);
        const VkFormatFeatureFlags feats = fp.optimalTilingFeatures;
        const bool transfers = (feats & VK_FORMAT_FEATURE_TRANSFER_SRC_BIT) && (feats & VK_FORMAT_FEATURE_TRANSFER_DST_BIT);
        c.sampledFormat[i] = transfers && (feats & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT);
        c.renderableFormat[i] = transfers &&
            (feats & (isDepthFormat(f) ? VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT));
        c.filterableFormat[i] = c.sampledFormat[i] && (feats & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT);
        c.blendableFormat[i] = c.renderableFormat[i] && !isDepthFormat(f) && (feats & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT);
        c.storageFormat[i] = transfers && fullFeatures_ && (feats & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT);
    }
    c.floatRenderTargets = c.renderableFormat[size_t(Format::R32F)] && c.renderableFormat[size_t(Format::RG16F)] &&
        c.renderableFormat[size_t(Format::RGBA16F)];
}

}  // namespace sfx::vulkan
