// The Vulkan backend's Device. Its hooks (vulkan_device.cpp) take the arguments Device's front end
// checked and delegate to the files that own each concern; the comments below name each file.
//
// Design, chosen for correctness over overlap:
// - One command buffer records everything between flushes; flush() submits it and waits.
// - Each command records only the barriers its hazards need, per image mip and per buffer, from
//   the last use tracked for each (vulkan_barriers.cpp); each mip has its own layout, so a pass
//   may render into mip i+1 while sampling mip i.
// - Buffers live in host-visible, coherent memory. Writes are recorded as copies from the staging
//   ring (vulkan_staging.cpp) so that they stay ordered with the commands around them; descriptor
//   sets are cached. After the first frame at a size and settings, a frame allocates nothing.
// - Vulkan functions come from a table loaded through vkGetInstanceProcAddr: the loader is opened
//   at run time (own device) or the host's entry point is used (wrapped device).
#pragma once

#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "sfx/handle.hpp"
#include "sfx/vulkan_device.hpp"
#include "vulkan_loader.hpp"
#include "vulkan_objects.hpp"

namespace sfx::vulkan {

// What the loader and the instance were made with; shared by createDevice and wrapDevice.
struct InstanceSetup {
    Functions fns;
    void* loaderLibrary = nullptr;  // dlopen handle, own device only
    VkInstance instance = VK_NULL_HANDLE;
    bool ownsInstance = false;
    bool debugUtils = false;
};

// vulkan_pipelines.cpp: SPIR-V whose structure a driver would walk off is refused.
Status validateSpirv(const CompiledProgram& program, const StageCode& stage);

class VulkanDevice final : public Device {
public:
    VulkanDevice()
        : serial_(nextDeviceSerial()),
          textures_(serial_, "texture"),
          buffers_(serial_, "buffer"),
          samplers_(serial_, "sampler"),
          programs_(serial_, "program"),
          pipelines_(serial_, "pipeline"),
          timers_(serial_, "timer"),
          recordings_(serial_, "recording") {}
    ~VulkanDevice() override {
        shutdown();
        // Messages nobody took (teardown ones included) go to the host's log callback.
        for (const std::string& m : takeValidationMessages())
            if (log_) log_(LogSeverity::Error, "sfx vulkan: untaken validation message at teardown: " + m);
    }

    // vulkan_platform.cpp: own instance and device, or the host's objects.
    Status initOwn(const DeviceOptions& options);
    Status initWrapped(const ExternalVulkan& ext, const DeviceOptions& options);

    // vulkan_commands.cpp
    Status setHostCommandBuffer(VkCommandBuffer cb, bool previousFinished);

    // vulkan_external_images.cpp: host images in, SDK images out, and their state contract.
    Result<TextureHandle> importExternal(const ExternalImage& image);
    Result<NativeImage> native(TextureHandle texture);

    const DeviceCaps& caps() const override { return caps_; }
    DeviceStats stats() const override;  // vulkan_memory.cpp

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
    // ---- Device's hooks: arguments checked by the front end (hal_device.cpp) ----------------
    const validation::ObjectLookup& objects() const override { return lookup_; }
    // vulkan_device.cpp, but for the timers (vulkan_timers.cpp), flush (vulkan_commands.cpp) and
    // replayed calls (vulkan_recordings.cpp).
    Result<TextureHandle> doCreateTexture(const TextureDesc& desc) override;
    Status doDestroyTexture(TextureHandle texture) override;
    Status doWriteTexture(TextureHandle texture, uint32_t mip, const void* data, size_t bytes) override;
    Status doReadTexture(TextureHandle texture, uint32_t mip, void* out, size_t bytes) override;

    Result<BufferHandle> doCreateBuffer(const BufferDesc& desc) override;
    Status doDestroyBuffer(BufferHandle buffer) override;
    Status doWriteBuffer(BufferHandle buffer, uint64_t offset, const void* data, size_t bytes) override;
    Status doReadBuffer(BufferHandle buffer, uint64_t offset, void* out, size_t bytes) override;

    Result<SamplerHandle> doCreateSampler(const SamplerDesc& desc) override;
    Status doDestroySampler(SamplerHandle sampler) override;

