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
    bool compute = false;
};
struct NullPipeline {
    bool compute = false;
    VertexLayout vertexLayout;  // bounds the draws' vertex reads
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
        if (!data) return invalidArgument("data", "null", "a pointer to the level's bytes");
        std::memcpy(t.mips[mip].data(), data, bytes);
        return Status::ok();
    }
    Status readTexture(TextureHandle h, uint32_t mip, void* out, size_t bytes) override {
        SFX_TRY(textures_.check(h, "texture"));
        NullTexture& t = textures_.get(h);
        SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
        if (!out) return invalidArgument("out", "null", "a pointer to the level's bytes");
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
        SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "writeBuffer range"));
        if (!data) return invalidArgument("data", "null", "a pointer to the bytes to write");
        std::memcpy(b.bytes.data() + offset, data, bytes);
        return Status::ok();
    }
    Status readBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) override {
        SFX_TRY(buffers_.check(h, "buffer"));
        NullBuffer& b = buffers_.get(h);
        SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "readBuffer range"));
        if (!out) return invalidArgument("out", "null", "a pointer for the bytes read");
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
        return programs_.insert(NullProgram{program.isCompute()});
    }
    Status destroyProgram(ProgramHandle h) override {
        SFX_TRY(programs_.check(h, "program"));
        programs_.remove(h);
        return Status::ok();
    }

    Result<PipelineHandle> createGraphicsPipeline(const GraphicsPipelineDesc& desc) override {
        SFX_TRY(programs_.check(desc.program, "GraphicsPipelineDesc.program"));
        if (programs_.get(desc.program).compute)
            return Status{StatusCode::InvalidArgument, "GraphicsPipelineDesc.program is a compute program"};
        SFX_TRY(validation::graphicsPipelineShape(desc, caps_));
        SFX_TRY(validation::graphicsPipelineState(desc, caps_));
        return pipelines_.insert(NullPipeline{false, desc.vertexLayout});
    }
    Result<PipelineHandle> createComputePipeline(const ComputePipelineDesc& desc) override {
        SFX_TRY(programs_.check(desc.program, "ComputePipelineDesc.program"));
        if (!programs_.get(desc.program).compute)
            return Status{StatusCode::InvalidArgument, "ComputePipelineDesc.program is not a compute program"};
        SFX_TRY(validation::specializationConstants(desc.constants, "ComputePipelineDesc"));
        return pipelines_.insert(NullPipeline{true, {}});
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
        if (pass.colors.empty() && pass.depth.texture.isNull())
            return invalidArgument("RenderPassDesc", "without attachments", "at least one colour or depth attachment");
        for (size_t i = 0; i < pass.colors.size(); ++i) {
            SFX_TRY(textures_.check(pass.colors[i].texture, "RenderPassDesc.colors[].texture"));
            SFX_TRY(validation::mipRange(textures_.get(pass.colors[i].texture).desc, pass.colors[i].mip,
                                         "RenderPassDesc.colors[].mip"));
        }
        if (!pass.depth.texture.isNull()) SFX_TRY(textures_.check(pass.depth.texture, "RenderPassDesc.depth.texture"));
        for (const DrawDesc& d : draws) {
            SFX_TRY(pipelines_.check(d.pipeline, "DrawDesc.pipeline"));
            SFX_TRY(checkBindings(d.bindings));
            SFX_TRY(validation::noFeedbackLoop(pass, d));
            const BufferDesc* vertexBuffer = nullptr;
            const BufferDesc* indexBuffer = nullptr;
            if (!pipelines_.get(d.pipeline).vertexLayout.attributes.empty() || !d.vertexBuffer.isNull()) {
                SFX_TRY(buffers_.check(d.vertexBuffer, "DrawDesc.vertexBuffer"));
                vertexBuffer = &buffers_.get(d.vertexBuffer).desc;
            }
            if (!d.indexBuffer.isNull()) {
                SFX_TRY(buffers_.check(d.indexBuffer, "DrawDesc.indexBuffer"));
                indexBuffer = &buffers_.get(d.indexBuffer).desc;
            }
            SFX_TRY(validation::drawRange(d, pipelines_.get(d.pipeline).vertexLayout, vertexBuffer, indexBuffer));
        }
        return Status::ok();
    }
    Status dispatch(const DispatchDesc& d) override {
        SFX_TRY(validation::dispatchGroups(d, caps_));
        SFX_TRY(pipelines_.check(d.pipeline, "DispatchDesc.pipeline"));
        return checkBindings(d.bindings);
    }
    Status beginTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        timers_.get(h).begun = true;
        return Status::ok();
    }
    Status endTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        if (!timers_.get(h).begun) return {StatusCode::InvalidArgument, "endTimer: timer was not begun"};
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
        if (!timers_.get(h).ended) return Status{StatusCode::InvalidArgument, "readTimer: timer has no finished measurement"};
        return TimerReading{0.0, caps_.timing};
    }

private:
    Status checkBindings(const BindingSet& b) {
        for (const auto& t : b.textures) {
            SFX_TRY(textures_.check(t.texture, "TextureBinding.texture"));
            SFX_TRY(validation::textureBinding(textures_.get(t.texture).desc, t));
            if (!t.sampler.isNull()) SFX_TRY(samplers_.check(t.sampler, "TextureBinding.sampler"));
        }
        for (const auto& u : b.uniformBuffers) SFX_TRY(buffers_.check(u.buffer, "BufferBinding.buffer"));
        for (const auto& s : b.storageBuffers) SFX_TRY(buffers_.check(s.buffer, "BufferBinding.buffer"));
        for (const auto& s : b.storageImages) SFX_TRY(textures_.check(s.texture, "StorageImageBinding.texture"));
        return Status::ok();
    }

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
    c.dialect = ShaderDialect::Glsl450;
    c.ceiling = ceiling;
    const bool full = ceiling == CapabilityCeiling::None;
    c.computeShaders = full;
    c.storageBuffers = full;
    c.atomics = full;
    c.storageImages = full;
    c.floatRenderTargets = true;
    c.float32Filterable = true;
    c.timing = TimingSource::WallClockAfterFinish;
    c.limits.maxTextureSize = 16384;
    c.limits.maxColorAttachments = 8;
    c.limits.maxUniformBlockSize = 65536;
    c.limits.maxStorageBufferSize = full ? (1u << 30) : 0;
    c.limits.maxBufferSize = 1u << 30;
    c.limits.maxComputeWorkGroupInvocations = full ? 1024 : 0;
    c.limits.maxTextureBindings = 16;
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
