// Barriers: each command records only the barriers its hazards need, from the last use tracked
// per image mip and per buffer (AccessState): a layout transition, a write after reads or writes
// (the earlier accesses must finish first), or a read of a write not yet made visible to the
// reading stage and access. Reads after reads need nothing. Barriers are batched per command:
// with synchronization2, one vkCmdPipelineBarrier2 holding every barrier with its own stage
// masks; without it, one vkCmdPipelineBarrier per pair of source and destination stage masks
// (a driver copies each barrier command into the command buffer, so fewer is cheaper for the
// recording thread). The lists live in the device's CommandScratch and keep their capacity.
#include <algorithm>

#include "vulkan_device_impl.hpp"
#include "vulkan_formats.hpp"

namespace sfx::vulkan {
namespace {

// What one use of a resource needs before it: nothing (src == 0 and no transition), or an
// execution and memory dependency from `src`/`srcAccess` to the use's stages and accesses.
struct Hazard {
    VkPipelineStageFlags src = 0;
    VkAccessFlags srcAccess = 0;
    VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    bool needed = false;
};

bool madeVisible(const AccessState& s, VkPipelineStageFlags stages, VkAccessFlags access) {
    for (uint32_t i = 0; i < s.visibleCount; ++i)
        if ((s.visible[i].first & stages) == stages && (s.visible[i].second & access) == access) return true;
    return false;
}

// Updates `s` for a use and says what barrier the use needs. `image`: the layout counts.
Hazard track(AccessState& s, bool image, VkImageLayout layout, VkPipelineStageFlags stages, VkAccessFlags access, bool write) {
    Hazard h;
    h.oldLayout = s.layout;
    const bool transition = image && s.layout != layout;
    if (write || transition) {
        // Everything earlier must finish (and earlier writes be made available) before this
        // write or transition; a layout transition is itself a write.
        h.src = s.writeStages | s.readStages;
        h.srcAccess = s.writeAccess;
        h.needed = transition || h.src != 0;
        s.layout = layout;
        s.writeStages = stages;
        s.writeAccess = write ? access : 0;
        s.readStages = write ? 0 : stages;
        s.visibleCount = 0;
        if (!write) s.visible[s.visibleCount++] = {stages, access};  // the transition's barrier covers this read
        return h;
    }
    if (s.writeStages && !madeVisible(s, stages, access)) {
        h.src = s.writeStages;
        h.srcAccess = s.writeAccess;
        h.needed = true;
        if (s.visibleCount < s.visible.size()) s.visible[s.visibleCount++] = {stages, access};
        s.writeStages |= stages;  // a later barrier from these stages chains after the write
    }
    s.readStages |= stages;
    return h;
}

// The batch of this command (the first `count` of `batches`) with these stage masks; a batch
// past `count` is reused, its lists cleared.
BarrierBatch& batchFor(std::vector<BarrierBatch>& batches, size_t& count, VkPipelineStageFlags src, VkPipelineStageFlags dst) {
    if (!src) src = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;  // nothing to wait for: a transition only
    for (size_t i = 0; i < count; ++i)
        if (batches[i].src == src && batches[i].dst == dst) return batches[i];
    if (count == batches.size()) batches.emplace_back();
    BarrierBatch& b = batches[count++];
    b.src = src;
    b.dst = dst;
    b.images.clear();
    b.buffers.clear();
    return b;
}

// The same barrier for vkCmdPipelineBarrier (its stage masks go to the call, per batch).
template <class Legacy, class Barrier2>
Legacy legacyAccess(VkStructureType type, const Barrier2& b) {
    Legacy l{type};
    l.srcAccessMask = VkAccessFlags(b.srcAccessMask);
    l.dstAccessMask = VkAccessFlags(b.dstAccessMask);
    l.srcQueueFamilyIndex = b.srcQueueFamilyIndex;
    l.dstQueueFamilyIndex = b.dstQueueFamilyIndex;
    return l;
}
VkImageMemoryBarrier legacyBarrier(const VkImageMemoryBarrier2& b) {
    auto l = legacyAccess<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER, b);
    l.oldLayout = b.oldLayout, l.newLayout = b.newLayout, l.image = b.image, l.subresourceRange = b.subresourceRange;
    return l;
}
VkBufferMemoryBarrier legacyBarrier(const VkBufferMemoryBarrier2& b) {
    auto l = legacyAccess<VkBufferMemoryBarrier>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER, b);
    l.buffer = b.buffer, l.offset = b.offset, l.size = b.size;
    return l;
}

}  // namespace

VkPipelineStageFlags shaderStages(uint32_t stageMask, bool compute) {
    VkPipelineStageFlags s = 0;
    if (stageMask & stageBit(ShaderStage::Vertex)) s |= VK_PIPELINE_STAGE_VERTEX_SHADER_BIT;
    if (stageMask & stageBit(ShaderStage::Fragment)) s |= VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    if (stageMask & stageBit(ShaderStage::Compute)) s |= VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    if (!s) s = compute ? VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT : VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    return s;
}

