// A stand-in host's own Vulkan layer, shared by the Vulkan engine sample and the tests on host
// devices: instance (optionally with the Khronos validation layer and synchronization
// validation), device, queue, and the images, buffers and pipelines the
// renderer makes. Nothing here uses the SDK. Every call that creates or allocates something, and
// every buffer <-> image copy, goes through VkHost and is counted, so a test can check that the
// frame loop makes and copies nothing.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "sfx/status.hpp"

namespace sfx::engine {

// What the host itself made or copied so far.
struct HostCounts {
    uint64_t memoryAllocations = 0;  // vkAllocateMemory
    uint64_t objectsCreated = 0;     // vkCreate*, vkAllocateCommandBuffers / DescriptorSets
    uint64_t descriptorWrites = 0;   // vkUpdateDescriptorSets
    uint64_t stagingCopies = 0;      // buffer <-> image copies: uploads and readbacks
    uint64_t submits = 0;            // vkQueueSubmit (one per frame in the loop)
    bool operator==(const HostCounts&) const = default;
};

struct HostImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageUsageFlags usage = 0;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    uint32_t width = 0, height = 0;
    uint32_t texelBytes = 0;
};

struct HostBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;  // host-visible and coherent, mapped for its lifetime
    VkDeviceSize size = 0;
};

// A graphics pipeline of the host's passes (dynamic rendering, dynamic viewport and scissor).
struct PipelineDesc {
    const uint32_t* vertexCode = nullptr;
    size_t vertexWords = 0;
    const uint32_t* fragmentCode = nullptr;
    size_t fragmentWords = 0;
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;  // with depth test LESS and writes
    bool meshVertices = false;                   // position + normal (two vec3) at binding 0
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    uint32_t pushConstantBytes = 0;  // vertex stage
};

class VkHost {
public:
    // BackendUnavailable with the reason when there is no loader, no 1.3 device, or (with
    // `validation`) no VK_LAYER_KHRONOS_validation. `wantSynchronization2`: enable that feature
    // where the device has it (the tests on host devices leave it off, to keep the SDK's
    // barriers without it under synchronization validation).
    Status create(bool validation, bool wantSynchronization2 = true);
    static bool validationLayerInstalled();
    ~VkHost();

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t family = 0;
    bool debugUtils = false;        // a messenger collects the layer's warnings and errors
    bool synchronization2 = false;  // the device feature, enabled when the device has it

    Status makeImage(VkFormat format, VkImageUsageFlags usage, uint32_t width, uint32_t height, HostImage* out);
    Status makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage, HostBuffer* out);
    Status makePipeline(const PipelineDesc& desc, VkPipelineLayout* layout, VkPipeline* pipeline);
    Status makeSetLayout(const std::vector<VkDescriptorSetLayoutBinding>& bindings, VkDescriptorSetLayout* out);
    Status makeCommands(VkCommandPool* pool, VkCommandBuffer* cb, VkFence* fence);
    Status makeSampler(VkSampler* out);
    Status makeDescriptorPool(uint32_t sets, uint32_t uniformBuffers, uint32_t samplers, VkDescriptorPool* out);
    Status allocateSet(VkDescriptorPool pool, VkDescriptorSetLayout layout, VkDescriptorSet* out);
    void writeDescriptors(const std::vector<VkWriteDescriptorSet>& writes);
    void copyImageToBuffer(VkCommandBuffer cb, const HostImage& image, VkImageLayout layout, const HostBuffer& buffer);
    Status submit(VkCommandBuffer cb, VkFence fence);

    void destroy(HostImage& image);
    void destroy(HostBuffer& buffer);

    const HostCounts& counts() const { return counts_; }
    std::vector<std::string> takeMessages();  // the layer's messages since the last call

private:
    Status createInstance(bool validation);
    Status createDevice(bool wantSynchronization2);
    uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags want) const;
    Status allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags want, VkDeviceMemory* out);

    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::vector<std::string> messages_;
    HostCounts counts_;
};

// One image barrier: `from` -> `to` layout, with the stages and accesses on either side.
void imageBarrier(VkCommandBuffer cb, const HostImage& image, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                  VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);
// The same on any VkImage (the SDK's own motion blur output), on one array layer.
void imageBarrier(VkCommandBuffer cb, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                  VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess, uint32_t layer = 0);

}  // namespace sfx::engine
