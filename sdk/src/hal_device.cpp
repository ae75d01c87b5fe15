// Device's front end: each public call runs the shared checks once, in the same order on every
// backend (the handle, then the description against the caps and limits, then what the handle's
// record says: sizes, reflection, pipeline formats), and only then calls the backend's hook.
// The order is what the validation parity tests pin: the first failing rule names the error.
#include "sfx/hal.hpp"
#include "sfx/hal_validation.hpp"

#include <utility>

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
    SFX_TRY(notWhileRecording("readTexture"));  // a read submits what was recorded
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
    SFX_TRY(notWhileRecording("readBuffer"));
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
    if (recordingState_ == RecordingState::Replaying) return doReplayCall(&pass, draws, nullptr);
    SFX_TRY(validation::renderPass(pass, draws, objects(), caps()));
    return doRenderPass(pass, draws);
}

Status Device::dispatch(const DispatchDesc& dispatch) {
    if (recordingState_ == RecordingState::Replaying) return doReplayCall(nullptr, {}, &dispatch);
    SFX_TRY(validation::dispatch(dispatch, objects(), caps()));
    return doDispatch(dispatch);
}

Status Device::flush() {
    SFX_TRY(notWhileRecording("flush"));
    return doFlush();
}

// ---- Reusable recordings -------------------------------------------------------------------
// The open recording or replay is the front end's state, so every backend refuses the same
// calls in the same order: the device keeps recordings, then nothing else is open (or the
// right kind is), then the handle.

Status Device::recordingsKept(const char* call) const {
    if (caps().reusableRecordings) return Status::ok();
    return {StatusCode::UnsupportedFeature,
            std::string(call) + ": the " + toString(caps().backend) + " device keeps no reusable recordings (caps().reusableRecordings is false)"};
}

Status Device::notWhileRecording(const char* call) const {
    if (recordingState_ == RecordingState::None) return Status::ok();
    const bool recording = recordingState_ == RecordingState::Recording;
    return {
        StatusCode::InvalidArgument,
        std::string(call) + ": a " + (recording ? "recording" : "replay") + " is open; allowed after " + (recording ? "endRecording" : "endReplay")};
}

Status Device::beginRecording() {
    SFX_TRY(recordingsKept("beginRecording"));
    SFX_TRY(notWhileRecording("beginRecording"));
    SFX_TRY(doBeginRecording());
    recordingState_ = RecordingState::Recording;
    return Status::ok();
}

Result<RecordingHandle> Device::endRecording() {
    SFX_TRY(recordingsKept("endRecording"));
    if (recordingState_ != RecordingState::Recording)
        return Status{StatusCode::InvalidArgument, "endRecording: no recording is open; allowed after beginRecording"};
    recordingState_ = RecordingState::None;
    return doEndRecording();
}

Status Device::beginReplay(RecordingHandle recording) {
    SFX_TRY(recordingsKept("beginReplay"));
    SFX_TRY(notWhileRecording("beginReplay"));
    SFX_TRY(objects().recording(recording, "recording"));
    SFX_TRY(doBeginReplay(recording));
    recordingState_ = RecordingState::Replaying;
    replayed_ = recording;
    return Status::ok();
}

Status Device::endReplay() {
    SFX_TRY(recordingsKept("endReplay"));
    if (recordingState_ != RecordingState::Replaying) return {StatusCode::InvalidArgument, "endReplay: no replay is open; allowed after beginReplay"};
    recordingState_ = RecordingState::None;
    const RecordingHandle replayed = std::exchange(replayed_, RecordingHandle{});
    return doEndReplay(replayed);
}

Status Device::destroyRecording(RecordingHandle recording) {
    SFX_TRY(recordingsKept("destroyRecording"));
    SFX_TRY(objects().recording(recording, "recording"));
    if (recordingState_ == RecordingState::Replaying && recording == replayed_)
        return {StatusCode::InvalidArgument, "destroyRecording: the recording is being replayed; allowed after endReplay"};
    return doDestroyRecording(recording);
}

// Reached only on a device that keeps recordings (the front end refuses first elsewhere).
Status Device::doBeginRecording() { return recordingsKept("beginRecording"); }
Result<RecordingHandle> Device::doEndRecording() { return recordingsKept("endRecording"); }
Status Device::doBeginReplay(RecordingHandle) { return recordingsKept("beginReplay"); }
Status Device::doEndReplay(RecordingHandle) { return recordingsKept("endReplay"); }
Status Device::doDestroyRecording(RecordingHandle) { return recordingsKept("destroyRecording"); }
Status Device::doReplayCall(const RenderPassDesc*, std::span<const DrawDesc>, const DispatchDesc*) { return recordingsKept("beginReplay"); }

}  // namespace sfx
