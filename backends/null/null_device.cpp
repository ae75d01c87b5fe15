// The null backend: every call goes through the same shared validation as on Vulkan and GL (it
// keeps each program's reflection, each pipeline's description and each texture's and buffer's
// description for that), then keeps contents in host memory and draws nothing.
#include "sfx/null_device.hpp"

#include <cstring>
#include <vector>

#include "sfx/hal_validation.hpp"

namespace sfx::null {
namespace {

struct NullTexture {
    TextureDesc desc;
    std::vector<std::vector<uint8_t>> mips;
};
struct NullBuffer {
    BufferDesc desc;
    std::vector<uint8_t> bytes;
};
struct NullProgram {
    validation::ProgramInfo info;
};
struct NullPipeline {
    validation::PipelineInfo info;
};
struct NullTimer {
    bool begun = false, ended = false;
};

class NullDevice final : public Device {
public:
    explicit NullDevice(const DeviceCaps& caps)
        : caps_(caps),
          serial_(nextDeviceSerial()),
          textures_(serial_, "texture"),
          buffers_(serial_, "buffer"),
          samplers_(serial_, "sampler"),
          programs_(serial_, "program"),
          pipelines_(serial_, "pipeline"),
          timers_(serial_, "timer") {}

    const DeviceCaps& caps() const override { return caps_; }

    Result<TextureHandle> createTexture(const TextureDesc& desc) override {
        SFX_TRY(validation::textureDesc(desc, caps_));
        NullTexture t{desc, {}};
        for (uint32_t m = 0; m < desc.mipLevels; ++m) {
            t.mips.emplace_back(mipLevelBytes(desc, m), uint8_t(0));
            bytesHeld_ += t.mips.back().size();
        }
        return textures_.insert(std::move(t));
    }
    Status destroyTexture(TextureHandle h) override {
        SFX_TRY(textures_.check(h, "texture"));
        for (const std::vector<uint8_t>& mip : textures_.remove(h).mips) bytesHeld_ -= mip.size();
        return Status::ok();
    }
    Result<TextureDesc> textureDesc(TextureHandle h) const override {
        SFX_TRY(textures_.check(h, "texture"));
        return textures_.get(h).desc;
    }
    Status writeTexture(TextureHandle h, uint32_t mip, const void* data, size_t bytes) override {
        SFX_TRY(textures_.check(h, "texture"));
        NullTexture& t = textures_.get(h);
        SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
        SFX_TRY(validation::pointer(data, "data", "the level's bytes"));
        std::memcpy(t.mips[mip].data(), data, bytes);
        return Status::ok();
    }
    Status readTexture(TextureHandle h, uint32_t mip, void* out, size_t bytes) override {
        SFX_TRY(textures_.check(h, "texture"));
        NullTexture& t = textures_.get(h);
        SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
        SFX_TRY(validation::pointer(out, "out", "the level's bytes"));
        std::memcpy(out, t.mips[mip].data(), bytes);
        return Status::ok();
    }

