// Memory and staging: allocations by memory type, host-visible coherent buffers (HAL buffers and
// the staging buffers of texture and buffer transfers), and buffer writes and reads kept in order
// with the commands recorded around them.
#include <cstring>

#include "vulkan_device_impl.hpp"

namespace sfx::vulkan {

Result<Allocation> VulkanDevice::allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags want, bool map) {
    int type = -1;
    for (uint32_t i = 0; i < memProps_.memoryTypeCount && type < 0; ++i)
        if ((req.memoryTypeBits & (1u << i)) && (memProps_.memoryTypes[i].propertyFlags & want) == want) type = int(i);
    if (type < 0) return Status{StatusCode::DeviceError, "no Vulkan memory type has the properties " + std::to_string(want)};
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = uint32_t(type);
    Allocation a;
    a.size = req.size;
    SFX_VK(vk_.vkAllocateMemory(device_, &ai, nullptr, &a.memory));
    if (map) {
        VkResult r = vk_.vkMapMemory(device_, a.memory, 0, VK_WHOLE_SIZE, 0, &a.mapped);
        if (r != VK_SUCCESS) {
            vk_.vkFreeMemory(device_, a.memory, nullptr);
            return vkError("vkMapMemory", r);
        }
    }
    memoryCount_.add();
    memoryBytes_ += a.size;
    return a;
}

void VulkanDevice::freeMemory(VkDeviceMemory memory, uint64_t bytes) {
    vk_.vkFreeMemory(device_, memory, nullptr);
    memoryCount_.remove();
    memoryBytes_ -= bytes;
}

Result<VulkanBuffer> VulkanDevice::makeBuffer(uint64_t size, VkBufferUsageFlags usage, const char* name) {
    VulkanBuffer b;
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size;
    bci.usage = usage;
    bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    SFX_VK(vk_.vkCreateBuffer(device_, &bci, nullptr, &b.buffer));
    VkMemoryRequirements req;
    vk_.vkGetBufferMemoryRequirements(device_, b.buffer, &req);
    Result<Allocation> a = allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, true);
    if (!a) {
        vk_.vkDestroyBuffer(device_, b.buffer, nullptr);
        return a.status();
    }
    b.alloc = a.value();
    VkResult r = vk_.vkBindBufferMemory(device_, b.buffer, b.alloc.memory, 0);
    if (r != VK_SUCCESS) {
        vk_.vkDestroyBuffer(device_, b.buffer, nullptr);
        freeMemory(b.alloc.memory, b.alloc.size);
        return vkError("vkBindBufferMemory", r);
    }
    setName(VK_OBJECT_TYPE_BUFFER, uint64_t(b.buffer), name);
    b.desc.size = size;
    return b;
}

Result<BufferHandle> VulkanDevice::makeHalBuffer(const BufferDesc& desc) {
    VkBufferUsageFlags usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (desc.usage & kBufferUniform) usage |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    if (desc.usage & kBufferStorage) usage |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    if (desc.usage & kBufferVertex) usage |= VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    if (desc.usage & kBufferIndex) usage |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
    Result<VulkanBuffer> b = makeBuffer(desc.size, usage, desc.debugName);
    if (!b) return b.status();
    b->desc = desc;
    std::memset(b->alloc.mapped, 0, desc.size);  // same start as every other backend
    return buffers_.insert(std::move(b.value()));
}

Status VulkanDevice::stageBufferWrite(VulkanBuffer& b, uint64_t offset, const void* data, size_t bytes) {
    if (!recording_ && !hostCommandBuffer_ && !usedByOpenRecording(b.state)) {
        // Nothing recorded and the GPU idle since the last flush: the mapping can take it now.
        std::memcpy(static_cast<uint8_t*>(b.alloc.mapped) + offset, data, bytes);
        return Status::ok();
    }
    // Recorded commands may still read the old contents: copy in order with them, through the
    // staging ring (before an open recording, unless that has read the buffer already).
    Result<VkCommandBuffer> cb = writeRecording(b.state);
    if (!cb) return cb.status();
    Result<StagingSlice> staging = stage(bytes);
    if (!staging) return staging.status();
    std::memcpy(staging->mapped, data, bytes);
    const BufferUse copyWrite{&b, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, true};
    barriers(cb.value(), {}, std::span(&copyWrite, 1));
    VkBufferCopy region{staging->offset, offset, bytes};
    vk_.vkCmdCopyBuffer(cb.value(), staging->buffer, b.buffer, 1, &region);
    return Status::ok();
}

Status VulkanDevice::readBackBuffer(VulkanBuffer& b, uint64_t offset, void* out, size_t bytes) {
    if (recording_) {
        Result<VkCommandBuffer> cb = recording();
        if (!cb) return cb.status();
        // The buffer's last GPU write made visible to the host read below.
        const BufferUse hostRead{&b, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT, false};
        barriers(cb.value(), {}, std::span(&hostRead, 1));
        SFX_TRY(submitAndWait());
    }
    std::memcpy(out, static_cast<const uint8_t*>(b.alloc.mapped) + offset, bytes);
    return Status::ok();
}

DeviceStats VulkanDevice::stats() const {
    DeviceStats s = halObjectStats(textures_, buffers_, samplers_, programs_, pipelines_, timers_);
    s.recordings = objectCount(recordings_);
    s.memoryAllocations = memoryCount_;
    s.stagingBuffers = stagingCount_;
    s.descriptorSets = descriptorSetCount_;
    s.descriptorPools = descriptorPoolCount_;
    s.imageViews = imageViewCount_;
    s.deviceMemoryBytes = memoryBytes_;
    return s;
}

}  // namespace sfx::vulkan
