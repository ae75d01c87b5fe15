// Textures: images and their memory, sampled and attachment views, texture uploads and
// readbacks through the staging ring, and samplers.
#include <cstring>

#include "vulkan_device_impl.hpp"
#include "vulkan_formats.hpp"

namespace sfx::vulkan {

Result<TextureHandle> VulkanDevice::makeTexture(const TextureDesc& desc) {
    VulkanTexture t;
    t.desc = desc;
    t.format = toVkFormat(desc.format);
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = t.format;
    ici.extent = {desc.width, desc.height, 1};
    ici.mipLevels = desc.mipLevels;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (desc.usage & kTextureSampled) ici.usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (desc.usage & kTextureStorage) ici.usage |= VK_IMAGE_USAGE_STORAGE_BIT;
    if (desc.usage & kTextureRenderTarget)
        ici.usage |= isDepthFormat(desc.format) ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    SFX_VK(vk_.vkCreateImage(device_, &ici, nullptr, &t.image));
    VkMemoryRequirements req;
    vk_.vkGetImageMemoryRequirements(device_, t.image, &req);
    Result<Allocation> a = allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, false);
    if (!a) a = allocate(req, 0, false);
    if (!a) {
        vk_.vkDestroyImage(device_, t.image, nullptr);
        return a.status();
    }
    t.memory = a->memory;
    t.memoryBytes = a->size;
    VkResult r = vk_.vkBindImageMemory(device_, t.image, t.memory, 0);
    if (r != VK_SUCCESS) {
        vk_.vkDestroyImage(device_, t.image, nullptr);
        freeMemory(t.memory, t.memoryBytes);
        return vkError("vkBindImageMemory", r);
    }
    setName(VK_OBJECT_TYPE_IMAGE, uint64_t(t.image), desc.debugName);
    t.mips.assign(desc.mipLevels, AccessState{});
    t.attachmentViews.assign(desc.mipLevels, VK_NULL_HANDLE);
    return textures_.insert(std::move(t));
}

Result<VkImageView> VulkanDevice::sampledView(VulkanTexture& t, uint32_t baseMip, uint32_t mipCount) {
    if (t.hostView && baseMip == 0 && mipCount == t.desc.mipLevels) return t.hostView;
    auto key = std::make_pair(baseMip, mipCount);
    auto it = t.views.find(key);
    if (it != t.views.end()) return it->second;
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = t.image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = t.format;
    vci.subresourceRange = t.range(dataAspect(t.desc.format), baseMip, mipCount);
    VkImageView view;
    SFX_VK(vk_.vkCreateImageView(device_, &vci, nullptr, &view));
    imageViewCount_.add();
    t.views[key] = view;
    return view;
}

Result<VkImageView> VulkanDevice::attachmentView(VulkanTexture& t, uint32_t mip) {
    if (t.attachmentViews[mip]) return t.attachmentViews[mip];
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = t.image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = t.format;
    vci.subresourceRange = t.range(fullAspect(t.desc.format), mip, 1);
    SFX_VK(vk_.vkCreateImageView(device_, &vci, nullptr, &t.attachmentViews[mip]));
    imageViewCount_.add();
    return t.attachmentViews[mip];
}

Status VulkanDevice::uploadTexture(VulkanTexture& t, uint32_t mip, const void* data, size_t bytes) {
    if (t.external && !(t.vkUsage & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        return {StatusCode::UnsupportedFeature, "writeTexture: texture is an imported image without VK_IMAGE_USAGE_TRANSFER_DST_BIT"};
    Result<VkCommandBuffer> cb = writeRecording(t.mips[mip]);
    if (!cb) return cb.status();
    Result<StagingSlice> staging = stage(bytes);
    if (!staging) return staging.status();
    // The HAL's D24S8 bytes put depth high; Vulkan's depth-aspect copy wants it low.
    if (t.desc.format == Format::D24S8)
        d24s8ToVulkan(data, staging->mapped, bytes);
    else
        std::memcpy(staging->mapped, data, bytes);
    const ImageUse copyWrite{&t, mip, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, true};
    barriers(cb.value(), std::span(&copyWrite, 1), {});
    VkBufferImageCopy region{};
    region.bufferOffset = staging->offset;
    region.imageSubresource = {dataAspect(t.desc.format), t.baseMip + mip, t.layer, 1};
    region.imageExtent = {mipExtent(t.desc.width, mip), mipExtent(t.desc.height, mip), 1};
    vk_.vkCmdCopyBufferToImage(cb.value(), staging->buffer, t.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    return Status::ok();
}

Status VulkanDevice::downloadTexture(VulkanTexture& t, uint32_t mip, void* out, size_t bytes) {
    if (t.external && !(t.vkUsage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT))
        return {StatusCode::UnsupportedFeature, "readTexture: texture is an imported image without VK_IMAGE_USAGE_TRANSFER_SRC_BIT"};
    Result<VkCommandBuffer> cb = recording();
    if (!cb) return cb.status();
    Result<StagingSlice> staging = stage(bytes);
    if (!staging) return staging.status();
    const StagingSlice readback = staging.value();
    const ImageUse copyRead{&t, mip, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, false};
    barriers(cb.value(), std::span(&copyRead, 1), {});
    VkBufferImageCopy region{};
    region.bufferOffset = readback.offset;
    region.imageSubresource = {dataAspect(t.desc.format), t.baseMip + mip, t.layer, 1};
    region.imageExtent = {mipExtent(t.desc.width, mip), mipExtent(t.desc.height, mip), 1};
    vk_.vkCmdCopyImageToBuffer(cb.value(), t.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
    // Makes the copy visible to the host read below.
    VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = readback.buffer;
    toHost.offset = readback.offset;
    toHost.size = bytes;
    vk_.vkCmdPipelineBarrier(cb.value(), VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &toHost, 0, nullptr);
    // The block goes back to the ring at the submit, but nothing writes it before the copy out.
    Status s = submitAndWait();
    if (s && t.desc.format == Format::D24S8)
        d24s8FromVulkan(readback.mapped, out, bytes);
    else if (s)
        std::memcpy(out, readback.mapped, bytes);
    return s;
}

Result<SamplerHandle> VulkanDevice::makeSampler(const SamplerDesc& desc) {
    auto filter = [](Filter f) { return f == Filter::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST; };
    const VkSamplerAddressMode address = desc.address == AddressMode::Repeat ? VK_SAMPLER_ADDRESS_MODE_REPEAT
        : desc.address == AddressMode::MirroredRepeat                        ? VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT
                                                                             : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = filter(desc.magFilter);
    sci.minFilter = filter(desc.minFilter);
    sci.mipmapMode = desc.mipFilter == Filter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = address;
    sci.maxLod = VK_LOD_CLAMP_NONE;
    VkSampler s;
    SFX_VK(vk_.vkCreateSampler(device_, &sci, nullptr, &s));
    return samplers_.insert(VulkanSampler{desc, s});
}

}  // namespace sfx::vulkan