    Result<ProgramHandle> doCreateProgram(const CompiledProgram& program) override;
    Status doDestroyProgram(ProgramHandle program) override;

    Result<PipelineHandle> doCreateGraphicsPipeline(const GraphicsPipelineDesc& desc, validation::PipelineInfo info) override;
    Result<PipelineHandle> doCreateComputePipeline(const ComputePipelineDesc& desc, validation::PipelineInfo info) override;
    Status doDestroyPipeline(PipelineHandle pipeline) override;

    Result<TimerHandle> doCreateTimer() override;
    Status doDestroyTimer(TimerHandle timer) override;
    Status doBeginTimer(TimerHandle timer) override;
    Status doEndTimer(TimerHandle timer) override;
    Result<TimerReading> doReadTimer(TimerHandle timer) override;

    // vulkan_recordings.cpp
    Status doBeginRecording() override;
    Result<RecordingHandle> doEndRecording() override;
    Status doBeginReplay(RecordingHandle recording) override;
    Status doEndReplay(RecordingHandle recording) override;
    Status doDestroyRecording(RecordingHandle recording) override;
    Status doReplayCall(const RenderPassDesc* pass, std::span<const DrawDesc> draws, const DispatchDesc* dispatch) override;
    Status doRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) override;
    Status doDispatch(const DispatchDesc& dispatch) override;
    Status doFlush() override;

    // vulkan_platform.cpp
    Status createInstance(const DeviceOptions& options, uint32_t& apiVersion);
    // Needs a graphics+compute queue and dynamic rendering; discrete first.
    Status pickPhysicalDevice(uint32_t apiVersion, const std::string& wanted, bool& needsKhrDynamicRendering);
    Status createLogicalDevice(bool needsKhrDynamicRendering);
    Status finishInit(const DeviceOptions& options, bool ownsDevice);
    void setName(VkObjectType type, uint64_t handle, const char* name);
    // vulkan_caps.cpp
    void fillCaps(const DeviceOptions& options);

