// Commands and submission: the device's own command buffer (begun on the first command after a
// flush, submitted and waited for by the next flush or read), or the host's command buffer while
// one is set; and the recording of render passes and dispatches whose arguments the device has
// already checked.
#include "vulkan_device_impl.hpp"
#include "vulkan_formats.hpp"

namespace sfx::vulkan {

Status VulkanDevice::noHostCommandBuffer(const char* call) const {
    // Vulkan only: only the Vulkan backend records into a host's command buffer.
    if (hostCommandBuffer_) return validation::fail(validation::Error::HostCommandBufferRead, {call});
    return Status::ok();
}

Result<VkCommandBuffer> VulkanDevice::allocateCommandBuffer(VkCommandBufferLevel level) {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = commandPool_;
    ai.level = level;
    ai.commandBufferCount = 1;
    VkCommandBuffer cb = VK_NULL_HANDLE;
    SFX_VK(vk_.vkAllocateCommandBuffers(device_, &ai, &cb));
    return cb;
}

Result<VkCommandBuffer> VulkanDevice::recording() {
    if (recordingOpen()) return open_.commandBuffer;
    return primaryRecording();
}

Result<VkCommandBuffer> VulkanDevice::primaryRecording() {
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

Status VulkanDevice::submitAndWait() {
    if (!recording_) return Status::ok();
    handBackExternal(commandBuffer_);
    recording_ = false;
    SFX_VK(vk_.vkEndCommandBuffer(commandBuffer_));
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &commandBuffer_;
    SFX_VK(vk_.vkQueueSubmit(queue_, 1, &si, fence_));
    SFX_VK(vk_.vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
    const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - recordStart_).count();
    SFX_VK(vk_.vkResetFences(device_, 1, &fence_));
    SFX_VK(vk_.vkResetCommandBuffer(commandBuffer_, 0));
    recycleStaging(stagingOwn_);
    releaseGarbage(pending_);
    markEndedTimersFlushed(false, wallMs);
    return Status::ok();
}

Status VulkanDevice::doFlush() {
    if (hostCommandBuffer_) {
        // The host ends and submits its command buffer; what it used (garbage, staging blocks)
        // lives until it is done, which the next setCommandBuffer may assume.
        handBackExternal(hostCommandBuffer_);
        hostCommandBuffer_ = VK_NULL_HANDLE;
        markEndedTimersFlushed(true, 0);
        return Status::ok();
    }
    return submitAndWait();
}

Status VulkanDevice::setHostCommandBuffer(VkCommandBuffer cb, bool previousFinished) {
    SFX_TRY(notWhileRecording("setCommandBuffer"));
    if (hostCommandBuffer_) SFX_TRY(flush());  // detach the previous one
    // Work recorded on our own command buffer comes first.
    SFX_TRY(submitAndWait());
    // The previous host command buffers have finished by now (documented contract), unless the
    // host says it attaches again before submitting them: then their staging and garbage wait.
    if (previousFinished) {
        releaseGarbage(hostPending_);
        recycleStaging(stagingHost_);
    }
    hostCommandBuffer_ = cb;
    return Status::ok();
}

void VulkanDevice::passTargets(const RenderPassDesc& pass, PassTargets& out) {
    out.clear();
    for (const ColorAttachment& c : pass.colors) {
        VulkanTexture& t = textures_.get(c.texture);
        if (out.width == 0) {
            out.width = mipExtent(t.desc.width, c.mip);
            out.height = mipExtent(t.desc.height, c.mip);
        }
        out.colorFormats.push_back(t.desc.format);
        out.uses.images.push_back({&t, c.mip, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                   VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, true});
    }
    if (!pass.depth.texture.isNull()) {
        VulkanTexture& depth = textures_.get(pass.depth.texture);
        if (out.width == 0) {
            out.width = depth.desc.width;
            out.height = depth.desc.height;
        }
        out.depth = &depth;
        out.depthFormat = depth.desc.format;
        out.uses.images.push_back({&depth, 0, 1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, true});
    }
}

Status VulkanDevice::recordRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws, const PassTargets& targets,
                                      std::span<ResolvedBindings> resolved) {
    // Views before recording, so that a failure leaves the command buffer untouched.
    std::vector<VkImageView>& colorViews = scratch_.colorViews;
    colorViews.clear();
    for (const ColorAttachment& c : pass.colors) {
        Result<VkImageView> v = attachmentView(textures_.get(c.texture), c.mip);
        if (!v) return v.status();
        colorViews.push_back(v.value());
    }
    VkImageView depthView = VK_NULL_HANDLE;
    if (targets.depth) {
        Result<VkImageView> v = attachmentView(*targets.depth, 0);
        if (!v) return v.status();
        depthView = v.value();
    }
    std::vector<VkDescriptorSet>& sets = scratch_.sets;
    sets.assign(draws.size(), VK_NULL_HANDLE);
    for (size_t i = 0; i < draws.size(); ++i) {
        Result<VkDescriptorSet> set = writeSet(pipelines_.get(draws[i].pipeline), resolved[i]);
        if (!set) return set.status();
        sets[i] = set.value();
    }

    Result<VkCommandBuffer> cbr = recording();
    if (!cbr) return cbr.status();
    VkCommandBuffer cb = cbr.value();
    barriers(cb, targets.uses);

    auto loadOp = [](LoadOp op) {
        return op == LoadOp::Clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : op == LoadOp::Load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    };
    std::vector<VkRenderingAttachmentInfo>& colorInfos = scratch_.colorInfos;
    colorInfos.clear();
    for (size_t i = 0; i < pass.colors.size(); ++i) {
        const ColorAttachment& c = pass.colors[i];
        VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        a.imageView = colorViews[i];
        a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a.loadOp = loadOp(c.load);
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        if (isIntegerFormat(targets.colorFormats[i])) {
            for (int k = 0; k < 4; ++k) a.clearValue.color.uint32[k] = c.clearColor[k] > 0 ? uint32_t(c.clearColor[k]) : 0u;
        } else {
            for (int k = 0; k < 4; ++k) a.clearValue.color.float32[k] = c.clearColor[k];
        }
        colorInfos.push_back(a);
    }
    VkRenderingAttachmentInfo depthInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    if (targets.depth) {
        depthInfo.imageView = depthView;
        depthInfo.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        depthInfo.loadOp = loadOp(pass.depth.load);
        depthInfo.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depthInfo.clearValue.depthStencil = {pass.depth.clearDepth, 0};
    }
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {targets.width, targets.height}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = uint32_t(colorInfos.size());
    ri.pColorAttachments = colorInfos.data();
    ri.pDepthAttachment = targets.depth ? &depthInfo : nullptr;
    vk_.vkCmdBeginRendering(cb, &ri);
    // Positive height: NDC y = -1 lands on row 0, as on GL (see hal.hpp).
    VkViewport viewport{0, 0, float(targets.width), float(targets.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {targets.width, targets.height}};
    vk_.vkCmdSetViewport(cb, 0, 1, &viewport);
    vk_.vkCmdSetScissor(cb, 0, 1, &scissor);
    for (size_t i = 0; i < draws.size(); ++i) {
        const DrawDesc& d = draws[i];
        const VulkanPipeline& pl = pipelines_.get(d.pipeline);
        vk_.vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pl.pipeline);
        if (sets[i]) vk_.vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pl.layout, 0, 1, &sets[i], 0, nullptr);
        if (pl.usesVertexBuffer()) {
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

Status VulkanDevice::recordDispatch(const DispatchDesc& d, const VulkanPipeline& pl, const Uses& uses, ResolvedBindings& resolved) {
    Result<VkDescriptorSet> s = writeSet(pl, resolved);
    if (!s) return s.status();
    const VkDescriptorSet set = s.value();
    Result<VkCommandBuffer> cbr = recording();
    if (!cbr) return cbr.status();
    VkCommandBuffer cb = cbr.value();
    barriers(cb, uses);
    vk_.vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pl.pipeline);
    if (set) vk_.vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pl.layout, 0, 1, &set, 0, nullptr);
    vk_.vkCmdDispatch(cb, d.groupsX, d.groupsY, d.groupsZ);
    return Status::ok();
}

}  // namespace sfx::vulkan
