#include "fault_injection.hpp"

#include <string>

namespace sfx::test {

void FaultInjectingDevice::failCreation(uint64_t k) {
    clearFaults();
    fault_ = Fault::Creation;
    at_ = k;
}

void FaultInjectingDevice::failSubmit(uint64_t k) {
    clearFaults();
    fault_ = Fault::Submit;
    at_ = k;
}

void FaultInjectingDevice::loseDevice(uint64_t k) {
    clearFaults();
    fault_ = Fault::Loss;
    at_ = k;
}

void FaultInjectingDevice::clearFaults() {
    fault_ = Fault::None;
    at_ = 0;
    armedCreations_ = armedSubmits_ = armedCalls_ = 0;
    fired_ = lost_ = false;
}

Status FaultInjectingDevice::enter(const char* what, bool creation, bool submit) {
    ++calls_;
    creations_ += creation ? 1 : 0;
    submits_ += submit ? 1 : 0;
    if (fault_ == Fault::None) return {};
    ++armedCalls_;
    armedCreations_ += creation ? 1 : 0;
    armedSubmits_ += submit ? 1 : 0;
    if (fault_ == Fault::Loss && (lost_ || armedCalls_ == at_)) {
        fired_ = lost_ = true;
        return {StatusCode::DeviceError, std::string(what) + ": device lost (injected fault)"};
    }
    if (fault_ == Fault::Creation && creation && armedCreations_ == at_) {
        fired_ = true;
        return {StatusCode::DeviceError, std::string(what) + ": out of device memory (injected fault)"};
    }
    if (fault_ == Fault::Submit && submit && armedSubmits_ == at_) {
        fired_ = true;
        return {StatusCode::DeviceError, std::string(what) + ": submit failed (injected fault)"};
    }
    return {};
}

Result<TextureHandle> FaultInjectingDevice::doCreateTexture(const TextureDesc& desc) {
    if (Status s = enter("createTexture", true, false); !s) return s;
    return inner_.createTexture(desc);
}

Status FaultInjectingDevice::doWriteTexture(TextureHandle texture, uint32_t mip, const void* data, size_t bytes) {
    if (Status s = enter("writeTexture", false, false); !s) return s;
    return inner_.writeTexture(texture, mip, data, bytes);
}

Status FaultInjectingDevice::doReadTexture(TextureHandle texture, uint32_t mip, void* out, size_t bytes) {
    if (Status s = enter("readTexture", false, true); !s) {
        // The recorded work is consumed all the same, as by a submit that failed on the GPU.
        (void)inner_.flush();
        return s;
    }
    return inner_.readTexture(texture, mip, out, bytes);
}

Result<BufferHandle> FaultInjectingDevice::doCreateBuffer(const BufferDesc& desc) {
    if (Status s = enter("createBuffer", true, false); !s) return s;
    return inner_.createBuffer(desc);
}

Status FaultInjectingDevice::doWriteBuffer(BufferHandle buffer, uint64_t offset, const void* data, size_t bytes) {
    if (Status s = enter("writeBuffer", false, false); !s) return s;
    return inner_.writeBuffer(buffer, offset, data, bytes);
}

Status FaultInjectingDevice::doReadBuffer(BufferHandle buffer, uint64_t offset, void* out, size_t bytes) {
    if (Status s = enter("readBuffer", false, true); !s) {
        (void)inner_.flush();
        return s;
    }
    return inner_.readBuffer(buffer, offset, out, bytes);
}

Result<SamplerHandle> FaultInjectingDevice::doCreateSampler(const SamplerDesc& desc) {
    if (Status s = enter("createSampler", true, false); !s) return s;
    return inner_.createSampler(desc);
}

Result<ProgramHandle> FaultInjectingDevice::doCreateProgram(const CompiledProgram& program) {
    if (Status s = enter("createProgram", true, false); !s) return s;
    if (!rewrite_) return inner_.createProgram(program);
    CompiledProgram edited = program;
    if (rewrite_(edited)) ++rewritten_;
    return inner_.createProgram(edited);
}

Result<PipelineHandle> FaultInjectingDevice::doCreateGraphicsPipeline(const GraphicsPipelineDesc& desc, validation::PipelineInfo) {
    if (Status s = enter("createGraphicsPipeline", true, false); !s) return s;
    return inner_.createGraphicsPipeline(desc);
}

Result<PipelineHandle> FaultInjectingDevice::doCreateComputePipeline(const ComputePipelineDesc& desc, validation::PipelineInfo) {
    if (Status s = enter("createComputePipeline", true, false); !s) return s;
    return inner_.createComputePipeline(desc);
}

Result<TimerHandle> FaultInjectingDevice::doCreateTimer() {
    if (Status s = enter("createTimer", true, false); !s) return s;
    return inner_.createTimer();
}

Status FaultInjectingDevice::doRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) {
    if (Status s = enter("renderPass", false, false); !s) return s;
    return inner_.renderPass(pass, draws);
}

Status FaultInjectingDevice::doDispatch(const DispatchDesc& dispatch) {
    if (Status s = enter("dispatch", false, false); !s) return s;
    return inner_.dispatch(dispatch);
}

Status FaultInjectingDevice::doBeginTimer(TimerHandle timer) {
    if (Status s = enter("beginTimer", false, false); !s) return s;
    return inner_.beginTimer(timer);
}

Status FaultInjectingDevice::doEndTimer(TimerHandle timer) {
    if (Status s = enter("endTimer", false, false); !s) return s;
    return inner_.endTimer(timer);
}

Status FaultInjectingDevice::doFlush() {
    if (Status s = enter("flush", false, true); !s) {
        (void)inner_.flush();
        return s;
    }
    return inner_.flush();
}

Result<TimerReading> FaultInjectingDevice::doReadTimer(TimerHandle timer) {
    if (Status s = enter("readTimer", false, false); !s) return s;
    return inner_.readTimer(timer);
}

Status FaultInjectingDevice::doBeginRecording() {
    if (Status s = enter("beginRecording", false, false); !s) return s;
    return inner_.beginRecording();
}

Status FaultInjectingDevice::doBeginReplay(RecordingHandle recording) {
    if (Status s = enter("beginReplay", false, false); !s) return s;
    return inner_.beginReplay(recording);
}

// A replayed call can meet a fault like any call; the wrapped device, replaying too, compares it.
Status FaultInjectingDevice::doReplayCall(const RenderPassDesc* pass, std::span<const DrawDesc> draws, const DispatchDesc* dispatch) {
    if (Status s = enter(pass ? "renderPass" : "dispatch", false, false); !s) return s;
    return pass ? inner_.renderPass(*pass, draws) : inner_.dispatch(*dispatch);
}

}  // namespace sfx::test
