// The staging ring: the bytes of buffer writes, texture uploads and texture readbacks pass
// through host-visible blocks that are made once and reused, so a steady frame allocates no
// memory. A block in use belongs to the command buffer that reads it: the device's own (free
// again once its submit has been waited for) or the host's (free at the next
// setCommandBuffer, when the host has finished the previous one). A request larger than a
// block gets a block of its own size, kept for the next such request.
#include <algorithm>

#include "vulkan_device_impl.hpp"

namespace sfx::vulkan {
namespace {

constexpr uint64_t kStagingBlockBytes = 1u << 20;
// Covers every texel size and the copy-offset alignment of any device.
constexpr uint64_t kStagingAlignment = 256;

uint64_t alignUp(uint64_t v, uint64_t a) { return (v + a - 1) / a * a; }

}  // namespace

Result<StagingSlice> VulkanDevice::stage(uint64_t bytes) {
    std::vector<StagingBlock>& inUse = hostCommandBuffer_ ? stagingHost_ : stagingOwn_;
    if (!inUse.empty()) {
        StagingBlock& b = inUse.back();
        const uint64_t offset = alignUp(b.used, kStagingAlignment);
        if (offset + bytes <= b.buffer.desc.size) {
            b.used = offset + bytes;
            return StagingSlice{b.buffer.buffer, offset, static_cast<uint8_t*>(b.buffer.alloc.mapped) + offset};
        }
    }
    // The smallest idle block that holds the request, else a new one.
    auto best = stagingIdle_.end();
    for (auto it = stagingIdle_.begin(); it != stagingIdle_.end(); ++it)
        if (it->buffer.desc.size >= bytes && (best == stagingIdle_.end() || it->buffer.desc.size < best->buffer.desc.size)) best = it;
    if (best != stagingIdle_.end()) {
        inUse.push_back(std::move(*best));
        stagingIdle_.erase(best);
    } else {
        Result<VulkanBuffer> b = makeBuffer(std::max(bytes, kStagingBlockBytes), VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                            "sfx staging ring");
        if (!b) return b.status();
        stagingCount_.add();
        inUse.push_back({std::move(b.value()), 0});
    }
    StagingBlock& b = inUse.back();
    b.used = bytes;
    return StagingSlice{b.buffer.buffer, 0, b.buffer.alloc.mapped};
}

void VulkanDevice::recycleStaging(std::vector<StagingBlock>& blocks) {
    for (StagingBlock& b : blocks) {
        b.used = 0;
        stagingIdle_.push_back(std::move(b));
    }
    blocks.clear();
}

void VulkanDevice::destroyStaging() {
    recycleStaging(stagingOwn_);
    recycleStaging(stagingHost_);
    for (StagingBlock& b : stagingIdle_) {
        retire(b.buffer, pending_);
        stagingCount_.remove();
    }
    stagingIdle_.clear();
}

}  // namespace sfx::vulkan
