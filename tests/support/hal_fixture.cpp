#include "hal_fixture.hpp"

namespace sfx::test {

const CompiledProgram& program(const char* name, Tier tier) {
    Result<const CompiledProgram*> p = test_shaders::find(name, tier);
    if (!p) p = shaders::find(name, tier);
    INFO(name << ": " << p.status().toString());
    REQUIRE(p.isOk());
    return *p.value();
}

TextureHandle makeTexture(Cleanup& c, uint32_t w, uint32_t h, Format f, uint32_t usage, uint32_t mips) {
    Result<TextureHandle> t = dev().createTexture({w, h, mips, f, usage, "hal test texture"});
    INFO("createTexture " << toString(f) << ": " << t.status().toString());
    REQUIRE(t.isOk());
    TextureHandle handle = t.value();
    c.steps.push_back([handle] { (void)dev().destroyTexture(handle); });
    return handle;
}

BufferHandle makeBuffer(Cleanup& c, uint64_t size, uint32_t usage, const void* data) {
    Result<BufferHandle> b = dev().createBuffer({size, usage, "hal test buffer"});
    INFO("createBuffer: " << b.status().toString());
    REQUIRE(b.isOk());
    BufferHandle handle = b.value();
    c.steps.push_back([handle] { (void)dev().destroyBuffer(handle); });
    if (data) SFX_REQUIRE_OK(dev().writeBuffer(handle, 0, data, size));
    return handle;
}

ProgramHandle makeProgram(Cleanup& c, const CompiledProgram& p) {
    Result<ProgramHandle> h = dev().createProgram(p);
    INFO("createProgram " << p.name << ": " << h.status().toString());
    REQUIRE(h.isOk());
    ProgramHandle handle = h.value();
    c.steps.push_back([handle] { (void)dev().destroyProgram(handle); });
    return handle;
}

PipelineHandle makePipeline(Cleanup& c, GraphicsPipelineDesc desc, const char* programName) {
    desc.program = makeProgram(c, program(programName));
    Result<PipelineHandle> p = dev().createGraphicsPipeline(desc);
    INFO("createGraphicsPipeline " << programName << ": " << p.status().toString());
    REQUIRE(p.isOk());
    PipelineHandle handle = p.value();
    c.steps.push_back([handle] { (void)dev().destroyPipeline(handle); });
    return handle;
}

PipelineHandle fullscreenPipeline(Cleanup& c, const char* programName, Format color) {
    GraphicsPipelineDesc d;
    d.colorFormats = {color};
    return makePipeline(c, d, programName);
}

void fullscreenPass(TextureHandle target, PipelineHandle pipeline, BindingSet bindings, uint32_t mip) {
    RenderPassDesc pass;
    pass.colors = {{target, mip, LoadOp::Clear, {0, 0, 0, 0}}};
    DrawDesc draw;
    draw.pipeline = pipeline;
    draw.bindings = std::move(bindings);
    SFX_REQUIRE_OK(dev().renderPass(pass, {&draw, 1}));
}

std::vector<float> sampledThroughCopy(Cleanup& c, TextureHandle source, uint32_t w, uint32_t h, uint32_t mip) {
    TextureHandle target = makeTexture(c, w, h, Format::R32F, kTextureSampled | kTextureRenderTarget);
    PipelineHandle copy = fullscreenPipeline(c, "copy", Format::R32F);
    fullscreenPass(target, copy, {.textures = {{gen::copy::uSource, source, mip, 1}}});
    return readLevel<float>(target);
}

GraphicsPipelineDesc meshPipelineDesc(Format color, Format depth) {
    GraphicsPipelineDesc d;
    d.colorFormats = {color};
    d.depthFormat = depth;
    d.vertexLayout.stride = sizeof(MeshVertex);
    d.vertexLayout.attributes = {{0, VertexFormat::Float3, 0}, {1, VertexFormat::Float4, 12}};
    return d;
}

void checkNamed(const Status& s, StatusCode code, const char* field) {
    INFO(s.toString());
    CHECK(s.code() == code);
    CHECK(s.message().find(field) != std::string::npos);
}

}  // namespace sfx::test
