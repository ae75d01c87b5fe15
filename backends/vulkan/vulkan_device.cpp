// The Vulkan backend of the HAL.
//
// Design, chosen for correctness over overlap:
// - One command buffer records everything between flushes; flush() submits it and waits.
// - Every command starts with a full memory barrier (all commands -> all commands) plus the
//   layout transitions its images need; each mip of each image tracks its own layout, so a pass
//   may render into mip i+1 while sampling mip i.
// - Buffers live in host-visible, coherent memory. Writes are recorded as copies from staging
//   buffers so that they stay ordered with the commands around them.
// - Vulkan functions come from a table loaded through vkGetInstanceProcAddr: the loader is opened
//   at run time (own device) or the host's entry point is used (wrapped device).
#include "sfx/vulkan_device.hpp"

#include <dlfcn.h>

#include <spirv-tools/libspirv.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "sfx/hal_validation.hpp"

namespace sfx::vulkan {
namespace {

// ---- Function table ----------------------------------------------------------------------

#define SFX_VK_INSTANCE_FUNCTIONS(X)            \
    X(vkDestroyInstance)                        \
    X(vkEnumeratePhysicalDevices)               \
    X(vkGetPhysicalDeviceProperties)            \
    X(vkGetPhysicalDeviceFeatures)              \
    X(vkGetPhysicalDeviceFeatures2)             \
    X(vkGetPhysicalDeviceQueueFamilyProperties) \
    X(vkGetPhysicalDeviceMemoryProperties)      \
    X(vkGetPhysicalDeviceFormatProperties)      \
    X(vkEnumerateDeviceExtensionProperties)     \
    X(vkCreateDevice)                           \
    X(vkGetDeviceProcAddr)

#define SFX_VK_DEVICE_FUNCTIONS(X)      \
    X(vkDestroyDevice)                  \
    X(vkGetDeviceQueue)                 \
    X(vkDeviceWaitIdle)                 \
    X(vkQueueWaitIdle)                  \
    X(vkQueueSubmit)                    \
    X(vkCreateFence)                    \
    X(vkDestroyFence)                   \
    X(vkWaitForFences)                  \
    X(vkResetFences)                    \
    X(vkCreateCommandPool)              \
    X(vkDestroyCommandPool)             \
    X(vkAllocateCommandBuffers)         \
    X(vkBeginCommandBuffer)             \
    X(vkEndCommandBuffer)               \
    X(vkResetCommandBuffer)             \
    X(vkAllocateMemory)                 \
    X(vkFreeMemory)                     \
    X(vkMapMemory)                      \
    X(vkUnmapMemory)                    \
    X(vkCreateBuffer)                   \
    X(vkDestroyBuffer)                  \
    X(vkGetBufferMemoryRequirements)    \
    X(vkBindBufferMemory)               \
    X(vkCreateImage)                    \
    X(vkDestroyImage)                   \
    X(vkGetImageMemoryRequirements)     \
    X(vkBindImageMemory)                \
    X(vkCreateImageView)                \
    X(vkDestroyImageView)               \
    X(vkCreateSampler)                  \
    X(vkDestroySampler)                 \
    X(vkCreateShaderModule)             \
    X(vkDestroyShaderModule)            \
    X(vkCreateDescriptorSetLayout)      \
    X(vkDestroyDescriptorSetLayout)     \
    X(vkCreatePipelineLayout)           \
    X(vkDestroyPipelineLayout)          \
    X(vkCreateGraphicsPipelines)        \
    X(vkCreateComputePipelines)         \
    X(vkDestroyPipeline)                \
    X(vkCreateDescriptorPool)           \
    X(vkDestroyDescriptorPool)          \
    X(vkResetDescriptorPool)            \
    X(vkAllocateDescriptorSets)         \
    X(vkUpdateDescriptorSets)           \
    X(vkCreateQueryPool)                \
    X(vkDestroyQueryPool)               \
    X(vkGetQueryPoolResults)            \
    X(vkCmdResetQueryPool)              \
    X(vkCmdWriteTimestamp)              \
    X(vkCmdPipelineBarrier)             \
    X(vkCmdCopyBuffer)                  \
    X(vkCmdCopyBufferToImage)           \
    X(vkCmdCopyImageToBuffer)           \
    X(vkCmdBindPipeline)                \
    X(vkCmdBindDescriptorSets)          \
    X(vkCmdBindVertexBuffers)           \
    X(vkCmdBindIndexBuffer)             \
    X(vkCmdSetViewport)                 \
    X(vkCmdSetScissor)                  \
    X(vkCmdDraw)                        \
    X(vkCmdDrawIndexed)                 \
    X(vkCmdDispatch)

struct Functions {
    PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr = nullptr;
    PFN_vkCreateInstance vkCreateInstance = nullptr;
    PFN_vkEnumerateInstanceLayerProperties vkEnumerateInstanceLayerProperties = nullptr;
    PFN_vkEnumerateInstanceVersion vkEnumerateInstanceVersion = nullptr;
#define SFX_DECLARE(name) PFN_##name name = nullptr;
    SFX_VK_INSTANCE_FUNCTIONS(SFX_DECLARE)
    SFX_VK_DEVICE_FUNCTIONS(SFX_DECLARE)
#undef SFX_DECLARE
    // Core in 1.3, or the KHR extension's entry points.
    PFN_vkCmdBeginRendering vkCmdBeginRendering = nullptr;
    PFN_vkCmdEndRendering vkCmdEndRendering = nullptr;
    // VK_EXT_debug_utils, when enabled.
    PFN_vkCreateDebugUtilsMessengerEXT vkCreateDebugUtilsMessengerEXT = nullptr;
    PFN_vkDestroyDebugUtilsMessengerEXT vkDestroyDebugUtilsMessengerEXT = nullptr;
    PFN_vkSetDebugUtilsObjectNameEXT vkSetDebugUtilsObjectNameEXT = nullptr;
};

template <class F>
bool loadInstanceFn(const Functions& f, VkInstance instance, const char* name, F* out) {
    *out = reinterpret_cast<F>(f.vkGetInstanceProcAddr(instance, name));
    return *out != nullptr;
}
template <class F>
bool loadDeviceFn(const Functions& f, VkDevice device, const char* name, F* out) {
    *out = reinterpret_cast<F>(f.vkGetDeviceProcAddr(device, name));
    return *out != nullptr;
}

Status loadInstanceFunctions(Functions& f, VkInstance instance) {
#define SFX_LOAD(name)                                       \
    if (!loadInstanceFn(f, instance, #name, &f.name))        \
        return {StatusCode::BackendUnavailable, "the Vulkan loader lacks " #name};
    SFX_VK_INSTANCE_FUNCTIONS(SFX_LOAD)
#undef SFX_LOAD
    return Status::ok();
}

Status loadDeviceFunctions(Functions& f, VkDevice device) {
#define SFX_LOAD(name)                                \
    if (!loadDeviceFn(f, device, #name, &f.name))     \
        return {StatusCode::BackendUnavailable, "the Vulkan device lacks " #name};
    SFX_VK_DEVICE_FUNCTIONS(SFX_LOAD)
#undef SFX_LOAD
    if (!loadDeviceFn(f, device, "vkCmdBeginRendering", &f.vkCmdBeginRendering))
        loadDeviceFn(f, device, "vkCmdBeginRenderingKHR", &f.vkCmdBeginRendering);
    if (!loadDeviceFn(f, device, "vkCmdEndRendering", &f.vkCmdEndRendering))
        loadDeviceFn(f, device, "vkCmdEndRenderingKHR", &f.vkCmdEndRendering);
    if (!f.vkCmdBeginRendering || !f.vkCmdEndRendering)
        return {StatusCode::BackendUnavailable, "the Vulkan device has no dynamic rendering (Vulkan 1.3 or VK_KHR_dynamic_rendering)"};
    return Status::ok();
}

std::string vkResultName(VkResult r) {
    switch (r) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_NOT_READY: return "VK_NOT_READY";
    case VK_TIMEOUT: return "VK_TIMEOUT";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_OUT_OF_POOL_MEMORY: return "VK_ERROR_OUT_OF_POOL_MEMORY";
    case VK_ERROR_INVALID_SHADER_NV: return "VK_ERROR_INVALID_SHADER_NV";
    default: return "VkResult " + std::to_string(int(r));
    }
}

Status vkError(const char* call, VkResult r) {
    return {StatusCode::DeviceError, std::string(call) + " failed: " + vkResultName(r)};
}

#define SFX_VK(call)                                           \
    do {                                                       \
        VkResult sfx_vk_result_ = (call);                      \
        if (sfx_vk_result_ != VK_SUCCESS) return vkError(#call, sfx_vk_result_); \
    } while (0)

// ---- Formats -------------------------------------------------------------------------------

VkFormat toVkFormat(Format f) {
    switch (f) {
    case Format::R8: return VK_FORMAT_R8_UNORM;
    case Format::RGBA8: return VK_FORMAT_R8G8B8A8_UNORM;
    case Format::R16F: return VK_FORMAT_R16_SFLOAT;
    case Format::RG16F: return VK_FORMAT_R16G16_SFLOAT;
    case Format::RGBA16F: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case Format::R32F: return VK_FORMAT_R32_SFLOAT;
    case Format::RG32F: return VK_FORMAT_R32G32_SFLOAT;
    case Format::RGBA32F: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case Format::R32UI: return VK_FORMAT_R32_UINT;
    case Format::D16: return VK_FORMAT_D16_UNORM;
    case Format::D24S8: return VK_FORMAT_D24_UNORM_S8_UINT;
    case Format::D32F: return VK_FORMAT_D32_SFLOAT;
    default: return VK_FORMAT_UNDEFINED;
    }
}

// The aspects an image of the format has (barriers cover all of them).
VkImageAspectFlags fullAspect(Format f) {
    if (f == Format::D24S8) return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    if (isDepthFormat(f)) return VK_IMAGE_ASPECT_DEPTH_BIT;
    return VK_IMAGE_ASPECT_COLOR_BIT;
}
// D24S8 texels between the HAL layout (depth in the high 24 bits, stencil in the low 8; see
// hal.hpp) and what a copy of Vulkan's depth aspect moves (X8_D24: depth in the low 24 bits,
// the high 8 undefined). Stencil is not copied: it is dropped on upload and reads as 0.
void d24s8ToVulkan(const void* hal, void* vk, size_t bytes) {
    for (size_t i = 0; i + 4 <= bytes; i += 4) {
        uint32_t v;
        std::memcpy(&v, static_cast<const uint8_t*>(hal) + i, 4);
        v >>= 8;
        std::memcpy(static_cast<uint8_t*>(vk) + i, &v, 4);
    }
}
void d24s8FromVulkan(const void* vk, void* hal, size_t bytes) {
    for (size_t i = 0; i + 4 <= bytes; i += 4) {
        uint32_t v;
        std::memcpy(&v, static_cast<const uint8_t*>(vk) + i, 4);
        v = (v & 0x00FFFFFFu) << 8;
        std::memcpy(static_cast<uint8_t*>(hal) + i, &v, 4);
    }
}

// What shaders sample, copies move and views see: depth only for depth formats.
VkImageAspectFlags dataAspect(Format f) {
    return isDepthFormat(f) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

VkCompareOp toVk(CompareOp op) {
    switch (op) {
    case CompareOp::Never: return VK_COMPARE_OP_NEVER;
    case CompareOp::Less: return VK_COMPARE_OP_LESS;
    case CompareOp::LessEqual: return VK_COMPARE_OP_LESS_OR_EQUAL;
    case CompareOp::Greater: return VK_COMPARE_OP_GREATER;
    case CompareOp::GreaterEqual: return VK_COMPARE_OP_GREATER_OR_EQUAL;
    case CompareOp::Equal: return VK_COMPARE_OP_EQUAL;
    case CompareOp::NotEqual: return VK_COMPARE_OP_NOT_EQUAL;
    case CompareOp::Always: return VK_COMPARE_OP_ALWAYS;
    }
    return VK_COMPARE_OP_ALWAYS;
}

VkBlendFactor toVk(BlendFactor f) {
    switch (f) {
    case BlendFactor::Zero: return VK_BLEND_FACTOR_ZERO;
    case BlendFactor::One: return VK_BLEND_FACTOR_ONE;
    case BlendFactor::SrcAlpha: return VK_BLEND_FACTOR_SRC_ALPHA;
    case BlendFactor::OneMinusSrcAlpha: return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    case BlendFactor::DstAlpha: return VK_BLEND_FACTOR_DST_ALPHA;
    case BlendFactor::OneMinusDstAlpha: return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
    }
    return VK_BLEND_FACTOR_ONE;
}

VkShaderStageFlags toVkStages(uint32_t stageMask) {
    VkShaderStageFlags s = 0;
    if (stageMask & stageBit(ShaderStage::Vertex)) s |= VK_SHADER_STAGE_VERTEX_BIT;
    if (stageMask & stageBit(ShaderStage::Fragment)) s |= VK_SHADER_STAGE_FRAGMENT_BIT;
    if (stageMask & stageBit(ShaderStage::Compute)) s |= VK_SHADER_STAGE_COMPUTE_BIT;
    return s;
}

VkDescriptorType toVkDescriptor(ResourceKind k) {
    switch (k) {
    case ResourceKind::UniformBuffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case ResourceKind::SampledTexture: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case ResourceKind::StorageBuffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case ResourceKind::StorageImage: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    }
    return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
}

// ---- Objects -------------------------------------------------------------------------------

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
    std::string name;
    bool compute = false;
    std::vector<ShaderResource> resources;
    std::vector<std::pair<ShaderStage, VkShaderModule>> modules;
};

struct VulkanPipeline {
    bool compute = false;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;  // own, so the program may go first
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    std::vector<ShaderResource> resources;
    std::string programName;
    std::vector<Format> colorFormats;
    Format depthFormat = Format::Undefined;
    bool usesVertexBuffer = false;
    VertexLayout vertexLayout;  // bounds the draws' vertex reads (validation::drawRange)
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

constexpr uint32_t kMaxTimers = 256;
constexpr uint32_t kDescriptorPoolSets = 256;

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void* user);

// What the loader and the instance were made with; shared by createDevice and wrapDevice.
struct InstanceSetup {
    Functions fns;
    void* loaderLibrary = nullptr;  // dlopen handle, own device only
    VkInstance instance = VK_NULL_HANDLE;
    bool ownsInstance = false;
    bool debugUtils = false;
};

class VulkanDevice final : public Device {
public:
    VulkanDevice() : serial_(nextDeviceSerial()), textures_(serial_, "texture"), buffers_(serial_, "buffer"),
                     samplers_(serial_, "sampler"), programs_(serial_, "program"), pipelines_(serial_, "pipeline"),
                     timers_(serial_, "timer") {}
    ~VulkanDevice() override {
        shutdown();
        // Messages nobody took (teardown ones included) can only be told on stderr now.
        for (const std::string& m : takeValidationMessages())
            std::fprintf(stderr, "sfx vulkan: untaken validation message at teardown: %s\n", m.c_str());
    }

    // Own instance and device.
    Status initOwn(const DeviceOptions& options);
    // Host objects.
    Status initWrapped(const ExternalVulkan& ext, const DeviceOptions& options);

    Status setHostCommandBuffer(VkCommandBuffer cb);

    const DeviceCaps& caps() const override { return caps_; }

    Result<TextureHandle> createTexture(const TextureDesc& desc) override;
    Status destroyTexture(TextureHandle texture) override;
    Result<TextureDesc> textureDesc(TextureHandle texture) const override {
        SFX_TRY(textures_.check(texture, "texture"));
        return textures_.get(texture).desc;
    }
    Status writeTexture(TextureHandle texture, uint32_t mip, const void* data, size_t bytes) override;
    Status readTexture(TextureHandle texture, uint32_t mip, void* out, size_t bytes) override;

    Result<BufferHandle> createBuffer(const BufferDesc& desc) override;
    Status destroyBuffer(BufferHandle buffer) override;
    Status writeBuffer(BufferHandle buffer, uint64_t offset, const void* data, size_t bytes) override;
    Status readBuffer(BufferHandle buffer, uint64_t offset, void* out, size_t bytes) override;

    Result<SamplerHandle> createSampler(const SamplerDesc& desc) override;
    Status destroySampler(SamplerHandle sampler) override;

    Result<ProgramHandle> createProgram(const CompiledProgram& program) override;
    Status destroyProgram(ProgramHandle program) override;

    Result<PipelineHandle> createGraphicsPipeline(const GraphicsPipelineDesc& desc) override;
    Result<PipelineHandle> createComputePipeline(const ComputePipelineDesc& desc) override;
    Status destroyPipeline(PipelineHandle pipeline) override;

    Result<TimerHandle> createTimer() override;
    Status destroyTimer(TimerHandle timer) override;

    Status renderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) override;
    Status dispatch(const DispatchDesc& dispatch) override;
    Status beginTimer(TimerHandle timer) override;
    Status endTimer(TimerHandle timer) override;
    Status flush() override;
    Result<TimerReading> readTimer(TimerHandle timer) override;

    std::vector<std::string> takeValidationMessages() override {
        std::lock_guard<std::mutex> lock(messagesMutex_);
        std::vector<std::string> out;
        out.swap(messages_);
        return out;
    }

    void addValidationMessage(std::string m) {
        std::lock_guard<std::mutex> lock(messagesMutex_);
        messages_.push_back(std::move(m));
    }

private:
    // A texture mip range that a command needs in a layout.
    struct ImageUse {
        VulkanTexture* texture;
        uint32_t baseMip, mipCount;
        VkImageLayout layout;
    };
    // A draw or dispatch with its resources resolved and checked, before anything is recorded.
    struct ResolvedBindings {
        std::vector<VkDescriptorImageInfo> images;   // stable storage for the writes
        std::vector<VkDescriptorBufferInfo> buffers;
        std::vector<VkWriteDescriptorSet> writes;
    };

    Status finishInit(const DeviceOptions& options, bool ownsDevice);
    void fillCaps(const DeviceOptions& options);
    void shutdown();

    void setName(VkObjectType type, uint64_t handle, const char* name);
    Result<Allocation> allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags want, bool map);
    Result<VkImageView> sampledView(VulkanTexture& t, uint32_t baseMip, uint32_t mipCount);
    Result<VkImageView> attachmentView(VulkanTexture& t, uint32_t mip);
    Result<VkImageView> storageView(VulkanTexture& t, uint32_t mip) { return sampledView(t, mip, 1); }
    Result<VulkanBuffer> makeBuffer(uint64_t size, VkBufferUsageFlags usage, const char* name);

    Result<VkCommandBuffer> recording();
    // A full barrier plus the layout transitions of `uses`.
    void barrier(VkCommandBuffer cb, const std::vector<ImageUse>& uses);
    Status resolveBindings(const BindingSet& set, const VulkanPipeline& pipeline, const char* what,
                           std::vector<ImageUse>& uses, ResolvedBindings& out);
    Result<VkDescriptorSet> allocateSet(VkDescriptorSetLayout layout);
    Status submitAndWait();
    void releaseGarbage(Garbage& g);
    void releaseIdleGarbage();
    void retire(VulkanTexture& t);
    void retire(VulkanBuffer& b, Garbage& g);
    void retire(VulkanPipeline& p);
    Status createLayouts(const std::vector<ShaderResource>& resources, bool compute, VulkanPipeline& out);
    Status noHostCommandBuffer(const char* call) const;

    DeviceCaps caps_;
    uint16_t serial_;
    HandlePool<TextureTag, VulkanTexture> textures_;
    HandlePool<BufferTag, VulkanBuffer> buffers_;
    HandlePool<SamplerTag, VkSampler> samplers_;
    HandlePool<ProgramTag, VulkanProgram> programs_;
    HandlePool<PipelineTag, VulkanPipeline> pipelines_;
    HandlePool<TimerTag, VulkanTimer> timers_;

public:  // set up by the factory functions
    InstanceSetup setup_;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    bool ownsDevice_ = false;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;

private:
    Functions& vk_ = setup_.fns;
    VkPhysicalDeviceProperties props_{};
    VkPhysicalDeviceMemoryProperties memProps_{};
    uint32_t timestampValidBits_ = 0;
    bool fullFeatures_ = true;  // no ceiling

    VkCommandPool commandPool_ = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    bool recording_ = false;               // own command buffer begun and holds commands
    VkCommandBuffer hostCommandBuffer_ = VK_NULL_HANDLE;
    VkSampler defaultSampler_ = VK_NULL_HANDLE;
    VkQueryPool queryPool_ = VK_NULL_HANDLE;
    std::vector<uint32_t> freeTimerSlots_;

    std::vector<VkDescriptorPool> descriptorPools_;
    size_t currentPool_ = 0;
    Garbage pending_;       // released after the next flush
    Garbage hostPending_;   // used by a host command buffer: released at the next setCommandBuffer
    std::chrono::steady_clock::time_point recordStart_{};

    std::mutex messagesMutex_;
    std::vector<std::string> messages_;
};

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* device = static_cast<VulkanDevice*>(user);
    const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    std::string text = std::string("vulkan ") + level + ": " + (data && data->pMessage ? data->pMessage : "(no text)");
    if (device) device->addValidationMessage(std::move(text));
    return VK_FALSE;  // never abort the call
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(void* user) {
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = debugCallback;
    info.pUserData = user;
    return info;
}

// ---- Initialisation ------------------------------------------------------------------------

Status VulkanDevice::initOwn(const DeviceOptions& options) {
    // The loader is opened here rather than linked, so its absence is a status, not a crash.
    void* lib = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!lib) lib = dlopen("libvulkan.so", RTLD_NOW | RTLD_LOCAL);
    if (!lib)
        return {StatusCode::BackendUnavailable,
                std::string("the Vulkan loader (libvulkan.so.1, package libvulkan1) could not be opened: ") + dlerror()};
    setup_.loaderLibrary = lib;
    vk_.vkGetInstanceProcAddr = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(lib, "vkGetInstanceProcAddr"));
    if (!vk_.vkGetInstanceProcAddr) return {StatusCode::BackendUnavailable, "the Vulkan loader has no vkGetInstanceProcAddr"};
    loadInstanceFn(vk_, VK_NULL_HANDLE, "vkCreateInstance", &vk_.vkCreateInstance);
    loadInstanceFn(vk_, VK_NULL_HANDLE, "vkEnumerateInstanceLayerProperties", &vk_.vkEnumerateInstanceLayerProperties);
    loadInstanceFn(vk_, VK_NULL_HANDLE, "vkEnumerateInstanceVersion", &vk_.vkEnumerateInstanceVersion);
    if (!vk_.vkCreateInstance || !vk_.vkEnumerateInstanceLayerProperties)
        return {StatusCode::BackendUnavailable, "the Vulkan loader lacks vkCreateInstance"};
    uint32_t instanceVersion = VK_API_VERSION_1_0;
    if (vk_.vkEnumerateInstanceVersion) vk_.vkEnumerateInstanceVersion(&instanceVersion);
    if (instanceVersion < VK_API_VERSION_1_1)
        return {StatusCode::BackendUnavailable, "the Vulkan loader supports only Vulkan 1.0; 1.1 or later is needed"};

    std::vector<const char*> layers, extensions;
    if (options.validation) {
        uint32_t count = 0;
        vk_.vkEnumerateInstanceLayerProperties(&count, nullptr);
        std::vector<VkLayerProperties> available(count);
        vk_.vkEnumerateInstanceLayerProperties(&count, available.data());
        bool found = false;
        for (const auto& l : available) found |= std::strcmp(l.layerName, "VK_LAYER_KHRONOS_validation") == 0;
        if (!found)
            return {StatusCode::BackendUnavailable,
                    "DeviceOptions.validation asks for VK_LAYER_KHRONOS_validation, which is not installed "
                    "(Debian/Ubuntu package vulkan-validationlayers)"};
        layers.push_back("VK_LAYER_KHRONOS_validation");
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "ScalableFX";
    app.pEngineName = "ScalableFX";
    app.apiVersion = instanceVersion >= VK_API_VERSION_1_3 ? VK_API_VERSION_1_3 : instanceVersion;
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    ci.enabledLayerCount = uint32_t(layers.size());
    ci.ppEnabledLayerNames = layers.data();
    ci.enabledExtensionCount = uint32_t(extensions.size());
    ci.ppEnabledExtensionNames = extensions.data();
    // Chained so that messages of vkCreateInstance / vkDestroyInstance are caught as well.
    VkDebugUtilsMessengerCreateInfoEXT dbg = messengerInfo(this);
    if (options.validation) ci.pNext = &dbg;
    VkResult r = vk_.vkCreateInstance(&ci, nullptr, &setup_.instance);
    if (r != VK_SUCCESS)
        return {StatusCode::BackendUnavailable, "vkCreateInstance failed (" + vkResultName(r) +
                                                    "): no usable Vulkan driver (ICD) on this machine"};
    setup_.ownsInstance = true;
    setup_.debugUtils = options.validation;
    SFX_TRY(loadInstanceFunctions(vk_, setup_.instance));

    // Physical device: needs a graphics+compute queue and dynamic rendering; discrete first.
    uint32_t count = 0;
    vk_.vkEnumeratePhysicalDevices(setup_.instance, &count, nullptr);
    std::vector<VkPhysicalDevice> gpus(count);
    vk_.vkEnumeratePhysicalDevices(setup_.instance, &count, gpus.data());
    if (gpus.empty()) return {StatusCode::BackendUnavailable, "Vulkan reports no physical device (no ICD installed?)"};
    int bestScore = -1;
    bool bestNeedsKhr = false;
    std::string rejected;
    for (VkPhysicalDevice gpu : gpus) {
        VkPhysicalDeviceProperties p;
        vk_.vkGetPhysicalDeviceProperties(gpu, &p);
        uint32_t extCount = 0;
        vk_.vkEnumerateDeviceExtensionProperties(gpu, nullptr, &extCount, nullptr);
        std::vector<VkExtensionProperties> exts(extCount);
        vk_.vkEnumerateDeviceExtensionProperties(gpu, nullptr, &extCount, exts.data());
        bool khrDynamic = false;
        for (const auto& e : exts) khrDynamic |= std::strcmp(e.extensionName, VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME) == 0;
        const bool core13 = p.apiVersion >= VK_API_VERSION_1_3 && app.apiVersion >= VK_API_VERSION_1_3;
        if (!core13 && !(khrDynamic && p.apiVersion >= VK_API_VERSION_1_1)) {
            rejected += std::string(" ") + p.deviceName + " (no dynamic rendering);";
            continue;
        }
        uint32_t qCount = 0;
        vk_.vkGetPhysicalDeviceQueueFamilyProperties(gpu, &qCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(qCount);
        vk_.vkGetPhysicalDeviceQueueFamilyProperties(gpu, &qCount, families.data());
        int family = -1;
        for (uint32_t i = 0; i < qCount; ++i)
            if ((families[i].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
                (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) {
                family = int(i);
                break;
            }
        if (family < 0) {
            rejected += std::string(" ") + p.deviceName + " (no graphics+compute queue);";
            continue;
        }
        int score = p.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU     ? 4
                    : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ? 3
                    : p.deviceType == VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU    ? 2
                                                                             : 1;
        if (score > bestScore) {
            bestScore = score;
            physical_ = gpu;
            queueFamily_ = uint32_t(family);
            bestNeedsKhr = !core13;
        }
    }
    if (!physical_) return {StatusCode::BackendUnavailable, "no Vulkan device is usable:" + rejected};

    // Features: dynamic rendering always; stores and atomics outside compute when present.
    VkPhysicalDeviceFeatures supported{};
    vk_.vkGetPhysicalDeviceFeatures(physical_, &supported);
    VkPhysicalDeviceFeatures enabled{};
    enabled.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
    enabled.vertexPipelineStoresAndAtomics = supported.vertexPipelineStoresAndAtomics;
    enabled.shaderStorageImageWriteWithoutFormat = supported.shaderStorageImageWriteWithoutFormat;
    enabled.shaderStorageImageReadWithoutFormat = supported.shaderStorageImageReadWithoutFormat;
    // Index values are not checked on the host (the index buffer lives on the device); with
    // robust access an out-of-range index reads zeros instead of memory past the vertex buffer.
    enabled.robustBufferAccess = supported.robustBufferAccess;
    VkPhysicalDeviceDynamicRenderingFeatures dynamic{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES};
    dynamic.dynamicRendering = VK_TRUE;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = queueFamily_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    std::vector<const char*> deviceExtensions;
    if (bestNeedsKhr) deviceExtensions.push_back(VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME);
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.pNext = &dynamic;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    dci.pEnabledFeatures = &enabled;
    dci.enabledExtensionCount = uint32_t(deviceExtensions.size());
    dci.ppEnabledExtensionNames = deviceExtensions.data();
    r = vk_.vkCreateDevice(physical_, &dci, nullptr, &device_);
    if (r != VK_SUCCESS) return {StatusCode::BackendUnavailable, "vkCreateDevice failed: " + vkResultName(r)};
    ownsDevice_ = true;
    SFX_TRY(loadDeviceFunctions(vk_, device_));
    vk_.vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    return finishInit(options, true);
}

Status VulkanDevice::initWrapped(const ExternalVulkan& ext, const DeviceOptions& options) {
    if (!ext.getInstanceProcAddr) return invalidArgument("ExternalVulkan.getInstanceProcAddr", "null", "the host's vkGetInstanceProcAddr");
    if (!ext.instance) return invalidArgument("ExternalVulkan.instance", "VK_NULL_HANDLE", "the host's VkInstance");
    if (!ext.physicalDevice) return invalidArgument("ExternalVulkan.physicalDevice", "VK_NULL_HANDLE", "the host's VkPhysicalDevice");
    if (!ext.device) return invalidArgument("ExternalVulkan.device", "VK_NULL_HANDLE", "the host's VkDevice");
    if (!ext.queue) return invalidArgument("ExternalVulkan.queue", "VK_NULL_HANDLE", "a queue of the host's device");
    vk_.vkGetInstanceProcAddr = ext.getInstanceProcAddr;
    setup_.instance = ext.instance;
    setup_.ownsInstance = false;
    SFX_TRY(loadInstanceFunctions(vk_, setup_.instance));
    physical_ = ext.physicalDevice;
    device_ = ext.device;
    queue_ = ext.queue;
    queueFamily_ = ext.queueFamily;
    ownsDevice_ = false;
    uint32_t qCount = 0;
    vk_.vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qCount, nullptr);
    if (queueFamily_ >= qCount)
        return invalidArgument("ExternalVulkan.queueFamily", std::to_string(queueFamily_), "[0, " + std::to_string(qCount) + ")");
    SFX_TRY(loadDeviceFunctions(vk_, device_));
    setup_.debugUtils = ext.debugUtilsEnabled;
    return finishInit(options, false);
}

Status VulkanDevice::finishInit(const DeviceOptions& options, bool) {
    if (setup_.debugUtils) {
        loadInstanceFn(vk_, setup_.instance, "vkCreateDebugUtilsMessengerEXT", &vk_.vkCreateDebugUtilsMessengerEXT);
        loadInstanceFn(vk_, setup_.instance, "vkDestroyDebugUtilsMessengerEXT", &vk_.vkDestroyDebugUtilsMessengerEXT);
        loadInstanceFn(vk_, setup_.instance, "vkSetDebugUtilsObjectNameEXT", &vk_.vkSetDebugUtilsObjectNameEXT);
        if (options.validation && vk_.vkCreateDebugUtilsMessengerEXT) {
            VkDebugUtilsMessengerCreateInfoEXT info = messengerInfo(this);
            SFX_VK(vk_.vkCreateDebugUtilsMessengerEXT(setup_.instance, &info, nullptr, &messenger_));
        }
    }
    vk_.vkGetPhysicalDeviceProperties(physical_, &props_);
    vk_.vkGetPhysicalDeviceMemoryProperties(physical_, &memProps_);
    uint32_t qCount = 0;
    vk_.vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(qCount);
    vk_.vkGetPhysicalDeviceQueueFamilyProperties(physical_, &qCount, families.data());
    timestampValidBits_ = families[queueFamily_].timestampValidBits;
    fullFeatures_ = options.ceiling == CapabilityCeiling::None;
    fillCaps(options);

    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pci.queueFamilyIndex = queueFamily_;
    SFX_VK(vk_.vkCreateCommandPool(device_, &pci, nullptr, &commandPool_));
    VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cai.commandPool = commandPool_;
    cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cai.commandBufferCount = 1;
    SFX_VK(vk_.vkAllocateCommandBuffers(device_, &cai, &commandBuffer_));
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    SFX_VK(vk_.vkCreateFence(device_, &fci, nullptr, &fence_));

    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
    sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sci.maxLod = VK_LOD_CLAMP_NONE;
    SFX_VK(vk_.vkCreateSampler(device_, &sci, nullptr, &defaultSampler_));

    if (timestampValidBits_ > 0) {
        VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
        qci.queryCount = kMaxTimers * 2;
        SFX_VK(vk_.vkCreateQueryPool(device_, &qci, nullptr, &queryPool_));
    }
    for (uint32_t i = kMaxTimers; i > 0; --i) freeTimerSlots_.push_back(i - 1);
    return Status::ok();
}

void VulkanDevice::fillCaps(const DeviceOptions& options) {
    DeviceCaps& c = caps_;
    c.backend = BackendKind::Vulkan;
    c.platform = "vulkan-loader";
    c.apiMajor = VK_API_VERSION_MAJOR(props_.apiVersion);
    c.apiMinor = VK_API_VERSION_MINOR(props_.apiVersion);
    c.apiName = "Vulkan " + std::to_string(c.apiMajor) + "." + std::to_string(c.apiMinor) + "." +
                std::to_string(VK_API_VERSION_PATCH(props_.apiVersion));
    c.deviceName = props_.deviceName;
    c.dialect = ShaderDialect::Spirv;
    c.ceiling = options.ceiling;
    c.computeShaders = fullFeatures_;
    c.storageBuffers = fullFeatures_;
    c.atomics = fullFeatures_;
    c.storageImages = fullFeatures_;
    c.timing = timestampValidBits_ > 0 ? TimingSource::GpuTimestamps : TimingSource::WallClockAfterFinish;
    c.clipDepth = ClipDepthRange::ZeroToOne;
    c.origin = FramebufferOrigin::UpperLeft;

    const VkPhysicalDeviceLimits& l = props_.limits;
    c.limits.maxTextureSize = l.maxImageDimension2D;
    c.limits.maxColorAttachments = std::min<uint32_t>(l.maxColorAttachments, 8);
    c.limits.maxUniformBlockSize = l.maxUniformBufferRange;
    c.limits.maxStorageBufferSize = fullFeatures_ ? l.maxStorageBufferRange : 0;
    // Buffers are one allocation each; keep them well inside what any heap offers.
    uint64_t largestHeap = 0;
    for (uint32_t i = 0; i < memProps_.memoryHeapCount; ++i) largestHeap = std::max(largestHeap, memProps_.memoryHeaps[i].size);
    c.limits.maxBufferSize = std::min<uint64_t>(uint64_t(1) << 30, largestHeap / 4);
    c.limits.maxComputeWorkGroupInvocations = fullFeatures_ ? l.maxComputeWorkGroupInvocations : 0;
    c.limits.maxTextureBindings = std::min<uint32_t>(l.maxPerStageDescriptorSampledImages, 64);

    for (size_t i = 1; i < size_t(Format::Count); ++i) {
        const Format f = Format(i);
        VkFormatProperties fp{};
        vk_.vkGetPhysicalDeviceFormatProperties(physical_, toVkFormat(f), &fp);
        const VkFormatFeatureFlags feats = fp.optimalTilingFeatures;
        const bool transfers = (feats & VK_FORMAT_FEATURE_TRANSFER_SRC_BIT) && (feats & VK_FORMAT_FEATURE_TRANSFER_DST_BIT);
        c.sampledFormat[i] = transfers && (feats & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT);
        c.renderableFormat[i] =
            transfers && (feats & (isDepthFormat(f) ? VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT
                                                    : VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT));
        if (f == Format::R32F)
            c.float32Filterable = (feats & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
    }
    c.floatRenderTargets = c.renderableFormat[size_t(Format::R32F)] && c.renderableFormat[size_t(Format::RG16F)] &&
                           c.renderableFormat[size_t(Format::RGBA16F)];
}

void VulkanDevice::shutdown() {
    if (device_) {
        hostCommandBuffer_ = VK_NULL_HANDLE;
        // The host owns its queue's other work; waiting on our queue is enough for our objects.
        if (recording_) {
            vk_.vkEndCommandBuffer(commandBuffer_);
            recording_ = false;
        }
        if (ownsDevice_) vk_.vkDeviceWaitIdle(device_);
        else vk_.vkQueueWaitIdle(queue_);
        releaseGarbage(pending_);
        releaseGarbage(hostPending_);
        textures_.forEachAlive([&](VulkanTexture& t) { retire(t); });
        buffers_.forEachAlive([&](VulkanBuffer& b) { retire(b, pending_); });
        samplers_.forEachAlive([&](VkSampler& s) { pending_.samplers.push_back(s); });
        pipelines_.forEachAlive([&](VulkanPipeline& p) { retire(p); });
        programs_.forEachAlive([&](VulkanProgram& p) {
            for (auto& m : p.modules) pending_.modules.push_back(m.second);
        });
        releaseGarbage(pending_);
        for (VkDescriptorPool p : descriptorPools_) vk_.vkDestroyDescriptorPool(device_, p, nullptr);
        descriptorPools_.clear();
        if (queryPool_) vk_.vkDestroyQueryPool(device_, queryPool_, nullptr);
        if (defaultSampler_) vk_.vkDestroySampler(device_, defaultSampler_, nullptr);
        if (fence_) vk_.vkDestroyFence(device_, fence_, nullptr);
        if (commandPool_) vk_.vkDestroyCommandPool(device_, commandPool_, nullptr);
        if (ownsDevice_) vk_.vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
    }
    if (messenger_ && vk_.vkDestroyDebugUtilsMessengerEXT)
        vk_.vkDestroyDebugUtilsMessengerEXT(setup_.instance, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
    if (setup_.ownsInstance && setup_.instance) vk_.vkDestroyInstance(setup_.instance, nullptr);
    setup_.instance = VK_NULL_HANDLE;
    if (setup_.loaderLibrary) dlclose(setup_.loaderLibrary);
    setup_.loaderLibrary = nullptr;
}

// ---- Helpers -------------------------------------------------------------------------------

void VulkanDevice::setName(VkObjectType type, uint64_t handle, const char* name) {
    if (!vk_.vkSetDebugUtilsObjectNameEXT || !name || !*name) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name;
    vk_.vkSetDebugUtilsObjectNameEXT(device_, &info);
}

Result<Allocation> VulkanDevice::allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags want, bool map) {
    int type = -1;
    for (uint32_t i = 0; i < memProps_.memoryTypeCount && type < 0; ++i)
        if ((req.memoryTypeBits & (1u << i)) && (memProps_.memoryTypes[i].propertyFlags & want) == want) type = int(i);
    if (type < 0)
        return Status{StatusCode::DeviceError, "no Vulkan memory type has the properties " + std::to_string(want)};
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = uint32_t(type);
    Allocation a;
    SFX_VK(vk_.vkAllocateMemory(device_, &ai, nullptr, &a.memory));
    if (map) {
        VkResult r = vk_.vkMapMemory(device_, a.memory, 0, VK_WHOLE_SIZE, 0, &a.mapped);
        if (r != VK_SUCCESS) {
            vk_.vkFreeMemory(device_, a.memory, nullptr);
            return vkError("vkMapMemory", r);
        }
    }
    return a;
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
        vk_.vkFreeMemory(device_, b.alloc.memory, nullptr);
        return vkError("vkBindBufferMemory", r);
    }
    setName(VK_OBJECT_TYPE_BUFFER, uint64_t(b.buffer), name);
    return b;
}

Result<VkImageView> VulkanDevice::sampledView(VulkanTexture& t, uint32_t baseMip, uint32_t mipCount) {
    auto key = std::make_pair(baseMip, mipCount);
    auto it = t.views.find(key);
    if (it != t.views.end()) return it->second;
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = t.image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = t.format;
    vci.subresourceRange = {dataAspect(t.desc.format), baseMip, mipCount, 0, 1};
    VkImageView view;
    SFX_VK(vk_.vkCreateImageView(device_, &vci, nullptr, &view));
    t.views[key] = view;
    return view;
}

Result<VkImageView> VulkanDevice::attachmentView(VulkanTexture& t, uint32_t mip) {
    if (t.attachmentViews[mip]) return t.attachmentViews[mip];
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = t.image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = t.format;
    vci.subresourceRange = {fullAspect(t.desc.format), mip, 1, 0, 1};
    SFX_VK(vk_.vkCreateImageView(device_, &vci, nullptr, &t.attachmentViews[mip]));
    return t.attachmentViews[mip];
}

Status VulkanDevice::noHostCommandBuffer(const char* call) const {
    if (hostCommandBuffer_)
        return {StatusCode::UnsupportedFeature,
                std::string(call) + " needs a submit, but the device records into a host command buffer; "
                                    "submit it, call flush(), then read"};
    return Status::ok();
}

Result<VkCommandBuffer> VulkanDevice::recording() {
    if (hostCommandBuffer_) return hostCommandBuffer_;
    if (!recording_) {
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        SFX_VK(vk_.vkBeginCommandBuffer(commandBuffer_, &bi));
        recording_ = true;
        recordStart_ = std::chrono::steady_clock::now();
    }
    return commandBuffer_;
}

void VulkanDevice::barrier(VkCommandBuffer cb, const std::vector<ImageUse>& uses) {
    // Everything before against everything after: simple and always correct.
    VkMemoryBarrier global{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    global.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
    global.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    std::vector<VkImageMemoryBarrier> images;
    for (const ImageUse& u : uses) {
        for (uint32_t m = u.baseMip; m < u.baseMip + u.mipCount; ++m) {
            if (u.texture->layouts[m] == u.layout) continue;
            VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
            b.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
            b.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
            b.oldLayout = u.texture->layouts[m];
            b.newLayout = u.layout;
            b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            b.image = u.texture->image;
            b.subresourceRange = {fullAspect(u.texture->desc.format), m, 1, 0, 1};
            images.push_back(b);
            u.texture->layouts[m] = u.layout;
        }
    }
    vk_.vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &global, 0,
                             nullptr, uint32_t(images.size()), images.data());
}

Result<VkDescriptorSet> VulkanDevice::allocateSet(VkDescriptorSetLayout layout) {
    for (;;) {
        const bool fresh = currentPool_ == descriptorPools_.size();
        if (fresh) {
            const VkDescriptorPoolSize sizes[] = {
                {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kDescriptorPoolSets * 4},
                {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kDescriptorPoolSets * 8},
                {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kDescriptorPoolSets * 4},
                {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kDescriptorPoolSets * 2},
            };
            VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
            pci.maxSets = kDescriptorPoolSets;
            pci.poolSizeCount = 4;
            pci.pPoolSizes = sizes;
            VkDescriptorPool pool;
            SFX_VK(vk_.vkCreateDescriptorPool(device_, &pci, nullptr, &pool));
            descriptorPools_.push_back(pool);
        }
        VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        ai.descriptorPool = descriptorPools_[currentPool_];
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &layout;
        VkDescriptorSet set;
        VkResult r = vk_.vkAllocateDescriptorSets(device_, &ai, &set);
        if (r == VK_SUCCESS) return set;
        // A new pool that cannot hold one set never will: stop rather than loop.
        if (fresh || (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL))
            return vkError("vkAllocateDescriptorSets", r);
        ++currentPool_;  // full: move on to the next (or a new) pool
    }
}

void VulkanDevice::retire(VulkanTexture& t) {
    Garbage& g = hostCommandBuffer_ ? hostPending_ : pending_;
    for (auto& v : t.views) g.views.push_back(v.second);
    for (VkImageView v : t.attachmentViews)
        if (v) g.views.push_back(v);
    g.images.push_back(t.image);
    g.memories.push_back(t.memory);
    t = VulkanTexture{};
}

void VulkanDevice::retire(VulkanBuffer& b, Garbage& g) {
    g.buffers.push_back(b.buffer);
    g.memories.push_back(b.alloc.memory);  // freeing unmaps
    b = VulkanBuffer{};
}

void VulkanDevice::releaseGarbage(Garbage& g) {
    for (VkPipeline p : g.pipelines) vk_.vkDestroyPipeline(device_, p, nullptr);
    for (VkPipelineLayout p : g.pipelineLayouts) vk_.vkDestroyPipelineLayout(device_, p, nullptr);
    for (VkDescriptorSetLayout s : g.setLayouts) vk_.vkDestroyDescriptorSetLayout(device_, s, nullptr);
    for (VkShaderModule m : g.modules) vk_.vkDestroyShaderModule(device_, m, nullptr);
    for (VkImageView v : g.views) vk_.vkDestroyImageView(device_, v, nullptr);
    for (VkImage i : g.images) vk_.vkDestroyImage(device_, i, nullptr);
    for (VkBuffer b : g.buffers) vk_.vkDestroyBuffer(device_, b, nullptr);
    for (VkDeviceMemory m : g.memories) vk_.vkFreeMemory(device_, m, nullptr);
    for (VkSampler s : g.samplers) vk_.vkDestroySampler(device_, s, nullptr);
    for (VkDescriptorPool p : g.descriptorPools) vk_.vkDestroyDescriptorPool(device_, p, nullptr);
    g = Garbage{};
}

Status VulkanDevice::submitAndWait() {
    if (!recording_) return Status::ok();
    recording_ = false;
    SFX_VK(vk_.vkEndCommandBuffer(commandBuffer_));
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &commandBuffer_;
    SFX_VK(vk_.vkQueueSubmit(queue_, 1, &si, fence_));
    SFX_VK(vk_.vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
    const double wallMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - recordStart_).count();
    SFX_VK(vk_.vkResetFences(device_, 1, &fence_));
    SFX_VK(vk_.vkResetCommandBuffer(commandBuffer_, 0));
    for (VkDescriptorPool p : descriptorPools_) vk_.vkResetDescriptorPool(device_, p, 0);
    currentPool_ = 0;
    releaseGarbage(pending_);
    timers_.forEachAlive([&](VulkanTimer& t) {
        if (t.state == VulkanTimer::State::Ended) {
            t.state = VulkanTimer::State::Flushed;
            t.wallMs = wallMs;
            t.hostRecorded = false;
        }
    });
    return Status::ok();
}

// ---- Textures ------------------------------------------------------------------------------

Result<TextureHandle> VulkanDevice::createTexture(const TextureDesc& desc) {
    SFX_TRY(validation::textureDesc(desc, caps_));
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
    VkResult r = vk_.vkBindImageMemory(device_, t.image, t.memory, 0);
    if (r != VK_SUCCESS) {
        vk_.vkDestroyImage(device_, t.image, nullptr);
        vk_.vkFreeMemory(device_, t.memory, nullptr);
        return vkError("vkBindImageMemory", r);
    }
    setName(VK_OBJECT_TYPE_IMAGE, uint64_t(t.image), desc.debugName);
    t.layouts.assign(desc.mipLevels, VK_IMAGE_LAYOUT_UNDEFINED);
    t.attachmentViews.assign(desc.mipLevels, VK_NULL_HANDLE);
    return textures_.insert(std::move(t));
}

// Destroyed objects wait in pending_ until the commands recorded with them have run; with
// nothing recording (and no host command buffer) that is now.
void VulkanDevice::releaseIdleGarbage() {
    if (!recording_ && !hostCommandBuffer_) releaseGarbage(pending_);
}

Status VulkanDevice::destroyTexture(TextureHandle h) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture t = textures_.remove(h);
    retire(t);
    releaseIdleGarbage();
    return Status::ok();
}

Status VulkanDevice::writeTexture(TextureHandle h, uint32_t mip, const void* data, size_t bytes) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture& t = textures_.get(h);
    SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
    if (!data) return invalidArgument("data", "null", "a pointer to the level's bytes");
    Result<VulkanBuffer> staging = makeBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "sfx staging (writeTexture)");
    if (!staging) return staging.status();
    // The HAL's D24S8 bytes put depth high; Vulkan's depth-aspect copy wants it low.
    if (t.desc.format == Format::D24S8)
        d24s8ToVulkan(data, staging->alloc.mapped, bytes);
    else
        std::memcpy(staging->alloc.mapped, data, bytes);
    Result<VkCommandBuffer> cb = recording();
    if (!cb) {
        retire(staging.value(), pending_);
        return cb.status();
    }
    barrier(cb.value(), {ImageUse{&t, mip, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL}});
    VkBufferImageCopy region{};
    region.imageSubresource = {dataAspect(t.desc.format), mip, 0, 1};
    region.imageExtent = {mipExtent(t.desc.width, mip), mipExtent(t.desc.height, mip), 1};
    vk_.vkCmdCopyBufferToImage(cb.value(), staging->buffer, t.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    retire(staging.value(), hostCommandBuffer_ ? hostPending_ : pending_);
    return Status::ok();
}

Status VulkanDevice::readTexture(TextureHandle h, uint32_t mip, void* out, size_t bytes) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture& t = textures_.get(h);
    SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
    if (!out) return invalidArgument("out", "null", "a pointer to the level's bytes");
    SFX_TRY(noHostCommandBuffer("readTexture"));
    Result<VulkanBuffer> staging = makeBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "sfx staging (readTexture)");
    if (!staging) return staging.status();
    VulkanBuffer readback = staging.value();
    Result<VkCommandBuffer> cb = recording();
    if (!cb) {
        retire(readback, pending_);
        return cb.status();
    }
    barrier(cb.value(), {ImageUse{&t, mip, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL}});
    VkBufferImageCopy region{};
    region.imageSubresource = {dataAspect(t.desc.format), mip, 0, 1};
    region.imageExtent = {mipExtent(t.desc.width, mip), mipExtent(t.desc.height, mip), 1};
    vk_.vkCmdCopyImageToBuffer(cb.value(), t.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
    // Makes the copy visible to the host read below.
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vk_.vkCmdPipelineBarrier(cb.value(), VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0,
                             nullptr, 0, nullptr);
    Status s = submitAndWait();
    if (s && t.desc.format == Format::D24S8)
        d24s8FromVulkan(readback.alloc.mapped, out, bytes);
    else if (s)
        std::memcpy(out, readback.alloc.mapped, bytes);
    retire(readback, pending_);
    releaseGarbage(pending_);
    return s;
}

// ---- Buffers -------------------------------------------------------------------------------

Result<BufferHandle> VulkanDevice::createBuffer(const BufferDesc& desc) {
    SFX_TRY(validation::bufferDesc(desc, caps_));
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

Status VulkanDevice::destroyBuffer(BufferHandle h) {
    SFX_TRY(buffers_.check(h, "buffer"));
    VulkanBuffer b = buffers_.remove(h);
    retire(b, hostCommandBuffer_ ? hostPending_ : pending_);
    releaseIdleGarbage();
    return Status::ok();
}

Status VulkanDevice::writeBuffer(BufferHandle h, uint64_t offset, const void* data, size_t bytes) {
    SFX_TRY(buffers_.check(h, "buffer"));
    VulkanBuffer& b = buffers_.get(h);
    SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "writeBuffer range"));
    if (!data) return invalidArgument("data", "null", "a pointer to the bytes to write");
    if (!recording_ && !hostCommandBuffer_) {
        // Nothing recorded and the GPU idle since the last flush: the mapping can take it now.
        std::memcpy(static_cast<uint8_t*>(b.alloc.mapped) + offset, data, bytes);
        return Status::ok();
    }
    // Recorded commands may still read the old contents: copy in order with them.
    Result<VulkanBuffer> staging = makeBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "sfx staging (writeBuffer)");
    if (!staging) return staging.status();
    std::memcpy(staging->alloc.mapped, data, bytes);
    Result<VkCommandBuffer> cb = recording();
    if (!cb) {
        retire(staging.value(), pending_);
        return cb.status();
    }
    barrier(cb.value(), {});
    VkBufferCopy region{0, offset, bytes};
    vk_.vkCmdCopyBuffer(cb.value(), staging->buffer, b.buffer, 1, &region);
    retire(staging.value(), hostCommandBuffer_ ? hostPending_ : pending_);
    return Status::ok();
}

Status VulkanDevice::readBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) {
    SFX_TRY(buffers_.check(h, "buffer"));
    VulkanBuffer& b = buffers_.get(h);
    SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "readBuffer range"));
    if (!out) return invalidArgument("out", "null", "a pointer for the bytes read");
    SFX_TRY(noHostCommandBuffer("readBuffer"));
    if (recording_) {
        Result<VkCommandBuffer> cb = recording();
        if (!cb) return cb.status();
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vk_.vkCmdPipelineBarrier(cb.value(), VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost,
                                 0, nullptr, 0, nullptr);
        SFX_TRY(submitAndWait());
    }
    std::memcpy(out, static_cast<const uint8_t*>(b.alloc.mapped) + offset, bytes);
    return Status::ok();
}

