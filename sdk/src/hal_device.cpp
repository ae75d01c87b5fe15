// Device's front end: each public call runs the shared checks once, in the same order on every
// backend (the handle, then the description against the caps and limits, then what the handle's
// record says: sizes, reflection, pipeline formats), and only then calls the backend's hook.
// The order is what the validation parity tests pin: the first failing rule names the error.
#include "sfx/hal.hpp"
#include "sfx/hal_validation.hpp"

namespace sfx {

// ---- Textures, buffers, samplers -----------------------------------------------------------

Result<TextureHandle> Device::createTexture(const TextureDesc& desc) {
    SFX_TRY(validation::textureDesc(desc, caps()));
    return doCreateTexture(desc);
}

Status Device::destroyTexture(TextureHandle texture) {
    SFX_TRY(objects().texture(texture, "texture").status());
    return doDestroyTexture(texture);
}

Result<TextureDesc> Device::textureDesc(TextureHandle texture) const {
    Result<const TextureDesc*> desc = objects().texture(texture, "texture");
    if (!desc) return desc.status();
    return *desc.value();
}

Status Device::writeTexture(TextureHandle texture, uint32_t mip, const void* data, size_t bytes) {
    Result<const TextureDesc*> desc = objects().texture(texture, "texture");
    if (!desc) return desc.status();
    SFX_TRY(validation::textureBytes(*desc.value(), mip, bytes, "bytes"));
    SFX_TRY(validation::pointer(data, "data", "the level's bytes"));
    return doWriteTexture(texture, mip, data, bytes);
}

Status Device::readTexture(TextureHandle texture, uint32_t mip, void* out, size_t bytes) {
    Result<const TextureDesc*> desc = objects().texture(texture, "texture");
    if (!desc) return desc.status();
    SFX_TRY(validation::textureBytes(*desc.value(), mip, bytes, "bytes"));
    SFX_TRY(validation::pointer(out, "out", "the level's bytes"));
    return doReadTexture(texture, mip, out, bytes);
}

Result<BufferHandle> Device::createBuffer(const BufferDesc& desc) {
    SFX_TRY(validation::bufferDesc(desc, caps()));
    return doCreateBuffer(desc);
}

Status Device::destroyBuffer(BufferHandle buffer) {
    SFX_TRY(objects().buffer(buffer, "buffer").status());
    return doDestroyBuffer(buffer);
}

Status Device::writeBuffer(BufferHandle buffer, uint64_t offset, const void* data, size_t bytes) {
    Result<const BufferDesc*> desc = objects().buffer(buffer, "buffer");
    if (!desc) return desc.status();
    SFX_TRY(validation::bufferRange(*desc.value(), offset, bytes, "writeBuffer(offset, bytes)"));
    SFX_TRY(validation::pointer(data, "data", "the bytes to write"));
    return doWriteBuffer(buffer, offset, data, bytes);
}

Status Device::readBuffer(BufferHandle buffer, uint64_t offset, void* out, size_t bytes) {
    Result<const BufferDesc*> desc = objects().buffer(buffer, "buffer");
    if (!desc) return desc.status();
    SFX_TRY(validation::bufferRange(*desc.value(), offset, bytes, "readBuffer(offset, bytes)"));
    SFX_TRY(validation::pointer(out, "out", "room for the bytes read"));
    return doReadBuffer(buffer, offset, out, bytes);
}

Result<SamplerHandle> Device::createSampler(const SamplerDesc& desc) {
    SFX_TRY(validation::samplerDesc(desc));
    return doCreateSampler(desc);
}

Status Device::destroySampler(SamplerHandle sampler) {
    SFX_TRY(objects().sampler(sampler, "sampler").status());
    return doDestroySampler(sampler);
}

// ---- Programs and pipelines ----------------------------------------------------------------

Result<ProgramHandle> Device::createProgram(const CompiledProgram& program) {
    // Names what the device lacks before the backend looks at the dialect's text.
    SFX_TRY(validation::program(program, caps()));
    return doCreateProgram(program);
}

Status Device::destroyProgram(ProgramHandle program) {
    SFX_TRY(objects().program(program, "program").status());
    return doDestroyProgram(program);
}

Result<PipelineHandle> Device::createGraphicsPipeline(const GraphicsPipelineDesc& desc) {
    Result<const validation::ProgramInfo*> program = objects().program(desc.program, "GraphicsPipelineDesc.program");
    if (!program) return program.status();
    Result<validation::PipelineInfo> info = validation::graphicsPipeline(desc, *program.value(), caps());
    if (!info) return info.status();
    return doCreateGraphicsPipeline(desc, std::move(info.value()));
}

Result<PipelineHandle> Device::createComputePipeline(const ComputePipelineDesc& desc) {
    Result<const validation::ProgramInfo*> program = objects().program(desc.program, "ComputePipelineDesc.program");
    if (!program) return program.status();
    Result<validation::PipelineInfo> info = validation::computePipeline(desc, *program.value());
    if (!info) return info.status();
    return doCreateComputePipeline(desc, std::move(info.value()));
}

Status Device::destroyPipeline(PipelineHandle pipeline) {
    SFX_TRY(objects().pipeline(pipeline, "pipeline").status());
    return doDestroyPipeline(pipeline);
}

// ---- Timers --------------------------------------------------------------------------------

Result<TimerHandle> Device::createTimer() { return doCreateTimer(); }

Status Device::destroyTimer(TimerHandle timer) {
    SFX_TRY(objects().timer(timer, "timer"));
    return doDestroyTimer(timer);
}

Status Device::beginTimer(TimerHandle timer) {
    SFX_TRY(objects().timer(timer, "timer"));
    return doBeginTimer(timer);
}

// Whether the timer was begun, and readTimer's whether it holds a measurement, are the backend's
// state (a Vulkan timer inside a replay is neither): the hooks report them.
Status Device::endTimer(TimerHandle timer) {
    SFX_TRY(objects().timer(timer, "timer"));
    return doEndTimer(timer);
}

Result<TimerReading> Device::readTimer(TimerHandle timer) {
    SFX_TRY(objects().timer(timer, "timer"));
    return doReadTimer(timer);
}

// ---- Commands ------------------------------------------------------------------------------

Status Device::renderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) {
    if (doReplayCall(&pass, draws, nullptr)) return Status::ok();
    SFX_TRY(validation::renderPass(pass, draws, objects(), caps()));
    return doRenderPass(pass, draws);
}

Status Device::dispatch(const DispatchDesc& dispatch) {
    if (doReplayCall(nullptr, {}, &dispatch)) return Status::ok();
    SFX_TRY(validation::dispatch(dispatch, objects(), caps()));
    return doDispatch(dispatch);
}

Status Device::flush() { return doFlush(); }

}  // namespace sfx
