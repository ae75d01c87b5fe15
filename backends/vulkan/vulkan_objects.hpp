// The backend's own records of HAL objects, and what a command gathers before it is recorded.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "sfx/hal.hpp"
#include "sfx/hal_validation.hpp"

namespace sfx::vulkan {

struct Allocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    uint64_t size = 0;
};

// How a buffer or an image mip was last used, so that the next command records only the barrier
// its hazards need (vulkan_barriers.cpp). Kept across submits: a host command buffer may be
// recorded while the previous one runs.
struct AccessState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // images only
    // The last write (or layout transition) and the stages chained after it by barriers since.
    VkPipelineStageFlags writeStages = 0;
    VkAccessFlags writeAccess = 0;        // 0 after a layout transition, which the barrier made available
    VkPipelineStageFlags readStages = 0;  // reads since the last write: what a write must wait for
    // Stage and access pairs the last write has been made visible to (a small set; a full one
    // only costs an extra barrier).
    std::array<std::pair<VkPipelineStageFlags, VkAccessFlags>, 4> visible{};
    uint32_t visibleCount = 0;
    // The open recording that has used this resource (its serial) and the index of its entry
    // there (vulkan_recordings.cpp); not part of the state sameState() compares.
    uint64_t recordingSerial = 0;
    uint32_t recordingEntry = 0;
};
// The same tracked access, the recording marks aside.
bool sameState(const AccessState& a, const AccessState& b);

struct VulkanSampler {
    SamplerDesc desc;
    VkSampler sampler = VK_NULL_HANDLE;
};

struct VulkanBuffer {
    BufferDesc desc;
    VkBuffer buffer = VK_NULL_HANDLE;
    Allocation alloc;
    AccessState state;
};

// A block of the staging ring (vulkan_staging.cpp): host-visible, mapped, used front to back.
struct StagingBlock {
    VulkanBuffer buffer;
    uint64_t used = 0;
};

struct VulkanTexture {
    TextureDesc desc;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    uint64_t memoryBytes = 0;
    std::vector<AccessState> mips;                               // layout and last use per mip
    std::map<std::pair<uint32_t, uint32_t>, VkImageView> views;  // (baseMip, mipCount) -> sampled view
    std::vector<VkImageView> attachmentViews;                    // per mip, all aspects
    // An imported host image (vulkan_external_images.cpp): never destroyed by the SDK; its mip i
    // is the image's mip baseMip + i of `layer`, and every flush hands it back in hostLayout.
    bool external = false;
    uint32_t baseMip = 0, layer = 0;
    VkImageLayout hostLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageUsageFlags vkUsage = 0;
    VkImageView hostView = VK_NULL_HANDLE;  // the host's sampled view of all mips, or none
    VkImageSubresourceRange range(VkImageAspectFlags aspect, uint32_t mip, uint32_t count) const { return {aspect, baseMip + mip, count, layer, 1}; }
};

struct VulkanProgram {
    validation::ProgramInfo info;
    std::vector<std::pair<ShaderStage, VkShaderModule>> modules;
};

struct VulkanPipeline {
    validation::PipelineInfo info;  // what the shared validation checks draws and dispatches against
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;  // own, so the program may go first
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    bool usesVertexBuffer() const { return !info.vertexLayout.attributes.empty(); }
};

struct VulkanTimer {
    uint32_t queryIndex = 0;  // begin; end is queryIndex + 1
    enum class State { Idle, Begun, Ended, Flushed } state = State::Idle;
    double wallMs = 0;          // WallClockAfterFinish fallback
    bool hostRecorded = false;  // recorded into a host command buffer: results may not be ready
};

// Objects released once the GPU is done with the commands recorded so far.
struct Garbage {
    std::vector<VkBuffer> buffers;
    std::vector<VkDeviceMemory> memories;
    uint64_t memoryBytes = 0;  // of `memories`
    std::vector<VkImage> images;
    std::vector<VkImageView> views;
    std::vector<VkSampler> samplers;
    std::vector<VkPipeline> pipelines;
    std::vector<VkPipelineLayout> pipelineLayouts;
    std::vector<VkDescriptorSetLayout> setLayouts;
    std::vector<VkShaderModule> modules;
    std::vector<VkDescriptorPool> descriptorPools;  // of a cleared descriptor-set cache
    std::vector<VkCommandBuffer> secondaries;       // of destroyed recordings: back to the free list
    uint64_t descriptorSets = 0;                    // the sets they held
};