// ---- Samplers ------------------------------------------------------------------------------

Result<SamplerHandle> VulkanDevice::createSampler(const SamplerDesc& desc) {
    SFX_TRY(validation::samplerDesc(desc));
    auto filter = [](Filter f) { return f == Filter::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST; };
    const VkSamplerAddressMode address = desc.address == AddressMode::Repeat           ? VK_SAMPLER_ADDRESS_MODE_REPEAT
                                         : desc.address == AddressMode::MirroredRepeat ? VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT
                                                                                       : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = filter(desc.magFilter);
    sci.minFilter = filter(desc.minFilter);
    sci.mipmapMode = desc.mipFilter == Filter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = address;
    sci.maxLod = VK_LOD_CLAMP_NONE;
    VkSampler s;
    SFX_VK(vk_.vkCreateSampler(device_, &sci, nullptr, &s));
    return samplers_.insert(s);
}

Status VulkanDevice::destroySampler(SamplerHandle h) {
    SFX_TRY(samplers_.check(h, "sampler"));
    (hostCommandBuffer_ ? hostPending_ : pending_).samplers.push_back(samplers_.remove(h));
    releaseIdleGarbage();
    return Status::ok();
}

// ---- Programs and pipelines ----------------------------------------------------------------

// SPIR-V that the driver would choke on is refused here, with SPIRV-Tools' words.
Status validateSpirv(const CompiledProgram& program, const StageCode& stage) {
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
    std::string errors;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t& pos, const char* message) {
        errors += "  word " + std::to_string(pos.index) + ": " + message + "\n";
    });
    if (!tools.Validate(stage.spirv))
        return {StatusCode::ShaderError, "program '" + program.name + "' " + toString(stage.stage) +
                                             " stage: invalid SPIR-V:\n" + errors};
    return Status::ok();
}

