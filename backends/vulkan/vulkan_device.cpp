// The Vulkan backend's HAL calls: each checks its arguments (the shared sfx::validation, and the
// backend's own checks in vulkan_checks.cpp) and delegates to the file that owns the concern
// (see vulkan_device_impl.hpp). Timers are in vulkan_timers.cpp and flush in vulkan_commands.cpp.
#include "sfx/hal_validation.hpp"
#include "vulkan_checks.hpp"
#include "vulkan_device_impl.hpp"

namespace sfx::vulkan {

// ---- Textures and samplers -----------------------------------------------------------------

Result<TextureHandle> VulkanDevice::createTexture(const TextureDesc& desc) {
    SFX_TRY(validation::textureDesc(desc, caps_));
    return makeTexture(desc);
}

Status VulkanDevice::destroyTexture(TextureHandle h) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture t = textures_.remove(h);
    clearSetCache();  // sets may name its views
    retire(t);
    releaseIdleGarbage();
    return Status::ok();
}

Status VulkanDevice::writeTexture(TextureHandle h, uint32_t mip, const void* data, size_t bytes) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture& t = textures_.get(h);
    SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
    if (!data) return invalidArgument("data", "null", "a pointer to the level's bytes");
    return uploadTexture(t, mip, data, bytes);
}

Status VulkanDevice::readTexture(TextureHandle h, uint32_t mip, void* out, size_t bytes) {
    SFX_TRY(textures_.check(h, "texture"));
    VulkanTexture& t = textures_.get(h);
    SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
    if (!out) return invalidArgument("out", "null", "a pointer to the level's bytes");
    SFX_TRY(noHostCommandBuffer("readTexture"));
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
    SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "writeBuffer range"));
    if (!data) return invalidArgument("data", "null", "a pointer to the bytes to write");
    return stageBufferWrite(b, offset, data, bytes);
}

Status VulkanDevice::readBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) {
    SFX_TRY(buffers_.check(h, "buffer"));
    VulkanBuffer& b = buffers_.get(h);
    SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "readBuffer range"));
    if (!out) return invalidArgument("out", "null", "a pointer for the bytes read");
    SFX_TRY(noHostCommandBuffer("readBuffer"));
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
    if (prog.compute) return Status{StatusCode::InvalidArgument, "GraphicsPipelineDesc.program is a compute program"};
    SFX_TRY(validation::graphicsPipelineShape(desc, caps_));
    SFX_TRY(validation::graphicsPipelineState(desc, caps_));
    return makeGraphicsPipeline(desc, prog);
}

Result<PipelineHandle> VulkanDevice::createComputePipeline(const ComputePipelineDesc& desc) {
    SFX_TRY(programs_.check(desc.program, "ComputePipelineDesc.program"));
    const VulkanProgram& prog = programs_.get(desc.program);
    if (!prog.compute) return Status{StatusCode::InvalidArgument, "ComputePipelineDesc.program is not a compute program"};
    SFX_TRY(validation::specializationConstants(desc.constants, "ComputePipelineDesc"));
    return makeComputePipeline(desc, prog);
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
    PassTargets targets;
    SFX_TRY(checkAttachments(pass, textures_, caps_, targets));
    std::vector<ResolvedBindings> resolved(draws.size());
    for (size_t i = 0; i < draws.size(); ++i) {
        const DrawDesc& d = draws[i];
        SFX_TRY(pipelines_.check(d.pipeline, "DrawDesc.pipeline"));
        const VulkanPipeline& pl = pipelines_.get(d.pipeline);
        if (pl.compute) return invalidArgument("DrawDesc.pipeline", "a compute pipeline", "a graphics pipeline");
        SFX_TRY(checkPipelineAttachments(pl, targets));
        SFX_TRY(resolveBindings(d.bindings, pl, "DrawDesc.bindings", targets.uses, resolved[i]));
        SFX_TRY(validation::noFeedbackLoop(pass, d));
        const BufferDesc* vertexBuffer = nullptr;
        const BufferDesc* indexBuffer = nullptr;
        if (pl.usesVertexBuffer || !d.vertexBuffer.isNull()) {
            SFX_TRY(buffers_.check(d.vertexBuffer, "DrawDesc.vertexBuffer"));
            VulkanBuffer& b = buffers_.get(d.vertexBuffer);
            vertexBuffer = &b.desc;
            targets.uses.buffers.push_back({&b, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT, VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT, false});
        }
        if (!d.indexBuffer.isNull()) {
            SFX_TRY(buffers_.check(d.indexBuffer, "DrawDesc.indexBuffer"));
            VulkanBuffer& b = buffers_.get(d.indexBuffer);
            indexBuffer = &b.desc;
            targets.uses.buffers.push_back({&b, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT, VK_ACCESS_INDEX_READ_BIT, false});
        }
        SFX_TRY(validation::drawRange(d, pl.vertexLayout, vertexBuffer, indexBuffer));
    }
    SFX_TRY(checkLayoutConflicts(targets.uses.images));
    return recordRenderPass(pass, draws, targets, resolved);
}

Status VulkanDevice::dispatch(const DispatchDesc& d) {
    SFX_TRY(validation::dispatchGroups(d, caps_));
    SFX_TRY(pipelines_.check(d.pipeline, "DispatchDesc.pipeline"));
    const VulkanPipeline& pl = pipelines_.get(d.pipeline);
    if (!pl.compute) return invalidArgument("DispatchDesc.pipeline", "a graphics pipeline", "a compute pipeline");
    Uses uses;
    ResolvedBindings resolved;
    SFX_TRY(resolveBindings(d.bindings, pl, "DispatchDesc.bindings", uses, resolved));
    SFX_TRY(checkLayoutConflicts(uses.images));
    return recordDispatch(d, pl, uses, resolved);
}

}  // namespace sfx::vulkan
