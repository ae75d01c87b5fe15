// Reusable recordings (Device::beginRecording / beginReplay, hal.hpp): an effect's passes recorded
// once into a secondary command buffer and executed again in later frames that make the same
// calls. What a replay saves is the recording itself: resolving bindings, looking up descriptor
// sets, computing barriers and, above all, the driver's per-command work (lavapipe copies every
// vkCmd* into its own list), which is most of a dispatch's CPU time.
//
// Correct by construction rather than by the caller's promise:
// - A replay's renderPass and dispatch calls are compared, argument by argument, with the recorded
//   ones; any difference (a changed setting, another input texture) makes endReplay stale and the
//   caller records again.
// - Creating or importing a texture or buffer, destroying any of them or a sampler or pipeline,
//   and dropping the descriptor-set cache bump the device's object epoch: descriptor sets, views
//   and the pointers a recording keeps to its resources' tracked states are then suspect.
//   (Creating a program, pipeline, sampler or timer moves nothing a recording holds.)
// - Barriers: the recording's command buffer holds the barriers between its own passes, computed
//   from the states its resources had when it was recorded. A resource the recording writes (or
//   moves to another layout) must be in exactly that state again for those barriers to be right;
//   for a resource it only reads (an input, a uniform buffer the host rewrote) endReplay records
//   in the primary command buffer the barrier (and layout transition) its reads need after
//   whatever came before, as the direct path would have.
// - Host writes during a recording (writeBuffer: a changed uniform) go to the primary command
//   buffer, before the recording runs, unless the recording has used the resource already: then
//   the copy must stay in order inside the recording, which is then single-use.
#include <bit>

#include "vulkan_device_impl.hpp"

