// The Vulkan backend's hooks behind Device's front end, which has checked their arguments with the
// shared sfx::validation. What is left here is what only Vulkan can tell (SPIR-V structure, in
// vulkan_pipelines.cpp; the host command buffer's and an open recording's limits, in
// vulkan_commands.cpp and vulkan_timers.cpp); each hook delegates to the file that owns the concern
// (see vulkan_device_impl.hpp). Timers are in vulkan_timers.cpp, flush in vulkan_commands.cpp.
#include "sfx/hal_validation.hpp"
#include "vulkan_device_impl.hpp"

namespace sfx::vulkan {

// ---- Textures and samplers -----------------------------------------------------------------

Result<TextureHandle> VulkanDevice::doCreateTexture(const TextureDesc& desc) {
    changeObjects();
    return makeTexture(desc);
}

Status VulkanDevice::doDestroyTexture(TextureHandle h) {
    VulkanTexture t = textures_.remove(h);
    if (t.external) SFX_TRY(forgetExternal(h, t));  // back in the host's layout first
    clearSetCache();                                // sets may name its views
    retire(t);
    releaseIdleGarbage();
    return Status::ok();
}

Status VulkanDevice::doWriteTexture(TextureHandle h, uint32_t mip, const void* data, size_t bytes) {
    return uploadTexture(textures_.get(h), mip, data, bytes);
}

Status VulkanDevice::doReadTexture(TextureHandle h, uint32_t mip, void* out, size_t bytes) {
    SFX_TRY(noHostCommandBuffer("readTexture"));
    return downloadTexture(textures_.get(h), mip, out, bytes);
}

Result<SamplerHandle> VulkanDevice::doCreateSampler(const SamplerDesc& desc) { return makeSampler(desc); }

Status VulkanDevice::doDestroySampler(SamplerHandle h) {
    clearSetCache();
    currentGarbage().samplers.push_back(samplers_.remove(h).sampler);
    releaseIdleGarbage();
    return Status::ok();
}

// ---- Buffers -------------------------------------------------------------------------------

Result<BufferHandle> VulkanDevice::doCreateBuffer(const BufferDesc& desc) {
    changeObjects();
    return makeHalBuffer(desc);
}

Status VulkanDevice::doDestroyBuffer(BufferHandle h) {
    VulkanBuffer b = buffers_.remove(h);
    clearSetCache();
    retire(b, currentGarbage());
    releaseIdleGarbage();
    return Status::ok();
}

Status VulkanDevice::doWriteBuffer(BufferHandle h, uint64_t offset, const void* data, size_t bytes) {
    return stageBufferWrite(buffers_.get(h), offset, data, bytes);
}

Status VulkanDevice::doReadBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) {
    SFX_TRY(noHostCommandBuffer("readBuffer"));
    return readBackBuffer(buffers_.get(h), offset, out, bytes);
}

// ---- Programs and pipelines ----------------------------------------------------------------

Result<ProgramHandle> VulkanDevice::doCreateProgram(const CompiledProgram& program) {
    // Here, not in the front end: walking the SPIR-V's structure is Vulkan's concern alone.
    for (const StageCode& s : program.stages) SFX_TRY(validateSpirv(program, s));
    return makeProgram(program);
}

Status VulkanDevice::doDestroyProgram(ProgramHandle h) {
    // Pipelines made from it have their own layouts and need no module after creation.
    VulkanProgram p = programs_.remove(h);
    for (auto& m : p.modules) currentGarbage().modules.push_back(m.second);
    releaseIdleGarbage();
    return Status::ok();
}

Result<PipelineHandle> VulkanDevice::doCreateGraphicsPipeline(const GraphicsPipelineDesc& desc, validation::PipelineInfo info) {
    return makeGraphicsPipeline(desc, programs_.get(desc.program), std::move(info));
}

Result<PipelineHandle> VulkanDevice::doCreateComputePipeline(const ComputePipelineDesc& desc, validation::PipelineInfo info) {
    return makeComputePipeline(desc, programs_.get(desc.program), std::move(info));
}

Status VulkanDevice::doDestroyPipeline(PipelineHandle h) {
    VulkanPipeline p = pipelines_.remove(h);
    clearSetCache();  // sets of its set layout
    retire(p);
    releaseIdleGarbage();
    return Status::ok();
}

// ---- Commands ------------------------------------------------------------------------------

Status VulkanDevice::doRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) {
    PassTargets& targets = scratch_.targets;
    passTargets(pass, targets);
    std::vector<ResolvedBindings>& resolvedLists = scratch_.resolved;
    if (resolvedLists.size() < draws.size()) resolvedLists.resize(draws.size());
    const std::span<ResolvedBindings> resolved(resolvedLists.data(), draws.size());
    for (size_t i = 0; i < draws.size(); ++i) {
        const DrawDesc& d = draws[i];
        const VulkanPipeline& pl = pipelines_.get(d.pipeline);
        SFX_TRY(resolveBindings(d.bindings, pl, targets.uses, resolved[i]));
        // Vertex and index reads, for the barriers after what last wrote the buffers.
        if (!d.vertexBuffer.isNull())
            targets.uses.buffers.push_back(
                {&buffers_.get(d.vertexBuffer), VK_PIPELINE_STAGE_VERTEX_INPUT_BIT, VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT, false});
        if (!d.indexBuffer.isNull())
            targets.uses.buffers.push_back({&buffers_.get(d.indexBuffer), VK_PIPELINE_STAGE_VERTEX_INPUT_BIT, VK_ACCESS_INDEX_READ_BIT, false});
    }
    SFX_TRY(recordRenderPass(pass, draws, targets, resolved));
    noteRecordedCall(&pass, draws, nullptr);  // only a call that was recorded can match a replay
    return Status::ok();
}

Status VulkanDevice::doDispatch(const DispatchDesc& d) {
    const VulkanPipeline& pl = pipelines_.get(d.pipeline);
    Uses& uses = scratch_.dispatchUses;
    uses.images.clear();
    uses.buffers.clear();
    if (scratch_.resolved.empty()) scratch_.resolved.resize(1);
    ResolvedBindings& resolved = scratch_.resolved[0];
    SFX_TRY(resolveBindings(d.bindings, pl, uses, resolved));
    SFX_TRY(recordDispatch(d, pl, uses, resolved));
    noteRecordedCall(nullptr, {}, &d);
    return Status::ok();
}

}  // namespace sfx::vulkan
