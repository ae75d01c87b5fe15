#include "copy_pass.hpp"

#include <algorithm>
#include <vector>

#include "sfx/budget.hpp"
#include "sfx_shaders.hpp"

namespace sfx::tools {

Status CopyPass::record() {
    RenderPassDesc rp;
    rp.colors = {ColorAttachment{dst, 0, LoadOp::DontCare, {}}};
    rp.debugName = "bench-copy";
    DrawDesc dr;
    dr.pipeline = pipeline;
    dr.bindings.textures = {TextureBinding{gen::copy::uSource, src, 0, 1, {}}};
    return dev.renderPass(rp, std::span<const DrawDesc>(&dr, 1));
}

Result<double> CopyPass::medianMs(uint32_t runs) {
    Result<TimerReading> r = budget::timeMedian(dev, runs, [&] {
        for (uint32_t i = 0; i < kCopiesPerRun; ++i) SFX_TRY(record());
        return Status::ok();
    });
    if (!r) return r.status();
    return r->milliseconds / double(kCopiesPerRun);
}

namespace {

// One timed, flushed recording.
Result<double> timeOnce(Device& dev, TimerHandle timer, const std::function<Status()>& record) {
    SFX_TRY(dev.beginTimer(timer));
    SFX_TRY(record());
    SFX_TRY(dev.endTimer(timer));
    SFX_TRY(dev.flush());
    Result<TimerReading> r = dev.readTimer(timer);
    if (!r) return r.status();
    return r->milliseconds;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

Result<CopyPass::Interleaved> CopyPass::timeAgainst(uint32_t runs, const std::function<Status()>& record) {
    if (runs == 0) return invalidArgument("runs", "0", "at least 1");
    const std::function<Status()> copies = [&] {
        for (uint32_t i = 0; i < kCopiesPerRun; ++i) SFX_TRY(this->record());
        return Status::ok();
    };
    Result<TimerHandle> timer = dev.createTimer();
    if (!timer) return timer.status();
    std::vector<double> effect, copy, ratio;
    Status status = Status::ok();
    // One warm-up pair (pipelines, caches), then `runs` timed pairs.
    for (uint32_t i = 0; i < runs + 1 && status; ++i) {
        const bool effectFirst = i % 2 == 0;
        Result<double> a = timeOnce(dev, timer.value(), effectFirst ? record : copies);
        Result<double> b = a ? timeOnce(dev, timer.value(), effectFirst ? copies : record) : a;
        if (!b) {
            status = b.status();
            break;
        }
        if (i == 0) continue;
        const double e = effectFirst ? a.value() : b.value();
        const double c = (effectFirst ? b.value() : a.value()) / double(kCopiesPerRun);
        effect.push_back(e);
        copy.push_back(c);
        ratio.push_back(c > 0 ? e / c : 0.0);
    }
    (void)dev.destroyTimer(timer.value());
    if (!status) return status;
    return Interleaved{median(effect), median(copy), median(ratio)};
}

CopyPass::~CopyPass() {
    if (!pipeline.isNull()) (void)dev.destroyPipeline(pipeline);
    if (!program.isNull()) (void)dev.destroyProgram(program);
    for (TextureHandle t : {src, dst})
        if (!t.isNull()) (void)dev.destroyTexture(t);
}

Result<std::unique_ptr<CopyPass>> makeCopyPass(Device& dev, Tier tier, uint32_t w, uint32_t h, Format format) {
    auto copy = std::make_unique<CopyPass>(dev);
    Result<TextureHandle> src = dev.createTexture({w, h, 1, format, kTextureSampled | kTextureRenderTarget, "bench-copy-src"});
    if (!src) return src.status();
    copy->src = src.value();
    Result<TextureHandle> dst = dev.createTexture({w, h, 1, format, kTextureSampled | kTextureRenderTarget, "bench-copy-dst"});
    if (!dst) return dst.status();
    copy->dst = dst.value();
    Result<const CompiledProgram*> compiled = shaders::find(gen::copy::kName, tier);
    if (!compiled) return compiled.status();
    Result<ProgramHandle> program = dev.createProgram(*compiled.value());
    if (!program) return program.status();
    copy->program = program.value();
    GraphicsPipelineDesc pd;
    pd.program = copy->program;
    pd.colorFormats = {format};
    Result<PipelineHandle> pipeline = dev.createGraphicsPipeline(pd);
    if (!pipeline) return pipeline.status();
    copy->pipeline = pipeline.value();
    return copy;
}

}  // namespace sfx::tools
