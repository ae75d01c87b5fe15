// Specialisation constants: a pipeline fixes the values its program declares with
// layout(constant_id), on every backend (Vulkan specialises the SPIR-V, GL compiles the text
// with the values in place); defaults hold for ids not given; repeated ids are refused.
#include <catch2/catch.hpp>

#include "sfx/shader_compiler.hpp"
#include "test_device.hpp"

using namespace sfx;

namespace {

const char* kVertex =
    "#version 450\n"
    "void main() {\n"
    "    vec2 p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));\n"
    "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";
// A loop bound and a branch that are constants of the pipeline.
const char* kFragment =
    "#version 450\n"
    "layout(constant_id = 0) const int kTaps = 1;\n"
    "layout(constant_id = 7) const int kRed = 0;\n"
    "layout(location = 0) out vec4 outColor;\n"
    "void main() {\n"
    "    float s = 0.0;\n"
    "    for (int i = 0; i < kTaps; ++i) s += 0.125;\n"
    "    outColor = kRed == 1 ? vec4(s, 0.0, 0.0, 1.0) : vec4(0.0, s, 0.0, 1.0);\n"
    "}\n";

// The colour a pipeline with `constants` renders, as RGBA8.
std::array<uint8_t, 4> render(ProgramHandle program, const std::vector<SpecializationConstant>& constants) {
    Device& dev = test::device();
    GraphicsPipelineDesc pd;
    pd.program = program;
    pd.colorFormats = {Format::RGBA8};
    pd.constants = constants;
    Result<PipelineHandle> pipeline = dev.createGraphicsPipeline(pd);
    INFO(pipeline.status().toString());
    REQUIRE(pipeline.isOk());
    TextureHandle target = dev.createTexture({4, 4, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget, "spec"}).value();
    RenderPassDesc pass;
    pass.colors = {{target, 0, LoadOp::Clear, {0, 0, 0, 0}}};
    DrawDesc draw;
    draw.pipeline = pipeline.value();
    SFX_REQUIRE_OK(dev.renderPass(pass, {&draw, 1}));
    std::vector<uint8_t> px(4 * 4 * 4);
    SFX_REQUIRE_OK(dev.readTexture(target, 0, px.data(), px.size()));
    SFX_REQUIRE_OK(dev.destroyTexture(target));
    SFX_REQUIRE_OK(dev.destroyPipeline(pipeline.value()));
    for (size_t i = 4; i < px.size(); ++i) REQUIRE(px[i] == px[i % 4]);  // one colour everywhere
    return {px[0], px[1], px[2], px[3]};
}

}  // namespace

TEST_CASE("hal: specialisation constants fix loop bounds and branches per pipeline", "[hal][specialization]") {
    Device& dev = test::device();
    shaderc::CompileOptions options;
    options.tier = test::tier();
    Result<CompiledProgram> compiled = shaderc::compileProgram(
        "spec_test", {{ShaderStage::Vertex, "spec.vert", kVertex}, {ShaderStage::Fragment, "spec.frag", kFragment}}, options);
    INFO(compiled.status().toString());
    REQUIRE(compiled.isOk());
    Result<ProgramHandle> program = dev.createProgram(compiled.value());
    INFO(program.status().toString());
    REQUIRE(program.isOk());

    using Px = std::array<uint8_t, 4>;
    CHECK(render(program.value(), {}) == Px{0, 32, 0, 255});                 // defaults: one tap, green
    CHECK(render(program.value(), {{0, 4}, {7, 1}}) == Px{128, 0, 0, 255});  // four taps, red
    CHECK(render(program.value(), {{7, 1}}) == Px{32, 0, 0, 255});           // the other default holds
    CHECK(render(program.value(), {{3, 9}, {0, 2}}) == Px{0, 64, 0, 255});   // an undeclared id is ignored

    GraphicsPipelineDesc repeated;
    repeated.program = program.value();
    repeated.colorFormats = {Format::RGBA8};
    repeated.constants = {{0, 4}, {0, 5}};
    Result<PipelineHandle> refused = dev.createGraphicsPipeline(repeated);
    CHECK(refused.status().code() == StatusCode::InvalidArgument);
    CHECK(refused.status().message().find("GraphicsPipelineDesc.constants[1].id") != std::string::npos);
    SFX_REQUIRE_OK(dev.destroyProgram(program.value()));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