Result<ProgramHandle> VulkanDevice::createProgram(const CompiledProgram& program) {
    SFX_TRY(validation::program(program, caps_));
    for (const StageCode& s : program.stages) SFX_TRY(validateSpirv(program, s));
    VulkanProgram p;
    p.name = program.name;
    p.compute = program.isCompute();
    p.resources = program.resources;
    auto cleanup = [&]() {
        for (auto& m : p.modules) vk_.vkDestroyShaderModule(device_, m.second, nullptr);
    };
    for (const StageCode& s : program.stages) {
        VkShaderModuleCreateInfo mci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        mci.codeSize = s.spirv.size() * sizeof(uint32_t);
        mci.pCode = s.spirv.data();
        VkShaderModule module;
        VkResult r = vk_.vkCreateShaderModule(device_, &mci, nullptr, &module);
        if (r != VK_SUCCESS) {
            cleanup();
            return Status{StatusCode::ShaderError, "program '" + program.name + "': vkCreateShaderModule failed: " + vkResultName(r)};
        }
        p.modules.emplace_back(s.stage, module);
    }
    return programs_.insert(std::move(p));
}

Status VulkanDevice::destroyProgram(ProgramHandle h) {
    SFX_TRY(programs_.check(h, "program"));
    // Pipelines made from it have their own layouts and need no module after creation.
    VulkanProgram p = programs_.remove(h);
    for (auto& m : p.modules) (hostCommandBuffer_ ? hostPending_ : pending_).modules.push_back(m.second);
    releaseIdleGarbage();
    return Status::ok();
}