    Result<BufferHandle> createBuffer(const BufferDesc& desc) override {
        SFX_TRY(validation::bufferDesc(desc, caps_));
        bytesHeld_ += desc.size;
        return buffers_.insert(NullBuffer{desc, std::vector<uint8_t>(desc.size, 0)});
    }
    Status destroyBuffer(BufferHandle h) override {
        SFX_TRY(buffers_.check(h, "buffer"));
        bytesHeld_ -= buffers_.remove(h).bytes.size();
        return Status::ok();
    }
    Status writeBuffer(BufferHandle h, uint64_t offset, const void* data, size_t bytes) override {
        SFX_TRY(buffers_.check(h, "buffer"));
        NullBuffer& b = buffers_.get(h);
        SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "writeBuffer(offset, bytes)"));
        SFX_TRY(validation::pointer(data, "data", "the bytes to write"));
        std::memcpy(b.bytes.data() + offset, data, bytes);
        return Status::ok();
    }
    Status readBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) override {
        SFX_TRY(buffers_.check(h, "buffer"));
        NullBuffer& b = buffers_.get(h);
        SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "readBuffer(offset, bytes)"));
        SFX_TRY(validation::pointer(out, "out", "room for the bytes read"));
        std::memcpy(out, b.bytes.data() + offset, bytes);
        return Status::ok();
    }

    Result<SamplerHandle> createSampler(const SamplerDesc& desc) override {
        SFX_TRY(validation::samplerDesc(desc));
        return samplers_.insert(desc);
    }
    Status destroySampler(SamplerHandle h) override {
        SFX_TRY(samplers_.check(h, "sampler"));
        samplers_.remove(h);
        return Status::ok();
    }

    Result<ProgramHandle> createProgram(const CompiledProgram& program) override {
        SFX_TRY(validation::program(program, caps_));
        return programs_.insert(NullProgram{validation::programInfo(program)});
    }
    Status destroyProgram(ProgramHandle h) override {
        SFX_TRY(programs_.check(h, "program"));
        programs_.remove(h);
        return Status::ok();
    }

    Result<PipelineHandle> createGraphicsPipeline(const GraphicsPipelineDesc& desc) override {
        SFX_TRY(programs_.check(desc.program, "GraphicsPipelineDesc.program"));
        Result<validation::PipelineInfo> info = validation::graphicsPipeline(desc, programs_.get(desc.program).info, caps_);
        if (!info) return info.status();
        return pipelines_.insert(NullPipeline{std::move(info.value())});
    }
    Result<PipelineHandle> createComputePipeline(const ComputePipelineDesc& desc) override {
        SFX_TRY(programs_.check(desc.program, "ComputePipelineDesc.program"));
        Result<validation::PipelineInfo> info = validation::computePipeline(desc, programs_.get(desc.program).info);
        if (!info) return info.status();
        return pipelines_.insert(NullPipeline{std::move(info.value())});
    }
    Status destroyPipeline(PipelineHandle h) override {
        SFX_TRY(pipelines_.check(h, "pipeline"));
        pipelines_.remove(h);
        return Status::ok();
    }

    Result<TimerHandle> createTimer() override { return timers_.insert(NullTimer{}); }
    Status destroyTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        timers_.remove(h);
        return Status::ok();
    }

    Status renderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) override {
        return validation::renderPass(pass, draws, validation::PoolLookup(textures_, buffers_, samplers_, pipelines_), caps_);
    }
    Status dispatch(const DispatchDesc& d) override { return validation::dispatch(d, validation::PoolLookup(textures_, buffers_, samplers_, pipelines_), caps_); }
    Status beginTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        timers_.get(h).begun = true;
        return Status::ok();
    }
    Status endTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        if (!timers_.get(h).begun) return validation::fail(validation::Error::TimerNotBegun, {});
        timers_.get(h).ended = true;
        return Status::ok();
    }
    Status flush() override { return Status::ok(); }

    DeviceStats stats() const override {
        // The null backend keeps its textures and buffers in host memory: that is what it holds.
        DeviceStats s = halObjectStats(textures_, buffers_, samplers_, programs_, pipelines_, timers_);
        s.deviceMemoryBytes = bytesHeld_;
        return s;
    }
    Result<TimerReading> readTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        if (!timers_.get(h).ended) return validation::fail(validation::Error::TimerNoMeasurement, {});
        return TimerReading{0.0, caps_.timing};
    }

private:
    DeviceCaps caps_;
    uint16_t serial_;
    HandlePool<TextureTag, NullTexture> textures_;
    HandlePool<BufferTag, NullBuffer> buffers_;
    HandlePool<SamplerTag, SamplerDesc> samplers_;
    HandlePool<ProgramTag, NullProgram> programs_;
    HandlePool<PipelineTag, NullPipeline> pipelines_;
    HandlePool<TimerTag, NullTimer> timers_;
    uint64_t bytesHeld_ = 0;  // texture and buffer bytes
};

}  // namespace

DeviceCaps defaultCaps(CapabilityCeiling ceiling) {
    DeviceCaps c;
    c.backend = BackendKind::Null;
    c.platform = "null";
    c.apiName = "null";
    c.deviceName = "null device";
    const bool full = ceiling == CapabilityCeiling::None;
    // Under the ceiling the dialect a GL ES 3.0-class desktop GL compiles, as the GL backend does,
    // so high-tier-only programs are refused the same way.
    c.dialect = full ? ShaderDialect::Glsl450 : ShaderDialect::Glsl330;
    c.ceiling = ceiling;
    c.computeShaders = full;
    c.storageBuffers = full;
    c.atomics = full;
    c.storageImages = full;
    c.fragmentStoresAndAtomics = full;
    c.floatRenderTargets = true;
    c.float32Filterable = true;
    c.timing = TimingSource::WallClockAfterFinish;
    c.limits.maxTextureSize = 16384;
    c.limits.maxRenderTargetWidth = c.limits.maxRenderTargetHeight = 16384;
    c.limits.maxColorAttachments = 8;
    c.limits.subPixelPrecisionBits = 8;
    c.limits.maxUniformBlockSize = 65536;
    c.limits.maxStorageBufferSize = full ? (1u << 30) : 0;
    c.limits.maxBufferSize = 1u << 30;
    c.limits.maxComputeWorkGroupInvocations = full ? 1024 : 0;
    c.limits.maxComputeWorkGroupCount = full ? std::array<uint32_t, 3>{65535, 65535, 65535} : std::array<uint32_t, 3>{};
    c.limits.maxTextureBindings = 16;
    // The largest alignment common hardware asks for, so code that passes here passes there.
    c.limits.minUniformBufferOffsetAlignment = 256;
    c.limits.minStorageBufferOffsetAlignment = 256;
    for (size_t f = 1; f < size_t(Format::Count); ++f) {
        c.sampledFormat[f] = true;
        c.renderableFormat[f] = true;
    }
    return c;
}

std::unique_ptr<Device> createDevice(const DeviceOptions& options) {
    return std::make_unique<NullDevice>(defaultCaps(options.ceiling));
}
std::unique_ptr<Device> createDevice(const DeviceCaps& caps) { return std::make_unique<NullDevice>(caps); }

}  // namespace sfx::null
