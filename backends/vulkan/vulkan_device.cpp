// The Vulkan backend's HAL calls: each checks its arguments with the shared sfx::validation (the
// Vulkan-only checks are SPIR-V validation, in vulkan_pipelines.cpp, and the host command buffer's
// limits, in vulkan_commands.cpp and vulkan_timers.cpp) and delegates to the file that owns the
// concern (see vulkan_device_impl.hpp). Timers are in vulkan_timers.cpp, flush in vulkan_commands.cpp.
#include "sfx/hal_validation.hpp"
#include "vulkan_device_impl.hpp"

namespace sfx::vulkan {

// ---- Textures and samplers -----------------------------------------------------------------

Result<TextureHandle> VulkanDevice::createTexture(const TextureDesc& desc) {
    SFX_TRY(validation::textureDesc(desc, caps_));
    changeObjects();
    return makeTexture(desc);
}

Status VulkanDevice::destroyTexture(TextureHandle h) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture t = textures_.remove(h);
    if (t.external) SFX_TRY(forgetExternal(h, t));  // back in the host's layout first
    clearSetCache();  // sets may name its views
    retire(t);
    releaseIdleGarbage();
    return Status::ok();
}

Status VulkanDevice::writeTexture(TextureHandle h, uint32_t mip, const void* data, size_t bytes) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture& t = textures_.get(h);
    SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
    SFX_TRY(validation::pointer(data, "data", "the level's bytes"));
    return uploadTexture(t, mip, data, bytes);
}

Status VulkanDevice::readTexture(TextureHandle h, uint32_t mip, void* out, size_t bytes) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture& t = textures_.get(h);
    SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
    SFX_TRY(validation::pointer(out, "out", "the level's bytes"));
    SFX_TRY(noHostCommandBuffer("readTexture"));
    SFX_TRY(notWhileRecording("readTexture"));
    return downloadTexture(t, mip, out, bytes);
}

Result<SamplerHandle> VulkanDevice::createSampler(const SamplerDesc& desc) {
    SFX_TRY(validation::samplerDesc(desc));
    return makeSampler(desc);
}

Status VulkanDevice::destroySampler(SamplerHandle h) {
    SFX_TRY(samplers_.check(h, "sampler"));
    clearSetCache();
    currentGarbage().samplers.push_back(samplers_.remove(h));
    releaseIdleGarbage();
    return Status::ok();
}

// ---- Buffers -------------------------------------------------------------------------------

Result<BufferHandle> VulkanDevice::createBuffer(const BufferDesc& desc) {
    SFX_TRY(validation::bufferDesc(desc, caps_));
    changeObjects();
    return makeHalBuffer(desc);
}

Status VulkanDevice::destroyBuffer(BufferHandle h) {
    SFX_TRY(buffers_.check(h, "buffer"));
    VulkanBuffer b = buffers_.remove(h);
    clearSetCache();
    retire(b, currentGarbage());
    releaseIdleGarbage();
    return Status::ok();
}

Status VulkanDevice::writeBuffer(BufferHandle h, uint64_t offset, const void* data, size_t bytes) {
    SFX_TRY(buffers_.check(h, "buffer"));
    VulkanBuffer& b = buffers_.get(h);
    SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "writeBuffer(offset, bytes)"));
    SFX_TRY(validation::pointer(data, "data", "the bytes to write"));
    return stageBufferWrite(b, offset, data, bytes);
}

Status VulkanDevice::readBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) {
    SFX_TRY(buffers_.check(h, "buffer"));
    VulkanBuffer& b = buffers_.get(h);
    SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "readBuffer(offset, bytes)"));
    SFX_TRY(validation::pointer(out, "out", "room for the bytes read"));
    SFX_TRY(noHostCommandBuffer("readBuffer"));
    SFX_TRY(notWhileRecording("readBuffer"));
    return readBackBuffer(b, offset, out, bytes);
}

// ---- Programs and pipelines ----------------------------------------------------------------

Result<ProgramHandle> VulkanDevice::createProgram(const CompiledProgram& program) {
    SFX_TRY(validation::program(program, caps_));
    for (const StageCode& s : program.stages) SFX_TRY(validateSpirv(program, s));
    return makeProgram(program);
}

Status VulkanDevice::destroyProgram(ProgramHandle h) {
    SFX_TRY(programs_.check(h, "program"));
    // Pipelines made from it have their own layouts and need no module after creation.
    VulkanProgram p = programs_.remove(h);
    for (auto& m : p.modules) currentGarbage().modules.push_back(m.second);
    releaseIdleGarbage();
    return Status::ok();
}

Result<PipelineHandle> VulkanDevice::createGraphicsPipeline(const GraphicsPipelineDesc& desc) {
    SFX_TRY(programs_.check(desc.program, "GraphicsPipelineDesc.program"));
    const VulkanProgram& prog = programs_.get(desc.program);
    Result<validation::PipelineInfo> info = validation::graphicsPipeline(desc, prog.info, caps_);
    if (!info) return info.status();
    return makeGraphicsPipeline(desc, prog, std::move(info.value()));
}

Result<PipelineHandle> VulkanDevice::createComputePipeline(const ComputePipelineDesc& desc) {
    SFX_TRY(programs_.check(desc.program, "ComputePipelineDesc.program"));
    const VulkanProgram& prog = programs_.get(desc.program);
    Result<validation::PipelineInfo> info = validation::computePipeline(desc, prog.info);
    if (!info) return info.status();
    return makeComputePipeline(desc, prog, std::move(info.value()));
}

Status VulkanDevice::destroyPipeline(PipelineHandle h) {
    SFX_TRY(pipelines_.check(h, "pipeline"));
    VulkanPipeline p = pipelines_.remove(h);
    clearSetCache();  // sets of its set layout
    retire(p);
    releaseIdleGarbage();
    return Status::ok();
}

// ---- Commands ------------------------------------------------------------------------------

Status VulkanDevice::renderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) {
    // Replaying: checked when it was recorded (the same arguments on the same objects pass again).
    if (noteCall(&pass, draws, nullptr)) return Status::ok();
    SFX_TRY(validation::renderPass(pass, draws, validation::PoolLookup(textures_, buffers_, samplers_, pipelines_), caps_));
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
            targets.uses.buffers.push_back({&buffers_.get(d.vertexBuffer), VK_PIPELINE_STAGE_VERTEX_INPUT_BIT,
                                            VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT, false});
        if (!d.indexBuffer.isNull())
            targets.uses.buffers.push_back({&buffers_.get(d.indexBuffer), VK_PIPELINE_STAGE_VERTEX_INPUT_BIT,
                                            VK_ACCESS_INDEX_READ_BIT, false});
    }
    return recordRenderPass(pass, draws, targets, resolved);
}

Status VulkanDevice::dispatch(const DispatchDesc& d) {
    if (noteCall(nullptr, {}, &d)) return Status::ok();
    SFX_TRY(validation::dispatch(d, validation::PoolLookup(textures_, buffers_, samplers_, pipelines_), caps_));
    const VulkanPipeline& pl = pipelines_.get(d.pipeline);
    Uses& uses = scratch_.dispatchUses;
    uses.images.clear();
    uses.buffers.clear();
    if (scratch_.resolved.empty()) scratch_.resolved.resize(1);
    ResolvedBindings& resolved = scratch_.resolved[0];
    SFX_TRY(resolveBindings(d.bindings, pl, uses, resolved));
    return recordDispatch(d, pl, uses, resolved);
}

}  // namespace sfx::vulkan