Status VulkanDevice::createLayouts(const std::vector<ShaderResource>& resources, bool compute, VulkanPipeline& out) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const ShaderResource& r : resources) {
        VkDescriptorSetLayoutBinding b{};
        b.binding = r.binding;
        b.descriptorType = toVkDescriptor(r.kind);
        b.descriptorCount = 1;
        b.stageFlags = toVkStages(r.stages);
        if (!b.stageFlags) b.stageFlags = compute ? VK_SHADER_STAGE_COMPUTE_BIT : VK_SHADER_STAGE_ALL_GRAPHICS;
        bindings.push_back(b);
    }
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = uint32_t(bindings.size());
    lci.pBindings = bindings.data();
    SFX_VK(vk_.vkCreateDescriptorSetLayout(device_, &lci, nullptr, &out.setLayout));
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &out.setLayout;
    SFX_VK(vk_.vkCreatePipelineLayout(device_, &plci, nullptr, &out.layout));
    return Status::ok();
}

void VulkanDevice::retire(VulkanPipeline& p) {
    Garbage& g = hostCommandBuffer_ ? hostPending_ : pending_;
    if (p.pipeline) g.pipelines.push_back(p.pipeline);
    if (p.layout) g.pipelineLayouts.push_back(p.layout);
    if (p.setLayout) g.setLayouts.push_back(p.setLayout);
    p = VulkanPipeline{};
}

