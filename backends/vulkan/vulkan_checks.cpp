// Every check the Vulkan backend makes on its own rather than through sfx::validation, in one
// place so that a follow-up can move them into the shared validation (the GL backend has its own
// copies of most of them):
// - binding versus reflection (ReflectionMatch): a binding given twice, a binding the program
//   does not reflect, a binding of the wrong kind, a reflected resource left unbound;
// - binding versus resource: a storage image without kTextureStorage; a buffer binding without
//   kBufferUniform / kBufferStorage, out of range, misaligned (minUniform/StorageBufferOffset-
//   Alignment), over maxUniform/StorageBufferRange, or smaller than the reflected block;
// - attachments (checkAttachments, checkPipelineAttachments): a pass without attachments, too
//   many colour attachments, a colour or depth target of the wrong kind or without
//   kTextureRenderTarget, an unknown load op, attachments of different sizes, a draw pipeline
//   made for other attachment formats;
// - layout conflicts (checkLayoutConflicts): one mip used in two layouts by one command.
#include "vulkan_checks.hpp"

#include <algorithm>
#include <string>

#include "sfx/hal_validation.hpp"

namespace sfx::vulkan {

Result<const ShaderResource*> ReflectionMatch::claim(uint32_t binding, ResourceKind kind, const char* arg) {
    const std::string b = std::to_string(binding);
    if (std::find(given_.begin(), given_.end(), binding) != given_.end())
        return invalidArgument(std::string(arg) + ".binding", b, "a binding given once per draw");
    given_.push_back(binding);
    for (const ShaderResource& r : pipeline_.resources)
        if (r.binding == binding) {
            if (r.kind != kind)
                return invalidArgument(std::string(arg) + ".binding", b,
                                       "a " + std::string(toString(kind)) + " binding; program '" + pipeline_.programName +
                                           "' has " + toString(r.kind) + " '" + r.name + "' there");
            return &r;
        }
    return invalidArgument(std::string(arg) + ".binding", b,
                           "a binding of program '" + pipeline_.programName + "', which has none at " + b);
}

Status ReflectionMatch::allClaimed() const {
    for (const ShaderResource& r : pipeline_.resources)
        if (std::find(given_.begin(), given_.end(), r.binding) == given_.end())
            return invalidArgument("BindingSet", "without " + std::string(toString(r.kind)) + " '" + r.name + "' (binding " +
                                                     std::to_string(r.binding) + ")",
                                   "every resource of program '" + pipeline_.programName + "'");
    return Status::ok();
}

Status checkStorageImageUsage(const TextureDesc& desc) {
    if (!(desc.usage & kTextureStorage))
        return invalidArgument("StorageImageBinding.texture", "a texture without kTextureStorage", "a storage texture");
    return Status::ok();
}

Result<uint64_t> checkBufferBinding(const BufferDesc& buffer, const BufferBinding& bb, ResourceKind kind,
                                    uint32_t usageBit, const ShaderResource& block, uint64_t alignment,
                                    uint64_t maxRange) {
    const bool uniform = kind == ResourceKind::UniformBuffer;
    const char* arg = uniform ? "uniformBuffers[].buffer" : "storageBuffers[].buffer";
    if (!(buffer.usage & usageBit))
        return invalidArgument(arg, "a buffer without " + std::string(uniform ? "kBufferUniform" : "kBufferStorage"),
                               "a buffer with that usage");
    const uint64_t size = bb.size ? bb.size : (bb.offset < buffer.size ? buffer.size - bb.offset : 0);
    SFX_TRY(validation::bufferRange(buffer, bb.offset, size, "BufferBinding range"));
    if (bb.offset % alignment != 0)
        return invalidArgument("BufferBinding.offset", std::to_string(bb.offset), "a multiple of " + std::to_string(alignment));
    if (size > maxRange)
        return invalidArgument("BufferBinding.size", std::to_string(size), "at most " + std::to_string(maxRange));
    if (block.blockSize > size)
        return invalidArgument("BufferBinding.size", std::to_string(size),
                               "at least the " + std::to_string(block.blockSize) + " bytes of block '" + block.name + "'");
    return size;
}

Status checkAttachments(const RenderPassDesc& pass, HandlePool<TextureTag, VulkanTexture>& textures,
                        const DeviceCaps& caps, PassTargets& out) {
    if (pass.colors.empty() && pass.depth.texture.isNull())
        return invalidArgument("RenderPassDesc", "without attachments", "at least one colour or depth attachment");
    if (pass.colors.size() > caps.limits.maxColorAttachments)
        return invalidArgument("RenderPassDesc.colors.size()", std::to_string(pass.colors.size()),
                               "[0, " + std::to_string(caps.limits.maxColorAttachments) + "]");
    auto extent = [&](const VulkanTexture& t, uint32_t mip) -> Status {
        const uint32_t w = mipExtent(t.desc.width, mip), h = mipExtent(t.desc.height, mip);
        if (out.width == 0) {
            out.width = w;
            out.height = h;
        } else if (w != out.width || h != out.height) {
            return invalidArgument("RenderPassDesc attachment size", std::to_string(w) + "x" + std::to_string(h),
                                   "the same size as the first attachment, " + std::to_string(out.width) + "x" +
                                       std::to_string(out.height));
        }
        return Status::ok();
    };
    for (const ColorAttachment& c : pass.colors) {
        SFX_TRY(textures.check(c.texture, "RenderPassDesc.colors[].texture"));
        VulkanTexture& t = textures.get(c.texture);
        SFX_TRY(validation::mipRange(t.desc, c.mip, "RenderPassDesc.colors[].mip"));
        if (!(t.desc.usage & kTextureRenderTarget) || isDepthFormat(t.desc.format))
            return invalidArgument("RenderPassDesc.colors[].texture", std::string("a ") + toString(t.desc.format) + " texture" +
                                                                          ((t.desc.usage & kTextureRenderTarget) ? "" : " without kTextureRenderTarget"),
                                   "a colour texture with kTextureRenderTarget");
        if (uint32_t(c.load) > uint32_t(LoadOp::DontCare))
            return invalidArgument("RenderPassDesc.colors[].load", std::to_string(uint32_t(c.load)), "Clear, Load or DontCare");
        SFX_TRY(extent(t, c.mip));
        out.colorFormats.push_back(t.desc.format);
        out.uses.images.push_back({&t, c.mip, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                   VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, true});
    }
    if (!pass.depth.texture.isNull()) {
        SFX_TRY(textures.check(pass.depth.texture, "RenderPassDesc.depth.texture"));
        VulkanTexture* depth = &textures.get(pass.depth.texture);
        if (!(depth->desc.usage & kTextureRenderTarget) || !isDepthFormat(depth->desc.format))
            return invalidArgument("RenderPassDesc.depth.texture", std::string("a ") + toString(depth->desc.format) + " texture",
                                   "a depth texture with kTextureRenderTarget");
        if (uint32_t(pass.depth.load) > uint32_t(LoadOp::DontCare))
            return invalidArgument("RenderPassDesc.depth.load", std::to_string(uint32_t(pass.depth.load)), "Clear, Load or DontCare");
        SFX_TRY(extent(*depth, 0));
        out.depth = depth;
        out.depthFormat = depth->desc.format;
        out.uses.images.push_back({depth, 0, 1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                                   true});
    }
    return Status::ok();
}

Status checkPipelineAttachments(const VulkanPipeline& pl, const PassTargets& targets) {
    if (pl.colorFormats != targets.colorFormats || pl.depthFormat != targets.depthFormat)
        return invalidArgument("DrawDesc.pipeline", "a pipeline made for other attachment formats",
                               "a pipeline whose colorFormats and depthFormat match the pass's attachments");
    return Status::ok();
}

Status checkLayoutConflicts(const std::vector<ImageUse>& uses) {
    std::vector<VkImage> images;
    std::vector<uint32_t> mips;
    std::vector<VkImageLayout> layouts;
    for (const ImageUse& u : uses)
        for (uint32_t m = u.baseMip; m < u.baseMip + u.mipCount; ++m) {
            images.push_back(u.texture->image);
            mips.push_back(m);
            layouts.push_back(u.layout);
        }
    for (size_t i = 0; i < images.size(); ++i)
        for (size_t j = i + 1; j < images.size(); ++j)
            if (images[i] == images[j] && mips[i] == mips[j] && layouts[i] != layouts[j])
                return invalidArgument("texture mip " + std::to_string(mips[i]), "used two ways in one command",
                                       "a mip that is either sampled, a storage image or an attachment, not several");
    return Status::ok();
}

}  // namespace sfx::vulkan
