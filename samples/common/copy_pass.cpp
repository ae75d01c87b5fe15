#include "copy_pass.hpp"

#include "sfx/budget.hpp"
#include "sfx_shaders.hpp"

namespace sfx::samples {

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


}  // namespace sfx::samples