Result<PipelineHandle> VulkanDevice::createGraphicsPipeline(const GraphicsPipelineDesc& desc) {
    SFX_TRY(programs_.check(desc.program, "GraphicsPipelineDesc.program"));
    const VulkanProgram& prog = programs_.get(desc.program);
    if (prog.compute) return Status{StatusCode::InvalidArgument, "GraphicsPipelineDesc.program is a compute program"};
    SFX_TRY(validation::graphicsPipelineShape(desc, caps_));
    SFX_TRY(validation::graphicsPipelineState(desc, caps_));

    VulkanPipeline p;
    p.compute = false;
    p.resources = prog.resources;
    p.programName = prog.name;
    p.colorFormats = desc.colorFormats;
    p.depthFormat = desc.depthFormat;
    p.usesVertexBuffer = desc.vertexLayout.stride > 0;
    p.vertexLayout = desc.vertexLayout;
    Status s = createLayouts(prog.resources, false, p);
    if (!s) {
        retire(p);
        return s;
    }

    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (const auto& [stage, module] : prog.modules) {
        VkPipelineShaderStageCreateInfo si{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        si.stage = stage == ShaderStage::Vertex ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
        si.module = module;
        si.pName = "main";
        stages.push_back(si);
    }
    VkVertexInputBindingDescription vb{0, desc.vertexLayout.stride, VK_VERTEX_INPUT_RATE_VERTEX};
    std::vector<VkVertexInputAttributeDescription> attributes;
    for (const VertexAttribute& a : desc.vertexLayout.attributes) {
        const VkFormat f = a.format == VertexFormat::Float2   ? VK_FORMAT_R32G32_SFLOAT
                           : a.format == VertexFormat::Float3 ? VK_FORMAT_R32G32B32_SFLOAT
                                                              : VK_FORMAT_R32G32B32A32_SFLOAT;
        attributes.push_back({a.location, 0, f, a.offset});
    }
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (p.usesVertexBuffer) {
        vi.vertexBindingDescriptionCount = 1;
        vi.pVertexBindingDescriptions = &vb;
        vi.vertexAttributeDescriptionCount = uint32_t(attributes.size());
        vi.pVertexAttributeDescriptions = attributes.data();
    }
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = desc.cull == CullMode::Back    ? VK_CULL_MODE_BACK_BIT
                  : desc.cull == CullMode::Front ? VK_CULL_MODE_FRONT_BIT
                                                 : VK_CULL_MODE_NONE;
    // The HAL's front faces wind counter-clockwise with rows counted upwards (GL's window
    // convention). Vulkan measures winding with framebuffer y pointing down the rows, so the same
    // memory picture winds clockwise here.
    rs.frontFace = VK_FRONT_FACE_CLOCKWISE;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = desc.depth.test;
    ds.depthWriteEnable = desc.depth.write;
    ds.depthCompareOp = desc.depth.test ? toVk(desc.depth.compare) : VK_COMPARE_OP_ALWAYS;
    std::vector<VkPipelineColorBlendAttachmentState> blends;
    for (size_t i = 0; i < desc.colorFormats.size(); ++i) {
        VkPipelineColorBlendAttachmentState b{};
        b.blendEnable = desc.blend.enable;
        b.srcColorBlendFactor = b.srcAlphaBlendFactor = toVk(desc.blend.src);
        b.dstColorBlendFactor = b.dstAlphaBlendFactor = toVk(desc.blend.dst);
        b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
        b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
        blends.push_back(b);
    }
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = uint32_t(blends.size());
    cb.pAttachments = blends.data();
    const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dyn{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dyn.dynamicStateCount = 2;
    dyn.pDynamicStates = dynamics;
    std::vector<VkFormat> colorFormats;
    for (Format f : desc.colorFormats) colorFormats.push_back(toVkFormat(f));
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = uint32_t(colorFormats.size());
    rendering.pColorAttachmentFormats = colorFormats.data();
    rendering.depthAttachmentFormat = toVkFormat(desc.depthFormat);

    VkGraphicsPipelineCreateInfo pci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    pci.pNext = &rendering;
    pci.stageCount = uint32_t(stages.size());
    pci.pStages = stages.data();
    pci.pVertexInputState = &vi;
    pci.pInputAssemblyState = &ia;
    pci.pViewportState = &vp;
    pci.pRasterizationState = &rs;
    pci.pMultisampleState = &ms;
    pci.pDepthStencilState = &ds;
    pci.pColorBlendState = &cb;
    pci.pDynamicState = &dyn;
    pci.layout = p.layout;
    VkResult r = vk_.vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &pci, nullptr, &p.pipeline);
    if (r != VK_SUCCESS) {
        retire(p);
        return Status{StatusCode::ShaderError, "program '" + prog.name + "': vkCreateGraphicsPipelines failed: " + vkResultName(r)};
    }
    setName(VK_OBJECT_TYPE_PIPELINE, uint64_t(p.pipeline), desc.debugName);
    return pipelines_.insert(std::move(p));
}

Result<PipelineHandle> VulkanDevice::createComputePipeline(const ComputePipelineDesc& desc) {
    SFX_TRY(programs_.check(desc.program, "ComputePipelineDesc.program"));
    const VulkanProgram& prog = programs_.get(desc.program);
    if (!prog.compute) return Status{StatusCode::InvalidArgument, "ComputePipelineDesc.program is not a compute program"};
    VulkanPipeline p;
    p.compute = true;
    p.resources = prog.resources;
    p.programName = prog.name;
    Status s = createLayouts(prog.resources, true, p);
    if (!s) {
        retire(p);
        return s;
    }
    VkComputePipelineCreateInfo pci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pci.stage.module = prog.modules[0].second;
    pci.stage.pName = "main";
    pci.layout = p.layout;
    VkResult r = vk_.vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &pci, nullptr, &p.pipeline);
    if (r != VK_SUCCESS) {
        retire(p);
        return Status{StatusCode::ShaderError, "program '" + prog.name + "': vkCreateComputePipelines failed: " + vkResultName(r)};
    }
    setName(VK_OBJECT_TYPE_PIPELINE, uint64_t(p.pipeline), desc.debugName);
    return pipelines_.insert(std::move(p));
}

