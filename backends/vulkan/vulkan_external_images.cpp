// Host images in, SDK images out: importImage wraps a host VkImage as a texture the SDK never
// destroys, nativeImage gives the Vulkan objects of any texture, and the state contract of
// docs/integration.md ("Host images and the state contract"): an imported image is in the
// host's layout whenever the host hands the device work, with unknown host accesses before it,
// and every flush records one barrier that puts it back in that layout after the SDK's accesses.
#include <string>

#include "vulkan_device_impl.hpp"
#include "vulkan_formats.hpp"

#include "sfx/validation_errors.hpp"

namespace sfx::vulkan {
namespace {

constexpr const char* kVkFormatList =
    "VK_FORMAT_R8_UNORM, R8G8B8A8_UNORM, R16_SFLOAT, R16G16_SFLOAT, R16G16B16A16_SFLOAT, R32_SFLOAT, "
    "R32G32_SFLOAT, R32G32B32A32_SFLOAT, R32_UINT, D16_UNORM, D24_UNORM_S8_UINT, D32_SFLOAT";

// The HAL format whose VkFormat is `f`; Undefined for any other.
Format fromVkFormat(VkFormat f) {
    for (uint32_t i = 1; i < uint32_t(Format::Count); ++i)
        if (f != VK_FORMAT_UNDEFINED && toVkFormat(Format(i)) == f) return Format(i);
    return Format::Undefined;
}

Result<Format> resolveFormat(const ExternalImage& e) {
    if (e.vkFormat == VK_FORMAT_UNDEFINED) {
        if (e.format == Format::Undefined || uint32_t(e.format) >= uint32_t(Format::Count))
            return invalidArgument(
                "ExternalImage.format",
                e.format == Format::Undefined ? "Undefined (and vkFormat VK_FORMAT_UNDEFINED)" : std::to_string(uint32_t(e.format)),
                std::string("an sfx::Format other than Undefined, or vkFormat one of ") + kVkFormatList);
        return e.format;
    }
    const Format mapped = fromVkFormat(e.vkFormat);
    if (mapped == Format::Undefined) return invalidArgument("ExternalImage.vkFormat", "VkFormat " + std::to_string(int(e.vkFormat)), kVkFormatList);
    if (e.format != Format::Undefined && e.format != mapped)
        return invalidArgument("ExternalImage.format", toString(e.format),
                               std::string("Undefined or the format of vkFormat (") + toString(mapped) + ")");
    return mapped;
}

// Layouts a texture of `format` may be left in by the host (and is handed back in).
bool layoutFits(VkImageLayout l, Format format) {
    switch (l) {
        case VK_IMAGE_LAYOUT_GENERAL:
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
        case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
        case VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL: return true;
        case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL: return !isDepthFormat(format);
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL:
        case VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL: return isDepthFormat(format);
        default: return false;
    }
}

// What the SDK assumes of an imported mip whenever the host hands it work: in the host's layout,
// after host accesses of any stage (so its first use waits for all of them and sees their writes).
AccessState hostState(VkImageLayout layout) {
    AccessState s;
    s.layout = layout;
    s.writeStages = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
    s.writeAccess = VK_ACCESS_MEMORY_WRITE_BIT;
    return s;
}

bool usedSinceHandBack(const AccessState& s, VkImageLayout hostLayout) {
    return s.layout != hostLayout || s.readStages != 0 || s.writeStages != VK_PIPELINE_STAGE_ALL_COMMANDS_BIT ||
        s.writeAccess != VK_ACCESS_MEMORY_WRITE_BIT || s.visibleCount != 0;
}

VulkanDevice* vulkanDevice(Device& device) { return dynamic_cast<VulkanDevice*>(&device); }

Status notVulkan(const char* call, const Device& device) {
    return validation::fail(validation::Error::DeviceWrongApi, {call, toString(device.caps().backend), "Vulkan"});
}

}  // namespace

Result<TextureHandle> VulkanDevice::importExternal(const ExternalImage& e) {
    if (!e.image) return invalidArgument("ExternalImage.image", "VK_NULL_HANDLE", "the host's VkImage");
    Result<Format> format = resolveFormat(e);
    if (!format) return format.status();
    TextureDesc desc{e.width, e.height, e.mipLevels, format.value(), e.usage, e.debugName ? e.debugName : ""};
    if (Status s = validation::textureDesc(desc, caps_); !s) return Status{s.code(), "importImage (ExternalImage as a TextureDesc): " + s.message()};
    if (e.vkUsage == 0) return invalidArgument("ExternalImage.vkUsage", "0", "the VkImageUsageFlags the image was created with");
    const VkImageUsageFlags attachment = isDepthFormat(desc.format) ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT
                                                                    : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    const std::pair<uint32_t, std::pair<VkImageUsageFlags, const char*>> needs[] = {
        {kTextureSampled, {VK_IMAGE_USAGE_SAMPLED_BIT, "VK_IMAGE_USAGE_SAMPLED_BIT"}},
        {kTextureStorage, {VK_IMAGE_USAGE_STORAGE_BIT, "VK_IMAGE_USAGE_STORAGE_BIT"}},
        {kTextureRenderTarget,
         {attachment, isDepthFormat(desc.format) ? "VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT" : "VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT"}},
    };
    for (const auto& [bit, vk] : needs)
        if ((e.usage & bit) && !(e.vkUsage & vk.first))
            return invalidArgument("ExternalImage.usage",
                                   std::string(bit == kTextureSampled       ? "kTextureSampled"
                                                   : bit == kTextureStorage ? "kTextureStorage"
                                                                            : "kTextureRenderTarget") +
                                       " on an image without " + vk.second,
                                   "only what ExternalImage.vkUsage allows");
    if (!layoutFits(e.layout, desc.format))
        return invalidArgument("ExternalImage.layout", "VkImageLayout " + std::to_string(int(e.layout)) + " for " + toString(desc.format),
                               isDepthFormat(desc.format)
                                   ? "GENERAL, SHADER_READ_ONLY_OPTIMAL, TRANSFER_SRC/DST_OPTIMAL, READ_ONLY_OPTIMAL, ATTACHMENT_OPTIMAL, "
                                     "DEPTH_STENCIL_ATTACHMENT/READ_ONLY_OPTIMAL, DEPTH_ATTACHMENT/READ_ONLY_OPTIMAL"
                                   : "GENERAL, SHADER_READ_ONLY_OPTIMAL, TRANSFER_SRC/DST_OPTIMAL, READ_ONLY_OPTIMAL, ATTACHMENT_OPTIMAL, "
                                     "COLOR_ATTACHMENT_OPTIMAL");

    VulkanTexture t;
    t.desc = desc;
    t.format = toVkFormat(desc.format);
    t.image = e.image;
    t.external = true;
    t.baseMip = e.baseMip;
    t.layer = e.layer;
    t.hostLayout = e.layout;
    t.vkUsage = e.vkUsage;
    t.hostView = e.view;
    t.mips.assign(desc.mipLevels, hostState(e.layout));
    t.attachmentViews.assign(desc.mipLevels, VK_NULL_HANDLE);
    changeObjects();
    TextureHandle h = textures_.insert(std::move(t));
    externals_.push_back(h);
    return h;
}

Result<NativeImage> VulkanDevice::native(TextureHandle h) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture& t = textures_.get(h);
    Result<VkImageView> view = sampledView(t, 0, t.desc.mipLevels);
    if (!view) return view.status();
    return NativeImage{t.image, view.value(), t.format, t.external ? t.hostLayout : t.mips[0].layout, t.baseMip, t.layer};
}

