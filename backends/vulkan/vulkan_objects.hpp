// The backend's own records of HAL objects, and what a command gathers before it is recorded.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sfx/hal.hpp"
#include "sfx/hal_validation.hpp"

namespace sfx::vulkan {

struct Allocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
};

struct VulkanBuffer {
    BufferDesc desc;
    VkBuffer buffer = VK_NULL_HANDLE;
    Allocation alloc;
};

struct VulkanTexture {
    TextureDesc desc;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    std::vector<VkImageLayout> layouts;                          // per mip
    std::map<std::pair<uint32_t, uint32_t>, VkImageView> views;  // (baseMip, mipCount) -> sampled view
    std::vector<VkImageView> attachmentViews;                    // per mip, all aspects
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
    std::vector<VkImage> images;
    std::vector<VkImageView> views;
    std::vector<VkSampler> samplers;
    std::vector<VkPipeline> pipelines;
    std::vector<VkPipelineLayout> pipelineLayouts;
    std::vector<VkDescriptorSetLayout> setLayouts;
    std::vector<VkShaderModule> modules;
    std::vector<VkDescriptorPool> descriptorPools;  // retired pools of a host command buffer
};

// Timestamp query pairs in the device's pool, and descriptor sets per descriptor pool.
constexpr uint32_t kMaxTimers = 256;
constexpr uint32_t kDescriptorPoolSets = 256;

// A texture mip range that a command needs in a layout.
struct ImageUse {
    VulkanTexture* texture;
    uint32_t baseMip, mipCount;
    VkImageLayout layout;
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
    std::vector<ImageUse> uses;  // attachments first; the draws' bindings are appended
    uint32_t width = 0, height = 0;
    std::vector<Format> colorFormats;
    Format depthFormat = Format::Undefined;
    VulkanTexture* depth = nullptr;
};

}  // namespace sfx::vulkan