Status VulkanDevice::destroyPipeline(PipelineHandle h) {
    SFX_TRY(pipelines_.check(h, "pipeline"));
    VulkanPipeline p = pipelines_.remove(h);
    retire(p);
    releaseIdleGarbage();
    return Status::ok();
}

// ---- Timers --------------------------------------------------------------------------------

Result<TimerHandle> VulkanDevice::createTimer() {
    if (freeTimerSlots_.empty())
        return Status{StatusCode::InvalidArgument, "createTimer: all " + std::to_string(kMaxTimers) + " timers are in use"};
    VulkanTimer t;
    t.queryIndex = freeTimerSlots_.back() * 2;
    freeTimerSlots_.pop_back();
    return timers_.insert(t);
}

Status VulkanDevice::destroyTimer(TimerHandle h) {
    SFX_TRY(timers_.check(h, "timer"));
    freeTimerSlots_.push_back(timers_.remove(h).queryIndex / 2);
    return Status::ok();
}

Status VulkanDevice::beginTimer(TimerHandle h) {
    SFX_TRY(timers_.check(h, "timer"));
    VulkanTimer& t = timers_.get(h);
    Result<VkCommandBuffer> cb = recording();
    if (!cb) return cb.status();
    if (queryPool_) {
        vk_.vkCmdResetQueryPool(cb.value(), queryPool_, t.queryIndex, 2);
        vk_.vkCmdWriteTimestamp(cb.value(), VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queryPool_, t.queryIndex);
    }
    t.state = VulkanTimer::State::Begun;
    return Status::ok();
}

Status VulkanDevice::endTimer(TimerHandle h) {
    SFX_TRY(timers_.check(h, "timer"));
    VulkanTimer& t = timers_.get(h);
    if (t.state != VulkanTimer::State::Begun) return {StatusCode::InvalidArgument, "endTimer: timer was not begun"};
    Result<VkCommandBuffer> cb = recording();
    if (!cb) return cb.status();
    if (queryPool_) vk_.vkCmdWriteTimestamp(cb.value(), VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queryPool_, t.queryIndex + 1);
    t.state = VulkanTimer::State::Ended;
    return Status::ok();
}

