// A test-only HAL decorator that makes a real device fail on purpose: the k-th resource creation
// (texture, buffer, sampler, program, pipeline or timer), the k-th submit (flush, or a read,
// which flushes first), or device loss from the k-th call on (every call after it fails, as
// on a GPU reset); or run a defect in its programs, which only a comparison with another device
// can see. Everything else is forwarded to the wrapped device, whose handles pass
// through unchanged, so the wrapped device's stats() tell whether a failed attempt leaked.
// Its own front end checks every call against the wrapped device's objects first, so a fault
// hits only calls that pass the checks, as a real device's failure would.
//
// Destroys are always forwarded, even after a simulated loss: releasing objects of a lost
// device is legal on every API (Vulkan requires it), and an effect that cleans up after an
// error must be able to.
#pragma once

#include <cstdint>
#include <functional>

#include "sfx/hal.hpp"
#include "sfx/hal_validation.hpp"

namespace sfx::test {

class FaultInjectingDevice final : public Device {
public:
    explicit FaultInjectingDevice(Device& inner) : inner_(inner) {}

    // Each arms one fault, counted from now (1 = the next one) and clears any other.
    void failCreation(uint64_t k);  // the k-th create* fails with DeviceError (out of memory)
    void failSubmit(uint64_t k);    // the k-th flush / readTexture / readBuffer fails with DeviceError
    void loseDevice(uint64_t k);    // the k-th call and every later one fail with DeviceError (device lost)
    void clearFaults();             // a working device again (after a loss too)

    // Counts since construction or the last resetCounts(): what a fault-free run goes through,
    // so a test knows the range of k.
    uint64_t creations() const { return creations_; }
    uint64_t submits() const { return submits_; }
    uint64_t calls() const { return calls_; }
    void resetCounts() { creations_ = submits_ = calls_ = 0; }
    bool faultFired() const { return fired_; }  // since the fault was armed
    bool lost() const { return lost_; }

    // A defect in what this one device runs (independent of the armed fault): `rewrite` edits a
    // copy of each program before the wrapped device creates it, and says whether it changed
    // anything (e.g. one line of a GL dialect's source). Empty: programs pass unchanged.
    void rewritePrograms(std::function<bool(CompiledProgram&)> rewrite) {
        rewrite_ = std::move(rewrite);
        rewritten_ = 0;
    }
    uint64_t rewrittenPrograms() const { return rewritten_; }  // since rewritePrograms

    Device& inner() { return inner_; }

    const DeviceCaps& caps() const override { return inner_.caps(); }

    DeviceStats stats() const override { return inner_.stats(); }
    std::vector<std::string> takeValidationMessages() override { return inner_.takeValidationMessages(); }

private:
    // Device's front end checks each call against the wrapped device's objects; a hook then
    // injects its fault or forwards the call to the wrapped device's public call.
    const validation::ObjectLookup& objects() const override { return objectsOf(inner_); }

    Result<TextureHandle> doCreateTexture(const TextureDesc& desc) override;
    Status doDestroyTexture(TextureHandle texture) override { return inner_.destroyTexture(texture); }
    Status doWriteTexture(TextureHandle texture, uint32_t mip, const void* data, size_t bytes) override;
    Status doReadTexture(TextureHandle texture, uint32_t mip, void* out, size_t bytes) override;

    Result<BufferHandle> doCreateBuffer(const BufferDesc& desc) override;
    Status doDestroyBuffer(BufferHandle buffer) override { return inner_.destroyBuffer(buffer); }
    Status doWriteBuffer(BufferHandle buffer, uint64_t offset, const void* data, size_t bytes) override;
    Status doReadBuffer(BufferHandle buffer, uint64_t offset, void* out, size_t bytes) override;

    Result<SamplerHandle> doCreateSampler(const SamplerDesc& desc) override;
    Status doDestroySampler(SamplerHandle sampler) override { return inner_.destroySampler(sampler); }

    Result<ProgramHandle> doCreateProgram(const CompiledProgram& program) override;
    Status doDestroyProgram(ProgramHandle program) override { return inner_.destroyProgram(program); }

    Result<PipelineHandle> doCreateGraphicsPipeline(const GraphicsPipelineDesc& desc, validation::PipelineInfo) override;
    Result<PipelineHandle> doCreateComputePipeline(const ComputePipelineDesc& desc, validation::PipelineInfo) override;
    Status doDestroyPipeline(PipelineHandle pipeline) override { return inner_.destroyPipeline(pipeline); }

    Result<TimerHandle> doCreateTimer() override;

    // Beginning a recording or replay can fail like any call; ending and destroying one are always
    // forwarded (as destroys are), so the wrapped device is never left with one open.
    Status doBeginRecording() override;
    Result<RecordingHandle> doEndRecording() override { return inner_.endRecording(); }
    Status doBeginReplay(RecordingHandle recording) override;
    Status doEndReplay(RecordingHandle) override { return inner_.endReplay(); }
    Status doDestroyRecording(RecordingHandle recording) override { return inner_.destroyRecording(recording); }
    Status doReplayCall(const RenderPassDesc* pass, std::span<const DrawDesc> draws, const DispatchDesc* dispatch) override;
    Status doDestroyTimer(TimerHandle timer) override { return inner_.destroyTimer(timer); }
    Status doBeginTimer(TimerHandle timer) override;
    Status doEndTimer(TimerHandle timer) override;
    Result<TimerReading> doReadTimer(TimerHandle timer) override;

    Status doRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) override;
    Status doDispatch(const DispatchDesc& dispatch) override;
    Status doFlush() override;

    enum class Fault { None, Creation, Submit, Loss };
    // Counts a call and says why it fails (Ok: forward it). `what` names the call.
    Status enter(const char* what, bool creation, bool submit);

    Device& inner_;
    Fault fault_ = Fault::None;
    uint64_t at_ = 0;  // the armed fault's k, counted from when it was armed
    uint64_t armedCreations_ = 0, armedSubmits_ = 0, armedCalls_ = 0;
    uint64_t creations_ = 0, submits_ = 0, calls_ = 0;
    bool fired_ = false, lost_ = false;
    std::function<bool(CompiledProgram&)> rewrite_;
    uint64_t rewritten_ = 0;
};

}  // namespace sfx::test