// A buffer or image mip that a recording uses: its state where the recording starts and ends,
// and the stages and accesses of all its uses there (vulkan_recordings.cpp).
struct VulkanTexture;
struct RecordedResource {
    VulkanTexture* texture = nullptr;  // with mip; else buffer
    uint32_t mip = 0;
    VulkanBuffer* buffer = nullptr;
    AccessState entry, exit;
    VkPipelineStageFlags stages = 0;
    VkAccessFlags access = 0;
    // Written or moved to another layout: a replay needs exactly the entry state. A resource only
    // read may be in any state: the replay records the barrier (and layout transition) its reads
    // need after whatever came before.
    bool written = false;
};

// Commands recorded once and replayed (Device::beginRecording): a secondary command buffer, the
// arguments of its HAL calls (to compare a replay's calls with), and what it needs of resources.
struct VulkanRecording {
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    uint64_t epoch = 0;           // the device's object epoch when recorded
    bool reusable = true;         // false: wrote a resource it had used, or held a timer
    const char* why = "";         // when not reusable
    std::vector<uint64_t> calls;  // the HAL calls' arguments, flattened
    std::vector<RecordedResource> resources;
};

// Timestamp query pairs in the device's pool, and descriptor sets per descriptor pool.
constexpr uint32_t kMaxTimers = 256;
constexpr uint32_t kDescriptorPoolSets = 256;

// The pipeline stages of a resource's shader stages (ShaderResource::stages); all of the
// pipeline's when reflection names none.
VkPipelineStageFlags shaderStages(uint32_t stageMask, bool compute);

// A texture mip range that a command needs in a layout, with the stages and accesses it makes.
struct ImageUse {
    VulkanTexture* texture;
    uint32_t baseMip, mipCount;
    VkImageLayout layout;
    VkPipelineStageFlags stages;
    VkAccessFlags access;
    bool write;
};
// A buffer a command reads or writes.
struct BufferUse {
    VulkanBuffer* buffer;
    VkPipelineStageFlags stages;
    VkAccessFlags access;
    bool write;
};
// A slice of the staging ring: where to copy from, and where the host writes the bytes.
struct StagingSlice {
    VkBuffer buffer;
    uint64_t offset;
    void* mapped;
};

// Everything one command touches; its barriers are made from this (vulkan_barriers.cpp).
struct Uses {
    std::vector<ImageUse> images;
    std::vector<BufferUse> buffers;
};

// A draw or dispatch with its resources resolved (checked by the shared validation), before
// anything is recorded.
struct ResolvedBindings {
    std::vector<VkDescriptorImageInfo> images;  // stable storage for the writes
    std::vector<VkDescriptorBufferInfo> buffers;
    std::vector<VkWriteDescriptorSet> writes;
};

// The attachments of a render pass once checked: their common size, formats and layouts.
struct PassTargets {
    Uses uses;  // attachments first; the draws' bindings are appended
    uint32_t width = 0, height = 0;
    std::vector<Format> colorFormats;
    Format depthFormat = Format::Undefined;
    VulkanTexture* depth = nullptr;
    void clear() {
        uses.images.clear();
        uses.buffers.clear();
        width = height = 0;
        colorFormats.clear();
        depthFormat = Format::Undefined;
        depth = nullptr;
    }
};

// One image mip's merged use within a command (vulkan_barriers.cpp).
struct MipBarrierUse {
    VulkanTexture* texture;
    uint32_t mip;
    ImageUse use;
};
// The barriers of one command with one pair of source and destination stage masks.
struct BarrierBatch {
    VkPipelineStageFlags src = 0, dst = 0;
    std::vector<VkImageMemoryBarrier> images;
    std::vector<VkBufferMemoryBarrier> buffers;
};

// What recording a command needs for a moment, kept by the device and reused (cleared, with
// its capacity) by every command, so that a steady frame records without heap allocations.
struct CommandScratch {
    PassTargets targets;                     // renderPass
    std::vector<ResolvedBindings> resolved;  // per draw (renderPass) or [0] (dispatch)
    Uses dispatchUses;                       // dispatch
    std::vector<VkImageView> colorViews;     // recordRenderPass
    std::vector<VkDescriptorSet> sets;
    std::vector<VkRenderingAttachmentInfo> colorInfos;
    // barriers(): merged uses, and the batches (the first batchCount in use this command).
    std::vector<MipBarrierUse> mips;
    std::vector<BufferUse> buffers;
    std::vector<BarrierBatch> batches;
    size_t batchCount = 0;
    std::vector<VkImageMemoryBarrier2> images2;  // with synchronization2: all in one command
    std::vector<VkBufferMemoryBarrier2> buffers2;
};

}  // namespace sfx::vulkan