Result<TimerReading> VulkanDevice::readTimer(TimerHandle h) {
    SFX_TRY(timers_.check(h, "timer"));
    VulkanTimer& t = timers_.get(h);
    if (t.state != VulkanTimer::State::Flushed)
        return Status{StatusCode::InvalidArgument, "readTimer: timer has no finished measurement"};
    if (!queryPool_) return TimerReading{t.wallMs, TimingSource::WallClockAfterFinish};
    uint64_t stamps[2] = {0, 0};
    // A host command buffer may not have run yet: never wait for it.
    const VkQueryResultFlags flags = VK_QUERY_RESULT_64_BIT | (t.hostRecorded ? 0 : VK_QUERY_RESULT_WAIT_BIT);
    VkResult r = vk_.vkGetQueryPoolResults(device_, queryPool_, t.queryIndex, 2, sizeof(stamps), stamps, sizeof(uint64_t), flags);
    if (r == VK_NOT_READY)
        return Status{StatusCode::InvalidArgument, "readTimer: the host command buffer holding the timer has not finished"};
    if (r != VK_SUCCESS) return vkError("vkGetQueryPoolResults", r);
    const uint64_t mask = timestampValidBits_ >= 64 ? ~uint64_t(0) : ((uint64_t(1) << timestampValidBits_) - 1);
    const uint64_t ticks = (stamps[1] - stamps[0]) & mask;
    return TimerReading{double(ticks) * double(props_.limits.timestampPeriod) * 1e-6, TimingSource::GpuTimestamps};
}

// ---- Commands ------------------------------------------------------------------------------