    // vulkan_memory.cpp: allocations, host-visible buffers and their staging copies.
    Result<Allocation> allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags want, bool map);
    void freeMemory(VkDeviceMemory memory, uint64_t bytes);  // of a failed creation
    Result<VulkanBuffer> makeBuffer(uint64_t size, VkBufferUsageFlags usage, const char* name);
    Result<BufferHandle> makeHalBuffer(const BufferDesc& desc);
    Status stageBufferWrite(VulkanBuffer& b, uint64_t offset, const void* data, size_t bytes);
    Status readBackBuffer(VulkanBuffer& b, uint64_t offset, void* out, size_t bytes);

    // vulkan_textures.cpp: images, their views and layouts, samplers.
    Result<TextureHandle> makeTexture(const TextureDesc& desc);
    Status uploadTexture(VulkanTexture& t, uint32_t mip, const void* data, size_t bytes);
    Status downloadTexture(VulkanTexture& t, uint32_t mip, void* out, size_t bytes);
    Result<SamplerHandle> makeSampler(const SamplerDesc& desc);
    Result<VkImageView> sampledView(VulkanTexture& t, uint32_t baseMip, uint32_t mipCount);
    Result<VkImageView> attachmentView(VulkanTexture& t, uint32_t mip);
    Result<VkImageView> storageView(VulkanTexture& t, uint32_t mip) { return sampledView(t, mip, 1); }

    // vulkan_external_images.cpp: the barrier that returns an imported image used since the last
    // hand-back to the host's layout (every flush, and before the SDK forgets the image).
    void handBack(VkCommandBuffer cb, VulkanTexture& t);
    void handBackExternal(VkCommandBuffer cb);
    Status forgetExternal(TextureHandle h, VulkanTexture& t);

    // vulkan_barriers.cpp: the barriers `uses` need after what was recorded before.
    void barriers(VkCommandBuffer cb, std::span<const ImageUse> images, std::span<const BufferUse> buffers);
    void barriers(VkCommandBuffer cb, const Uses& uses) { barriers(cb, uses.images, uses.buffers); }

    // vulkan_staging.cpp: `bytes` of the staging ring, for the command buffer being recorded.
    Result<StagingSlice> stage(uint64_t bytes);
    void recycleStaging(std::vector<StagingBlock>& blocks);  // their command buffer has finished
    void destroyStaging();

    // vulkan_descriptors.cpp
    // Descriptor writes, and image and buffer uses, of a BindingSet the shared validation accepted.
    Status resolveBindings(const BindingSet& set, const VulkanPipeline& pipeline, Uses& uses, ResolvedBindings& out);
    Result<VkDescriptorSet> allocateSet(VkDescriptorSetLayout layout);
    // A set of the pipeline's layout holding `resolved`, from the cache or written once;
    // VK_NULL_HANDLE for a pipeline without resources.
    Result<VkDescriptorSet> writeSet(const VulkanPipeline& pipeline, ResolvedBindings& resolved);
    void clearSetCache();  // before an object a cached set may name goes
    Status createLayouts(const std::vector<ShaderResource>& resources, bool compute, VulkanPipeline& out);

    // vulkan_pipelines.cpp
    Result<ProgramHandle> makeProgram(const CompiledProgram& program);
    Result<PipelineHandle> makeGraphicsPipeline(const GraphicsPipelineDesc& desc, const VulkanProgram& prog, validation::PipelineInfo info);
    Result<PipelineHandle> makeComputePipeline(const ComputePipelineDesc& desc, const VulkanProgram& prog, validation::PipelineInfo info);
    // The pipeline's checked description and the layouts made from its reflection; on failure
    // `p` is retired.
    Status startPipeline(validation::PipelineInfo info, VulkanPipeline& p);
    // Inserts `p` once created (r is VK_SUCCESS); otherwise retires it and names the program.
    Result<PipelineHandle> finishPipeline(VulkanPipeline& p, VkResult r, const char* call, const char* debugName);

    // vulkan_commands.cpp: recording, submission and the host's command buffer.
    // The command buffer a command goes to: the open recording's, or primaryRecording().
    Result<VkCommandBuffer> recording();
    Result<VkCommandBuffer> primaryRecording();                                 // the host's, or the device's own (begun here)
    Result<VkCommandBuffer> allocateCommandBuffer(VkCommandBufferLevel level);  // from the device's pool
    Status submitAndWait();
    Status noHostCommandBuffer(const char* call) const;
    // The attachments of a render pass the shared validation accepted: size, formats, layouts.
    // Filled into `out` (cleared first).
    void passTargets(const RenderPassDesc& pass, PassTargets& out);
    Status recordRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws, const PassTargets& targets,
                            std::span<ResolvedBindings> resolved);
    Status recordDispatch(const DispatchDesc& d, const VulkanPipeline& pl, const Uses& uses, ResolvedBindings& resolved);

    // vulkan_recordings.cpp: what the calls between beginRecording/beginReplay and their end do.
    // Recording: a checked renderPass's or dispatch's arguments, kept with the open recording.
    void noteRecordedCall(const RenderPassDesc* pass, std::span<const DrawDesc> draws, const DispatchDesc* dispatch);
    // A timer inside a recording makes it single-use; inside a replay, a mismatch. True: skip it.
    bool noteTimer();
    // Recording: notes a use of a resource (the barriers of the recording's command buffer).
    // `texture` and `mip`, or `buffer`, name it; called before the use is tracked.
    void noteRecordedUse(VulkanTexture* texture, uint32_t mip, VulkanBuffer* buffer, VkImageLayout layout, VkPipelineStageFlags stages,
                         VkAccessFlags access, bool write);
    // The command buffer a host write (a staged copy) goes to: the primary one, unless the open
    // recording has used the resource already (the copy must follow that use: it goes into the
    // recording, which is then not reusable).
    Result<VkCommandBuffer> writeRecording(const AccessState& s);
    bool usedByOpenRecording(const AccessState& s) const { return recordingOpen() && s.recordingSerial == recordingSerial_; }
    bool recordingOpen() const { return recordingState() == RecordingState::Recording; }
    // A texture or buffer made or imported, one destroyed (or a sampler or pipeline), the
    // descriptor-set cache dropped: recordings made before are stale.
    void changeObjects() { ++objectEpoch_; }

    // vulkan_garbage.cpp: deferred destruction.
    Garbage& currentGarbage() { return hostCommandBuffer_ ? hostPending_ : pending_; }
    void releaseGarbage(Garbage& g);
    void releaseIdleGarbage();
    void retire(VulkanTexture& t);
    void retire(VulkanBuffer& b, Garbage& g);
    void retire(VulkanPipeline& p);
    void shutdown();

    // vulkan_timers.cpp
    Status createTimerPool();
    // Ended timers hold a finished measurement: of the submit that took wallMs, or of a host
    // command buffer (hostRecorded), whose results may not be ready and whose wall time is unknown.
    void markEndedTimersFlushed(bool hostRecorded, double wallMs);

    DeviceCaps caps_;
    uint16_t serial_;
    HandlePool<TextureTag, VulkanTexture> textures_;
    HandlePool<BufferTag, VulkanBuffer> buffers_;
    HandlePool<SamplerTag, VulkanSampler> samplers_;
    HandlePool<ProgramTag, VulkanProgram> programs_;
    HandlePool<PipelineTag, VulkanPipeline> pipelines_;
    HandlePool<TimerTag, VulkanTimer> timers_;
    HandlePool<RecordingTag, VulkanRecording> recordings_;
    const decltype(validation::poolLookup(textures_, buffers_, samplers_, programs_, pipelines_, timers_, recordings_)) lookup_ =
        validation::poolLookup(textures_, buffers_, samplers_, programs_, pipelines_, timers_, recordings_);
    std::vector<TextureHandle> externals_;  // imported images, handed back at every flush