void VulkanDevice::handBack(VkCommandBuffer cb, VulkanTexture& t) {
    std::vector<VkImageMemoryBarrier> barriers;
    VkPipelineStageFlags src = 0;
    for (uint32_t m = 0; m < t.mips.size(); ++m) {
        AccessState& s = t.mips[m];
        if (!usedSinceHandBack(s, t.hostLayout)) continue;
        VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        b.srcAccessMask = s.writeAccess;
        b.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
        b.oldLayout = s.layout;
        b.newLayout = t.hostLayout;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = t.image;
        b.subresourceRange = t.range(fullAspect(t.desc.format), m, 1);
        barriers.push_back(b);
        src |= s.writeStages | s.readStages;
        s = hostState(t.hostLayout);
    }
    if (barriers.empty()) return;
    // The host's next access may be of any stage: it waits for all of the SDK's.
    vk_.vkCmdPipelineBarrier(cb, src, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0, nullptr, uint32_t(barriers.size()), barriers.data());
}

void VulkanDevice::handBackExternal(VkCommandBuffer cb) {
    for (TextureHandle h : externals_) handBack(cb, textures_.get(h));
}

Status VulkanDevice::forgetExternal(TextureHandle h, VulkanTexture& t) {
    std::erase(externals_, h);
    for (const AccessState& s : t.mips)
        if (usedSinceHandBack(s, t.hostLayout)) {
            Result<VkCommandBuffer> cb = recording();
            if (!cb) return cb.status();
            handBack(cb.value(), t);
            break;
        }
    return Status::ok();
}

Result<TextureHandle> importImage(Device& device, const ExternalImage& image) {
    VulkanDevice* vk = vulkanDevice(device);
    if (!vk) return notVulkan("importImage", device);
    return vk->importExternal(image);
}

Result<NativeImage> nativeImage(Device& device, TextureHandle texture) {
    VulkanDevice* vk = vulkanDevice(device);
    if (!vk) return notVulkan("nativeImage", device);
    return vk->native(texture);
}

}  // namespace sfx::vulkan