Status VulkanDevice::resolveBindings(const BindingSet& set, const VulkanPipeline& pl, const char* what,
                                     std::vector<ImageUse>& uses, ResolvedBindings& out) {
    out.images.reserve(set.textures.size() + set.storageImages.size());
    out.buffers.reserve(set.uniformBuffers.size() + set.storageBuffers.size());
    std::vector<uint32_t> given;
    // The reflected resource at `binding`, of `kind`; InvalidArgument names what is wrong.
    auto resource = [&](uint32_t binding, ResourceKind kind, const char* arg) -> Result<const ShaderResource*> {
        const std::string b = std::to_string(binding);
        if (std::find(given.begin(), given.end(), binding) != given.end())
            return invalidArgument(std::string(arg) + ".binding", b, "a binding given once per draw");
        given.push_back(binding);
        for (const ShaderResource& r : pl.resources)
            if (r.binding == binding) {
                if (r.kind != kind)
                    return invalidArgument(std::string(arg) + ".binding", b,
                                           "a " + std::string(toString(kind)) + " binding; program '" + pl.programName +
                                               "' has " + toString(r.kind) + " '" + r.name + "' there");
                return &r;
            }
        return invalidArgument(std::string(arg) + ".binding", b,
                               "a binding of program '" + pl.programName + "', which has none at " + b);
    };
    auto write = [&](uint32_t binding, VkDescriptorType type) {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstBinding = binding;
        w.descriptorCount = 1;
        w.descriptorType = type;
        out.writes.push_back(w);
        return &out.writes.back();
    };
    (void)what;

    for (const TextureBinding& tb : set.textures) {
        SFX_TRY(textures_.check(tb.texture, "TextureBinding.texture"));
        VulkanTexture& t = textures_.get(tb.texture);
        SFX_TRY(validation::textureBinding(t.desc, tb));
        VkSampler sampler = defaultSampler_;
        if (!tb.sampler.isNull()) {
            SFX_TRY(samplers_.check(tb.sampler, "TextureBinding.sampler"));
            sampler = samplers_.get(tb.sampler);
        }
        Result<const ShaderResource*> r = resource(tb.binding, ResourceKind::SampledTexture, "TextureBinding");
        if (!r) return r.status();
        Result<VkImageView> view = sampledView(t, tb.baseMip, tb.mipCount);
        if (!view) return view.status();
        out.images.push_back({sampler, view.value(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
        write(tb.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER)->pImageInfo = &out.images.back();
        uses.push_back({&t, tb.baseMip, tb.mipCount, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
    }
    for (const StorageImageBinding& sb : set.storageImages) {
        SFX_TRY(textures_.check(sb.texture, "StorageImageBinding.texture"));
        VulkanTexture& t = textures_.get(sb.texture);
        SFX_TRY(validation::mipRange(t.desc, sb.mip, "StorageImageBinding.mip"));
        Result<const ShaderResource*> r = resource(sb.binding, ResourceKind::StorageImage, "StorageImageBinding");
        if (!r) return r.status();
        if (!(t.desc.usage & kTextureStorage))
            return invalidArgument("StorageImageBinding.texture", "a texture without kTextureStorage", "a storage texture");
        Result<VkImageView> view = storageView(t, sb.mip);
        if (!view) return view.status();
        out.images.push_back({VK_NULL_HANDLE, view.value(), VK_IMAGE_LAYOUT_GENERAL});
        write(sb.binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE)->pImageInfo = &out.images.back();
        uses.push_back({&t, sb.mip, 1, VK_IMAGE_LAYOUT_GENERAL});
    }
    auto buffers = [&](const std::vector<BufferBinding>& list, ResourceKind kind, uint32_t usageBit,
                       uint64_t alignment, uint64_t maxRange) -> Status {
        const bool uniform = kind == ResourceKind::UniformBuffer;
        const char* arg = uniform ? "uniformBuffers[].buffer" : "storageBuffers[].buffer";
        for (const BufferBinding& bb : list) {
            SFX_TRY(buffers_.check(bb.buffer, "BufferBinding.buffer"));
            const VulkanBuffer& b = buffers_.get(bb.buffer);
            Result<const ShaderResource*> r = resource(bb.binding, kind, "BufferBinding");
            if (!r) return r.status();
            if (!(b.desc.usage & usageBit))
                return invalidArgument(arg, "a buffer without " + std::string(uniform ? "kBufferUniform" : "kBufferStorage"),
                                       "a buffer with that usage");
            const uint64_t size = bb.size ? bb.size : (bb.offset < b.desc.size ? b.desc.size - bb.offset : 0);
            SFX_TRY(validation::bufferRange(b.desc, bb.offset, size, "BufferBinding range"));
            if (bb.offset % alignment != 0)
                return invalidArgument("BufferBinding.offset", std::to_string(bb.offset),
                                       "a multiple of " + std::to_string(alignment));
            if (size > maxRange)
                return invalidArgument("BufferBinding.size", std::to_string(size), "at most " + std::to_string(maxRange));
            if (r.value()->blockSize > size)
                return invalidArgument("BufferBinding.size", std::to_string(size),
                                       "at least the " + std::to_string(r.value()->blockSize) + " bytes of block '" +
                                           r.value()->name + "'");
            out.buffers.push_back({b.buffer, bb.offset, size});
            write(bb.binding, toVkDescriptor(kind))->pBufferInfo = &out.buffers.back();
        }
        return Status::ok();
    };
    SFX_TRY(buffers(set.uniformBuffers, ResourceKind::UniformBuffer, kBufferUniform,
                    props_.limits.minUniformBufferOffsetAlignment, props_.limits.maxUniformBufferRange));
    SFX_TRY(buffers(set.storageBuffers, ResourceKind::StorageBuffer, kBufferStorage,
                    props_.limits.minStorageBufferOffsetAlignment, props_.limits.maxStorageBufferRange));
    for (const ShaderResource& r : pl.resources)
        if (std::find(given.begin(), given.end(), r.binding) == given.end())
            return invalidArgument("BindingSet", "without " + std::string(toString(r.kind)) + " '" + r.name + "' (binding " +
                                                     std::to_string(r.binding) + ")",
                                   "every resource of program '" + pl.programName + "'");
    return Status::ok();
}

// Two uses of one mip in different layouts within a command cannot both hold.
Status checkLayoutConflicts(const std::vector<VkImage>& images, const std::vector<uint32_t>& mips,
                            const std::vector<VkImageLayout>& layouts) {
    for (size_t i = 0; i < images.size(); ++i)
        for (size_t j = i + 1; j < images.size(); ++j)
            if (images[i] == images[j] && mips[i] == mips[j] && layouts[i] != layouts[j])
                return invalidArgument("texture mip " + std::to_string(mips[i]), "used two ways in one command",
                                       "a mip that is either sampled, a storage image or an attachment, not several");
    return Status::ok();
}

Status VulkanDevice::renderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) {
    if (pass.colors.empty() && pass.depth.texture.isNull())
        return invalidArgument("RenderPassDesc", "without attachments", "at least one colour or depth attachment");
    if (pass.colors.size() > caps_.limits.maxColorAttachments)
        return invalidArgument("RenderPassDesc.colors.size()", std::to_string(pass.colors.size()),
                               "[0, " + std::to_string(caps_.limits.maxColorAttachments) + "]");
    std::vector<ImageUse> uses;
    uint32_t width = 0, height = 0;
    auto extent = [&](const VulkanTexture& t, uint32_t mip) -> Status {
        const uint32_t w = mipExtent(t.desc.width, mip), h = mipExtent(t.desc.height, mip);
        if (width == 0) {
            width = w;
            height = h;
        } else if (w != width || h != height) {
            return invalidArgument("RenderPassDesc attachment size", std::to_string(w) + "x" + std::to_string(h),
                                   "the same size as the first attachment, " + std::to_string(width) + "x" + std::to_string(height));
        }
        return Status::ok();
    };
    std::vector<Format> colorFormats;
    for (const ColorAttachment& c : pass.colors) {
        SFX_TRY(textures_.check(c.texture, "RenderPassDesc.colors[].texture"));
        VulkanTexture& t = textures_.get(c.texture);
        SFX_TRY(validation::mipRange(t.desc, c.mip, "RenderPassDesc.colors[].mip"));
        if (!(t.desc.usage & kTextureRenderTarget) || isDepthFormat(t.desc.format))
            return invalidArgument("RenderPassDesc.colors[].texture", std::string("a ") + toString(t.desc.format) + " texture" +
                                                                          ((t.desc.usage & kTextureRenderTarget) ? "" : " without kTextureRenderTarget"),
                                   "a colour texture with kTextureRenderTarget");
        if (uint32_t(c.load) > uint32_t(LoadOp::DontCare))
            return invalidArgument("RenderPassDesc.colors[].load", std::to_string(uint32_t(c.load)), "Clear, Load or DontCare");
        SFX_TRY(extent(t, c.mip));
        colorFormats.push_back(t.desc.format);
        uses.push_back({&t, c.mip, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    }
    Format depthFormat = Format::Undefined;
    VulkanTexture* depth = nullptr;
    if (!pass.depth.texture.isNull()) {
        SFX_TRY(textures_.check(pass.depth.texture, "RenderPassDesc.depth.texture"));
        depth = &textures_.get(pass.depth.texture);
        if (!(depth->desc.usage & kTextureRenderTarget) || !isDepthFormat(depth->desc.format))
            return invalidArgument("RenderPassDesc.depth.texture", std::string("a ") + toString(depth->desc.format) + " texture",
                                   "a depth texture with kTextureRenderTarget");
        if (uint32_t(pass.depth.load) > uint32_t(LoadOp::DontCare))
            return invalidArgument("RenderPassDesc.depth.load", std::to_string(uint32_t(pass.depth.load)), "Clear, Load or DontCare");
        SFX_TRY(extent(*depth, 0));
        depthFormat = depth->desc.format;
        uses.push_back({depth, 0, 1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL});
    }

    std::vector<ResolvedBindings> resolved(draws.size());
    for (size_t i = 0; i < draws.size(); ++i) {
        const DrawDesc& d = draws[i];
        SFX_TRY(pipelines_.check(d.pipeline, "DrawDesc.pipeline"));
        const VulkanPipeline& pl = pipelines_.get(d.pipeline);
        if (pl.compute) return invalidArgument("DrawDesc.pipeline", "a compute pipeline", "a graphics pipeline");
        if (pl.colorFormats != colorFormats || pl.depthFormat != depthFormat)
            return invalidArgument("DrawDesc.pipeline", "a pipeline made for other attachment formats",
                                   "a pipeline whose colorFormats and depthFormat match the pass's attachments");
        SFX_TRY(resolveBindings(d.bindings, pl, "DrawDesc.bindings", uses, resolved[i]));
        SFX_TRY(validation::noFeedbackLoop(pass, d));
        const BufferDesc* vertexBuffer = nullptr;
        const BufferDesc* indexBuffer = nullptr;
        if (pl.usesVertexBuffer || !d.vertexBuffer.isNull()) {
            SFX_TRY(buffers_.check(d.vertexBuffer, "DrawDesc.vertexBuffer"));
            vertexBuffer = &buffers_.get(d.vertexBuffer).desc;
        }
        if (!d.indexBuffer.isNull()) {
            SFX_TRY(buffers_.check(d.indexBuffer, "DrawDesc.indexBuffer"));
            indexBuffer = &buffers_.get(d.indexBuffer).desc;
        }
        SFX_TRY(validation::drawRange(d, pl.vertexLayout, vertexBuffer, indexBuffer));
    }
    {
        std::vector<VkImage> images;
        std::vector<uint32_t> mips;
        std::vector<VkImageLayout> layouts;
        for (const ImageUse& u : uses)
            for (uint32_t m = u.baseMip; m < u.baseMip + u.mipCount; ++m) {
                images.push_back(u.texture->image);
                mips.push_back(m);
                layouts.push_back(u.layout);
            }
        SFX_TRY(checkLayoutConflicts(images, mips, layouts));
    }
    // Views before recording, so that a failure leaves the command buffer untouched.
    std::vector<VkImageView> colorViews;
    for (const ColorAttachment& c : pass.colors) {
        Result<VkImageView> v = attachmentView(textures_.get(c.texture), c.mip);
        if (!v) return v.status();
        colorViews.push_back(v.value());
    }
    VkImageView depthView = VK_NULL_HANDLE;
    if (depth) {
        Result<VkImageView> v = attachmentView(*depth, 0);
        if (!v) return v.status();
        depthView = v.value();
    }
    std::vector<VkDescriptorSet> sets(draws.size(), VK_NULL_HANDLE);
    for (size_t i = 0; i < draws.size(); ++i) {
        const VulkanPipeline& pl = pipelines_.get(draws[i].pipeline);
        if (pl.resources.empty()) continue;
        Result<VkDescriptorSet> set = allocateSet(pl.setLayout);
        if (!set) return set.status();
        sets[i] = set.value();
        for (VkWriteDescriptorSet& w : resolved[i].writes) w.dstSet = sets[i];
        vk_.vkUpdateDescriptorSets(device_, uint32_t(resolved[i].writes.size()), resolved[i].writes.data(), 0, nullptr);
    }

    Result<VkCommandBuffer> cbr = recording();
    if (!cbr) return cbr.status();
    VkCommandBuffer cb = cbr.value();
    barrier(cb, uses);

    auto loadOp = [](LoadOp op) {
        return op == LoadOp::Clear ? VK_ATTACHMENT_LOAD_OP_CLEAR
               : op == LoadOp::Load ? VK_ATTACHMENT_LOAD_OP_LOAD
                                    : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    };
    std::vector<VkRenderingAttachmentInfo> colorInfos;
    for (size_t i = 0; i < pass.colors.size(); ++i) {
        const ColorAttachment& c = pass.colors[i];
        VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        a.imageView = colorViews[i];
        a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a.loadOp = loadOp(c.load);
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        if (isIntegerFormat(colorFormats[i])) {
            for (int k = 0; k < 4; ++k) a.clearValue.color.uint32[k] = c.clearColor[k] > 0 ? uint32_t(c.clearColor[k]) : 0u;
        } else {
            for (int k = 0; k < 4; ++k) a.clearValue.color.float32[k] = c.clearColor[k];
        }
        colorInfos.push_back(a);
    }
    VkRenderingAttachmentInfo depthInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    if (depth) {
        depthInfo.imageView = depthView;
        depthInfo.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        depthInfo.loadOp = loadOp(pass.depth.load);
        depthInfo.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depthInfo.clearValue.depthStencil = {pass.depth.clearDepth, 0};
    }
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {width, height}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = uint32_t(colorInfos.size());
    ri.pColorAttachments = colorInfos.data();
    ri.pDepthAttachment = depth ? &depthInfo : nullptr;
    vk_.vkCmdBeginRendering(cb, &ri);
    // Positive height: NDC y = -1 lands on row 0, as on GL (see hal.hpp).
    VkViewport viewport{0, 0, float(width), float(height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {width, height}};
    vk_.vkCmdSetViewport(cb, 0, 1, &viewport);
    vk_.vkCmdSetScissor(cb, 0, 1, &scissor);
    for (size_t i = 0; i < draws.size(); ++i) {
        const DrawDesc& d = draws[i];
        const VulkanPipeline& pl = pipelines_.get(d.pipeline);
        vk_.vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pl.pipeline);
        if (sets[i]) vk_.vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pl.layout, 0, 1, &sets[i], 0, nullptr);
        if (pl.usesVertexBuffer) {
            const VkDeviceSize offset = 0;
            vk_.vkCmdBindVertexBuffers(cb, 0, 1, &buffers_.get(d.vertexBuffer).buffer, &offset);
        }
        if (!d.indexBuffer.isNull()) {
            vk_.vkCmdBindIndexBuffer(cb, buffers_.get(d.indexBuffer).buffer, 0, VK_INDEX_TYPE_UINT32);
            vk_.vkCmdDrawIndexed(cb, d.count, d.instanceCount, 0, 0, 0);
        } else {
            vk_.vkCmdDraw(cb, d.count, d.instanceCount, 0, 0);
        }
    }
    vk_.vkCmdEndRendering(cb);
    return Status::ok();
}

Status VulkanDevice::dispatch(const DispatchDesc& d) {
    SFX_TRY(validation::dispatchGroups(d, caps_));
    SFX_TRY(pipelines_.check(d.pipeline, "DispatchDesc.pipeline"));
    const VulkanPipeline& pl = pipelines_.get(d.pipeline);
    if (!pl.compute) return invalidArgument("DispatchDesc.pipeline", "a graphics pipeline", "a compute pipeline");
    std::vector<ImageUse> uses;
    ResolvedBindings resolved;
    SFX_TRY(resolveBindings(d.bindings, pl, "DispatchDesc.bindings", uses, resolved));
    {
        std::vector<VkImage> images;
        std::vector<uint32_t> mips;
        std::vector<VkImageLayout> layouts;
        for (const ImageUse& u : uses)
            for (uint32_t m = u.baseMip; m < u.baseMip + u.mipCount; ++m) {
                images.push_back(u.texture->image);
                mips.push_back(m);
                layouts.push_back(u.layout);
            }
        SFX_TRY(checkLayoutConflicts(images, mips, layouts));
    }
    VkDescriptorSet set = VK_NULL_HANDLE;
    if (!pl.resources.empty()) {
        Result<VkDescriptorSet> s = allocateSet(pl.setLayout);
        if (!s) return s.status();
        set = s.value();
        for (VkWriteDescriptorSet& w : resolved.writes) w.dstSet = set;
        vk_.vkUpdateDescriptorSets(device_, uint32_t(resolved.writes.size()), resolved.writes.data(), 0, nullptr);
    }
    Result<VkCommandBuffer> cbr = recording();
    if (!cbr) return cbr.status();
    VkCommandBuffer cb = cbr.value();
    barrier(cb, uses);
    vk_.vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pl.pipeline);
    if (set) vk_.vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pl.layout, 0, 1, &set, 0, nullptr);
    vk_.vkCmdDispatch(cb, d.groupsX, d.groupsY, d.groupsZ);
    return Status::ok();
}

Status VulkanDevice::flush() {
    if (hostCommandBuffer_) {
        // The host ends and submits its command buffer; what it used lives until it is done.
        hostCommandBuffer_ = VK_NULL_HANDLE;
        for (VkDescriptorPool p : descriptorPools_) hostPending_.descriptorPools.push_back(p);
        descriptorPools_.clear();
        currentPool_ = 0;
        timers_.forEachAlive([&](VulkanTimer& t) {
            if (t.state == VulkanTimer::State::Ended) {
                t.state = VulkanTimer::State::Flushed;
                t.hostRecorded = true;
            }
        });
        return Status::ok();
    }
    return submitAndWait();
}

Status VulkanDevice::setHostCommandBuffer(VkCommandBuffer cb) {
    if (hostCommandBuffer_) SFX_TRY(flush());  // detach the previous one
    // Work recorded on our own command buffer comes first.
    SFX_TRY(submitAndWait());
    // The previous host command buffer has finished by now (documented contract).
    releaseGarbage(hostPending_);
    hostCommandBuffer_ = cb;
    return Status::ok();
}

// A failed open explains itself with what the loader and layers said on the way.
Status withMessages(const Status& s, VulkanDevice& device) {
    std::string text = s.message();
    for (const std::string& m : device.takeValidationMessages()) text += "; " + m;
    return {s.code(), text};
}

}  // namespace

Result<std::unique_ptr<Device>> createDevice(const DeviceOptions& options) {
    auto device = std::make_unique<VulkanDevice>();
    Status s = device->initOwn(options);
    if (!s) return withMessages(s, *device);
    return std::unique_ptr<Device>(std::move(device));
}

Result<std::unique_ptr<Device>> wrapDevice(const ExternalVulkan& external, const DeviceOptions& options) {
    auto device = std::make_unique<VulkanDevice>();
    Status s = device->initWrapped(external, options);
    if (!s) return withMessages(s, *device);
    return std::unique_ptr<Device>(std::move(device));
}

Status setCommandBuffer(Device& device, VkCommandBuffer commandBuffer) {
    auto* vk = dynamic_cast<VulkanDevice*>(&device);
    if (!vk) return invalidArgument("device", std::string("a ") + toString(device.caps().backend) + " device", "a Vulkan device");
    return vk->setHostCommandBuffer(commandBuffer);
}

}  // namespace sfx::vulkan
