// The null backend: a thin backend like the others behind Device's front end, which checks every
// call (the pools below keep the descriptions and reflection the checks read). It keeps contents
// in host memory and draws nothing.
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
struct NullSampler {
    SamplerDesc desc;
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

    DeviceStats stats() const override {
        // The null backend keeps its textures and buffers in host memory: that is what it holds.
        DeviceStats s = halObjectStats(textures_, buffers_, samplers_, programs_, pipelines_, timers_);
        s.deviceMemoryBytes = bytesHeld_;
        return s;
    }

private:
    const validation::ObjectLookup& objects() const override { return lookup_; }

    Result<TextureHandle> doCreateTexture(const TextureDesc& desc) override {
        NullTexture t{desc, {}};
        for (uint32_t m = 0; m < desc.mipLevels; ++m) {
            t.mips.emplace_back(mipLevelBytes(desc, m), uint8_t(0));
            bytesHeld_ += t.mips.back().size();
        }
        return textures_.insert(std::move(t));
    }
    Status doDestroyTexture(TextureHandle h) override {
        for (const std::vector<uint8_t>& mip : textures_.remove(h).mips) bytesHeld_ -= mip.size();
        return Status::ok();
    }
    Status doWriteTexture(TextureHandle h, uint32_t mip, const void* data, size_t bytes) override {
        std::memcpy(textures_.get(h).mips[mip].data(), data, bytes);
        return Status::ok();
    }
    Status doReadTexture(TextureHandle h, uint32_t mip, void* out, size_t bytes) override {
        std::memcpy(out, textures_.get(h).mips[mip].data(), bytes);
        return Status::ok();
    }

    Result<BufferHandle> doCreateBuffer(const BufferDesc& desc) override {
        bytesHeld_ += desc.size;
        return buffers_.insert(NullBuffer{desc, std::vector<uint8_t>(desc.size, 0)});
    }
    Status doDestroyBuffer(BufferHandle h) override {
        bytesHeld_ -= buffers_.remove(h).bytes.size();
        return Status::ok();
    }
    Status doWriteBuffer(BufferHandle h, uint64_t offset, const void* data, size_t bytes) override {
        std::memcpy(buffers_.get(h).bytes.data() + offset, data, bytes);
        return Status::ok();
    }
    Status doReadBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) override {
        std::memcpy(out, buffers_.get(h).bytes.data() + offset, bytes);
        return Status::ok();
    }

    Result<SamplerHandle> doCreateSampler(const SamplerDesc& desc) override { return samplers_.insert(NullSampler{desc}); }
    Status doDestroySampler(SamplerHandle h) override {
        samplers_.remove(h);
        return Status::ok();
    }

    Result<ProgramHandle> doCreateProgram(const CompiledProgram& program) override {
        return programs_.insert(NullProgram{validation::programInfo(program)});
    }
    Status doDestroyProgram(ProgramHandle h) override {
        programs_.remove(h);
        return Status::ok();
    }

    Result<PipelineHandle> doCreateGraphicsPipeline(const GraphicsPipelineDesc&, validation::PipelineInfo info) override {
        return pipelines_.insert(NullPipeline{std::move(info)});
    }
    Result<PipelineHandle> doCreateComputePipeline(const ComputePipelineDesc&, validation::PipelineInfo info) override {
        return pipelines_.insert(NullPipeline{std::move(info)});
    }
    Status doDestroyPipeline(PipelineHandle h) override {
        pipelines_.remove(h);
        return Status::ok();
    }

    Result<TimerHandle> doCreateTimer() override { return timers_.insert(NullTimer{}); }
    Status doDestroyTimer(TimerHandle h) override {
        timers_.remove(h);
        return Status::ok();
    }
    Status doBeginTimer(TimerHandle h) override {
        timers_.get(h).begun = true;
        return Status::ok();
    }
    Status doEndTimer(TimerHandle h) override {
        if (!timers_.get(h).begun) return validation::fail(validation::Error::TimerNotBegun, {});
        timers_.get(h).ended = true;
        return Status::ok();
    }
    Result<TimerReading> doReadTimer(TimerHandle h) override {
        if (!timers_.get(h).ended) return validation::fail(validation::Error::TimerNoMeasurement, {});
        return TimerReading{0.0, caps_.timing};
    }

    // Nothing is drawn: a checked command has nothing left to do.
    Status doRenderPass(const RenderPassDesc&, std::span<const DrawDesc>) override { return Status::ok(); }
    Status doDispatch(const DispatchDesc&) override { return Status::ok(); }
    Status doFlush() override { return Status::ok(); }

    DeviceCaps caps_;
    uint16_t serial_;
    HandlePool<TextureTag, NullTexture> textures_;
    HandlePool<BufferTag, NullBuffer> buffers_;
    HandlePool<SamplerTag, NullSampler> samplers_;
    HandlePool<ProgramTag, NullProgram> programs_;
    HandlePool<PipelineTag, NullPipeline> pipelines_;
    HandlePool<TimerTag, NullTimer> timers_;
    const decltype(validation::poolLookup(textures_, buffers_, samplers_, programs_, pipelines_, timers_)) lookup_ = validation::poolLookup(
        textures_, buffers_, samplers_, programs_, pipelines_, timers_);
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
    // The fewest sample counts and texels Vulkan allows (1 and 4 samples, 65536 texels).
    c.limits.framebufferColorSampleCounts = c.limits.framebufferDepthSampleCounts = 0x1 | 0x4;
    c.limits.sampledImageColorSampleCounts = c.limits.sampledImageDepthSampleCounts = full ? 0x1 | 0x4 : 0x1;
    c.limits.maxTexelBufferElements = full ? 65536 : 0;
    // Every format as far as the APIs allow any device: depth and integer formats do not filter
    // or blend, depth formats are no storage images.
    for (size_t f = 1; f < size_t(Format::Count); ++f) {
        const bool colour = !isDepthFormat(Format(f)), integer = isIntegerFormat(Format(f));
        c.sampledFormat[f] = true;
        c.renderableFormat[f] = true;
        c.filterableFormat[f] = colour && !integer;
        c.blendableFormat[f] = colour && !integer;
        c.storageFormat[f] = full && colour;
    }
    return c;
}

std::unique_ptr<Device> createDevice(const DeviceOptions& options) { return std::make_unique<NullDevice>(defaultCaps(options.ceiling)); }
std::unique_ptr<Device> createDevice(const DeviceCaps& caps) { return std::make_unique<NullDevice>(caps); }

}  // namespace sfx::null