namespace sfx::vulkan {
namespace {

Status stale(const char* why) { return {StatusCode::StaleHandle, std::string("endReplay: the recording is stale: ") + why}; }

AccessState& stateOf(VulkanTexture* texture, uint32_t mip, VulkanBuffer* buffer) { return texture ? texture->mips[mip] : buffer->state; }
AccessState& stateOf(const RecordedResource& r) { return stateOf(r.texture, r.mip, r.buffer); }

uint64_t floatBits(float f) { return std::bit_cast<uint32_t>(f); }

// Every argument of a renderPass or dispatch that reaches the command buffer, flattened.
void flattenBindings(const BindingSet& b, std::vector<uint64_t>& out) {
    out.push_back(b.textures.size());
    for (const TextureBinding& t : b.textures) {
        out.push_back(t.binding);
        out.push_back(t.texture.bits);
        out.push_back((uint64_t(t.baseMip) << 32) | t.mipCount);
        out.push_back(t.sampler.bits);
    }
    for (const std::vector<BufferBinding>* list : {&b.uniformBuffers, &b.storageBuffers}) {
        out.push_back(list->size());
        for (const BufferBinding& u : *list) {
            out.push_back(u.binding);
            out.push_back(u.buffer.bits);
            out.push_back(u.offset);
            out.push_back(u.size);
        }
    }
    out.push_back(b.storageImages.size());
    for (const StorageImageBinding& s : b.storageImages) {
        out.push_back(s.binding);
        out.push_back(s.texture.bits);
        out.push_back(s.mip);
    }
}

void flattenCall(const RenderPassDesc* pass, std::span<const DrawDesc> draws, const DispatchDesc* dispatch, std::vector<uint64_t>& out) {
    out.clear();
    if (pass) {
        out.push_back(1);
        out.push_back(pass->colors.size());
        for (const ColorAttachment& c : pass->colors) {
            out.push_back(c.texture.bits);
            out.push_back((uint64_t(c.mip) << 32) | uint64_t(c.load));
            for (float f : c.clearColor) out.push_back(floatBits(f));
        }
        out.push_back(pass->depth.texture.bits);
        out.push_back((uint64_t(pass->depth.load) << 32) | floatBits(pass->depth.clearDepth));
        out.push_back(draws.size());
        for (const DrawDesc& d : draws) {
            out.push_back(d.pipeline.bits);
            flattenBindings(d.bindings, out);
            out.push_back(d.vertexBuffer.bits);
            out.push_back(d.indexBuffer.bits);
            out.push_back((uint64_t(d.count) << 32) | d.instanceCount);
        }
    } else {
        out.push_back(2);
        out.push_back(dispatch->pipeline.bits);
        flattenBindings(dispatch->bindings, out);
        out.push_back(dispatch->groupsX);
        out.push_back((uint64_t(dispatch->groupsY) << 32) | dispatch->groupsZ);
    }
}

}  // namespace

bool sameState(const AccessState& a, const AccessState& b) {
    if (a.layout != b.layout || a.writeStages != b.writeStages || a.writeAccess != b.writeAccess || a.readStages != b.readStages ||
        a.visibleCount != b.visibleCount)
        return false;
    for (uint32_t i = 0; i < a.visibleCount; ++i)
        if (a.visible[i] != b.visible[i]) return false;
    return true;
}

// The front end (hal_device.cpp) has checked that the device keeps recordings, what is open and
// the handle; these do the Vulkan work.
Status VulkanDevice::doBeginRecording() {
    VkCommandBuffer cb = VK_NULL_HANDLE;
    if (!freeSecondaries_.empty()) {
        cb = freeSecondaries_.back();
        freeSecondaries_.pop_back();
    } else {
        Result<VkCommandBuffer> made = allocateCommandBuffer(VK_COMMAND_BUFFER_LEVEL_SECONDARY);
        if (!made) return made.status();
        cb = made.value();
    }
    // Not a render-pass continuation: the recording begins and ends its own dynamic renderings.
    // Simultaneous use: host command buffers holding it may be pending at once.
    VkCommandBufferInheritanceInfo inheritance{VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_INFO};
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_SIMULTANEOUS_USE_BIT;
    bi.pInheritanceInfo = &inheritance;
    const VkResult r = vk_.vkBeginCommandBuffer(cb, &bi);
    if (r != VK_SUCCESS) {
        freeSecondaries_.push_back(cb);
        return vkError("vkBeginCommandBuffer", r);
    }
    open_ = VulkanRecording{};
    open_.commandBuffer = cb;
    open_.epoch = objectEpoch_;
    ++recordingSerial_;
    return Status::ok();
}

Result<RecordingHandle> VulkanDevice::doEndRecording() {
    VulkanRecording rec = std::move(open_);
    open_ = VulkanRecording{};
    VkResult r = vk_.vkEndCommandBuffer(rec.commandBuffer);
    Result<VkCommandBuffer> primary = r == VK_SUCCESS ? primaryRecording() : Result<VkCommandBuffer>(vkError("vkEndCommandBuffer", r));
    if (!primary) {
        freeSecondaries_.push_back(rec.commandBuffer);  // beginning it again resets it
        return primary.status();
    }
    // The calls made while recording run now, where they were made.
    vk_.vkCmdExecuteCommands(primary.value(), 1, &rec.commandBuffer);
    if (rec.epoch != objectEpoch_) {
        // The resources' records may have moved: their exit states cannot be read.
        rec.reusable = false;
        rec.why = "an object was created or destroyed while it was recorded";
    } else {
        for (RecordedResource& res : rec.resources) res.exit = stateOf(res);
    }
    return recordings_.insert(std::move(rec));
}

Status VulkanDevice::doBeginReplay(RecordingHandle) {
    replayCursor_ = 0;
    replayMatches_ = true;
    return Status::ok();
}

Status VulkanDevice::doEndReplay(RecordingHandle replayed) {
    const VulkanRecording& rec = recordings_.get(replayed);
    if (!replayMatches_ || replayCursor_ != rec.calls.size()) return stale("the calls differ from the recorded ones");
    if (!rec.reusable) return stale(rec.why);
    if (rec.epoch != objectEpoch_) return stale("an object was created or destroyed since it was recorded");
    for (const RecordedResource& res : rec.resources)
        if (res.written && !sameState(stateOf(res), res.entry)) return stale("a resource it writes is not in the state it was recorded from");
    Result<VkCommandBuffer> primary = primaryRecording();
    if (!primary) return primary.status();
    // What the resources it only reads need after what came before (a rewritten uniform buffer,
    // the host's pass that wrote the depth, an upload that left a texture in another layout): the
    // barrier the direct path would have recorded, into the layout the recording reads them in.
    replayImages_.clear();
    replayBuffers_.clear();
    for (const RecordedResource& res : rec.resources) {
        if (res.written) continue;
        if (res.texture)
            replayImages_.push_back({res.texture, res.mip, 1, res.entry.layout, res.stages, res.access, false});
        else
            replayBuffers_.push_back({res.buffer, res.stages, res.access, false});
    }
    barriers(primary.value(), replayImages_, replayBuffers_);
    vk_.vkCmdExecuteCommands(primary.value(), 1, &rec.commandBuffer);
    for (const RecordedResource& res : rec.resources)
        if (res.written) stateOf(res) = res.exit;
    return Status::ok();
}

Status VulkanDevice::doDestroyRecording(RecordingHandle h) {
    VulkanRecording rec = recordings_.remove(h);
    // Command buffers that executed it may still be pending: it goes back to the free list
    // when they have finished.
    currentGarbage().secondaries.push_back(rec.commandBuffer);
    releaseIdleGarbage();
    return Status::ok();
}

void VulkanDevice::noteRecordedCall(const RenderPassDesc* pass, std::span<const DrawDesc> draws, const DispatchDesc* dispatch) {
    if (!recordingOpen()) return;
    flattenCall(pass, draws, dispatch, callScratch_);
    open_.calls.insert(open_.calls.end(), callScratch_.begin(), callScratch_.end());
}

// Replaying: the call is compared with the recorded ones (the same arguments on the same objects
// pass the checks again, and endReplay refuses the recording if objects changed since).
Status VulkanDevice::doReplayCall(const RenderPassDesc* pass, std::span<const DrawDesc> draws, const DispatchDesc* dispatch) {
    flattenCall(pass, draws, dispatch, callScratch_);
    const std::vector<uint64_t>& recorded = recordings_.get(replayedRecording()).calls;
    if (replayMatches_ && replayCursor_ + callScratch_.size() <= recorded.size() &&
        std::equal(callScratch_.begin(), callScratch_.end(), recorded.begin() + std::ptrdiff_t(replayCursor_)))
        replayCursor_ += callScratch_.size();
    else
        replayMatches_ = false;
    return Status::ok();
}

bool VulkanDevice::noteTimer() {
    if (recordingOpen()) {
        open_.reusable = false;
        open_.why = "it holds a timer";
    }
    if (recordingState() != RecordingState::Replaying) return false;
    replayMatches_ = false;  // the calls are made again, recorded, with the timer in its place
    return true;
}

void VulkanDevice::noteRecordedUse(VulkanTexture* texture, uint32_t mip, VulkanBuffer* buffer, VkImageLayout layout, VkPipelineStageFlags stages,
                                   VkAccessFlags access, bool write) {
    AccessState& s = stateOf(texture, mip, buffer);
    if (s.recordingSerial != recordingSerial_) {
        s.recordingSerial = recordingSerial_;
        s.recordingEntry = uint32_t(open_.resources.size());
        RecordedResource r;
        r.texture = texture;
        r.mip = mip;
        r.buffer = buffer;
        r.entry = s;
        open_.resources.push_back(r);
    }
    RecordedResource& r = open_.resources[s.recordingEntry];
    r.stages |= stages;
    r.access |= access;
    r.written = r.written || write || (texture && s.layout != layout);
}

Result<VkCommandBuffer> VulkanDevice::writeRecording(const AccessState& s) {
    if (!usedByOpenRecording(s)) return primaryRecording();
    open_.reusable = false;
    open_.why = "it wrote a resource it had used before";
    return open_.commandBuffer;
}

}  // namespace sfx::vulkan