public:  // set up by the factory functions
    InstanceSetup setup_;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    std::string deviceChoice_;  // why pickPhysicalDevice took physical_ (own device)
    bool ownsDevice_ = false;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    LogCallback log_;  // DeviceOptions::log

private:
    Functions& vk_ = setup_.fns;
    VkPhysicalDeviceProperties props_{};
    VkPhysicalDeviceMemoryProperties memProps_{};
    uint32_t timestampValidBits_ = 0;
    bool fullFeatures_ = true;               // no ceiling
    bool fragmentStoresAndAtomics_ = false;  // the device feature, enabled when present
    bool synchronization2_ = false;          // barriers() records one vkCmdPipelineBarrier2 per command

    VkCommandPool commandPool_ = VK_NULL_HANDLE;
    VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    bool recording_ = false;  // own command buffer begun and holds commands
    VkCommandBuffer hostCommandBuffer_ = VK_NULL_HANDLE;
    VkSampler defaultSampler_ = VK_NULL_HANDLE;
    VkQueryPool queryPool_ = VK_NULL_HANDLE;
    std::vector<uint32_t> freeTimerSlots_;

    std::vector<VkDescriptorPool> descriptorPools_;  // of the set cache
    size_t currentPool_ = 0;
    std::map<std::vector<uint64_t>, VkDescriptorSet> setCache_;
    std::vector<uint64_t> setKey_;  // reused to build the key of each lookup
    CommandScratch scratch_;        // reused by every command (vulkan_objects.hpp)
    std::vector<StagingBlock> stagingIdle_, stagingOwn_, stagingHost_;
    // For stats().
    ObjectCount memoryCount_, stagingCount_, descriptorSetCount_, descriptorPoolCount_, imageViewCount_;
    uint64_t memoryBytes_ = 0;
    Garbage pending_;      // released after the next flush
    Garbage hostPending_;  // used by a host command buffer: released at the next setCommandBuffer
    std::chrono::steady_clock::time_point recordStart_{};

    // Reusable recordings (vulkan_recordings.cpp); which is open is the front end's state.
    VulkanRecording open_;     // Recording: being recorded
    size_t replayCursor_ = 0;  // Replaying: how much of its calls the calls so far matched
    bool replayMatches_ = true;
    uint64_t recordingSerial_ = 0;       // of the open recording (marks AccessState::recordingSerial)
    uint64_t objectEpoch_ = 1;           // bumped by changeObjects()
    std::vector<uint64_t> callScratch_;  // one call's arguments, flattened
    std::vector<VkCommandBuffer> freeSecondaries_;
    std::vector<ImageUse> replayImages_;
    std::vector<BufferUse> replayBuffers_;

    std::mutex messagesMutex_;
    std::vector<std::string> messages_;
};

}  // namespace sfx::vulkan