void VulkanDevice::barriers(VkCommandBuffer cb, std::span<const ImageUse> images, std::span<const BufferUse> bufferUses) {
    // One entry per image mip and per buffer: a command's several uses of one resource (say,
    // the same texture sampled by two draws) make a single use with their stages and accesses.
    std::vector<MipBarrierUse>& mips = scratch_.mips;
    std::vector<BufferUse>& buffers = scratch_.buffers;
    std::vector<BarrierBatch>& batches = scratch_.batches;
    size_t& batchCount = scratch_.batchCount;
    std::vector<VkImageMemoryBarrier2>& images2 = scratch_.images2;
    std::vector<VkBufferMemoryBarrier2>& buffers2 = scratch_.buffers2;
    mips.clear();
    buffers.clear();
    images2.clear();
    buffers2.clear();
    batchCount = 0;
    for (const ImageUse& u : images)
        for (uint32_t m = u.baseMip; m < u.baseMip + u.mipCount; ++m) {
            auto it = std::find_if(mips.begin(), mips.end(), [&](const MipBarrierUse& e) { return e.texture == u.texture && e.mip == m; });
            if (it == mips.end()) {
                mips.push_back({u.texture, m, u});
            } else {
                it->use.stages |= u.stages;
                it->use.access |= u.access;
                it->use.write = it->use.write || u.write;
            }
        }
    for (const BufferUse& u : bufferUses) {
        auto it = std::find_if(buffers.begin(), buffers.end(), [&](const BufferUse& e) { return e.buffer == u.buffer; });
        if (it == buffers.end()) {
            buffers.push_back(u);
        } else {
            it->stages |= u.stages;
            it->access |= u.access;
            it->write = it->write || u.write;
        }
    }

    // Commands going into an open recording note the states its resources start from.
    const bool intoRecording = recordingOpen() && cb == open_.commandBuffer;
    for (const MipBarrierUse& e : mips) {
        if (intoRecording) noteRecordedUse(e.texture, e.mip, nullptr, e.use.layout, e.use.stages, e.use.access, e.use.write);
        const Hazard h = track(e.texture->mips[e.mip], true, e.use.layout, e.use.stages, e.use.access, e.use.write);
        if (!h.needed) continue;
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.srcStageMask = h.src;  // the legacy stage and access bits keep their values in the *2 flags
        b.srcAccessMask = h.srcAccess;
        b.dstStageMask = e.use.stages;
        b.dstAccessMask = e.use.access;
        b.oldLayout = h.oldLayout;
        b.newLayout = e.use.layout;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = e.texture->image;
        b.subresourceRange = e.texture->range(fullAspect(e.texture->desc.format), e.mip, 1);
        if (synchronization2_)
            images2.push_back(b);
        else
            batchFor(batches, batchCount, h.src, e.use.stages).images.push_back(legacyBarrier(b));
    }
    for (const BufferUse& u : buffers) {
        if (intoRecording) noteRecordedUse(nullptr, 0, u.buffer, VK_IMAGE_LAYOUT_UNDEFINED, u.stages, u.access, u.write);
        const Hazard h = track(u.buffer->state, false, VK_IMAGE_LAYOUT_UNDEFINED, u.stages, u.access, u.write);
        if (!h.needed) continue;
        VkBufferMemoryBarrier2 b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
        b.srcStageMask = h.src;
        b.srcAccessMask = h.srcAccess;
        b.dstStageMask = u.stages;
        b.dstAccessMask = u.access;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.buffer = u.buffer->buffer;
        b.offset = 0;
        b.size = VK_WHOLE_SIZE;
        if (synchronization2_)
            buffers2.push_back(b);
        else
            batchFor(batches, batchCount, h.src, u.stages).buffers.push_back(legacyBarrier(b));
    }
    if (!images2.empty() || !buffers2.empty()) {
        VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dependency.bufferMemoryBarrierCount = uint32_t(buffers2.size());
        dependency.pBufferMemoryBarriers = buffers2.data();
        dependency.imageMemoryBarrierCount = uint32_t(images2.size());
        dependency.pImageMemoryBarriers = images2.data();
        vk_.vkCmdPipelineBarrier2(cb, &dependency);
    }
    for (size_t i = 0; i < batchCount; ++i) {
        const BarrierBatch& b = batches[i];
        vk_.vkCmdPipelineBarrier(cb, b.src, b.dst, 0, 0, nullptr, uint32_t(b.buffers.size()), b.buffers.data(), uint32_t(b.images.size()),
                                 b.images.data());
    }
}

}  // namespace sfx::vulkan
