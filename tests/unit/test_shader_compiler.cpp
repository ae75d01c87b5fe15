// The shader compiler behind sfxc: errors as file:line, reflection, every dialect.
#include <catch2/catch.hpp>

#include "sfx/shader_compiler.hpp"

using namespace sfx;

TEST_CASE("shader compiler reports source errors as file:line: message", "[shaders][bad-input]") {
    shaderc::StageSource src{ShaderStage::Fragment, "broken.frag",
                             "#version 450\nlayout(location = 0) out vec4 o;\nvoid main() {\n  o = vec4(missing);\n}\n"};
    Result<CompiledProgram> p = shaderc::compileProgram("broken", {src}, {});
    REQUIRE_FALSE(p.isOk());
    CHECK(p.status().code() == StatusCode::ShaderError);
    CHECK(p.status().message().find("broken.frag:4: error:") != std::string::npos);
    CHECK(p.status().message().find("missing") != std::string::npos);
}

TEST_CASE("shader compiler reports a missing include at its line", "[shaders][bad-input]") {
    shaderc::StageSource src{ShaderStage::Fragment, "inc.frag", "#version 450\n#include \"nope.h\"\nvoid main() {}\n"};
    Result<CompiledProgram> p = shaderc::compileProgram("inc", {src}, {});
    REQUIRE_FALSE(p.isOk());
    CHECK(p.status().message().find("inc.frag:2:") != std::string::npos);
}

TEST_CASE("shader compiler reflects bindings and emits every GL dialect", "[shaders]") {
    shaderc::StageSource src{ShaderStage::Fragment, "ok.frag",
                             "#version 450\n"
                             "layout(set=0, binding=3) uniform sampler2D uTex;\n"
                             "layout(set=0, binding=5, std140) uniform Params { vec4 scale; } params;\n"
                             "layout(location=0) out vec4 o;\n"
                             "void main() { o = texelFetch(uTex, ivec2(gl_FragCoord.xy), 0) * params.scale; }\n"};
    shaderc::CompileOptions opts;
    opts.tier = Tier::Current;
    Result<CompiledProgram> p = shaderc::compileProgram("ok", {src}, opts);
    REQUIRE(p.isOk());
    const ShaderResource* tex = p->findResource("uTex");
    const ShaderResource* params = p->findResource("Params");
    REQUIRE(tex);
    REQUIRE(params);
    CHECK(tex->binding == 3);
    CHECK(tex->kind == ResourceKind::SampledTexture);
    CHECK(params->binding == 5);
    CHECK(params->blockSize == 16);
    const StageCode& s = p->stages[0];
    CHECK(s.glsl[size_t(ShaderDialect::Essl300)].find("#version 300 es") == 0);
    // ESSL 300 cannot carry binding=; the GL backend binds by name.
    CHECK(s.glsl[size_t(ShaderDialect::Essl300)].find("binding") == std::string::npos);
    CHECK(s.glsl[size_t(ShaderDialect::Glsl450)].find("#version 450") == 0);
}

TEST_CASE("sfxc's generated header lists each program's reflected uniform blocks", "[shaders]") {
    auto program = [](const char* block, Tier tier) {
        shaderc::StageSource src{ShaderStage::Fragment, "blocks.frag",
                                 std::string("#version 450\nlayout(set=0, binding=2, std140) uniform Params { ") + block +
                                     " } params;\nlayout(location=0) out vec4 o;\nvoid main() { o = params.a; }\n"};
        shaderc::CompileOptions opts;
        opts.tier = tier;
        return shaderc::compileProgram("blocks", {src}, opts);
    };
    Result<CompiledProgram> current = program("vec4 a;", Tier::Current), high = program("vec4 a;", Tier::High);
    REQUIRE(current.isOk());
    REQUIRE(high.isOk());
    auto embedded = shaderc::generateEmbedding({current.value(), high.value()}, {"blocks.hpp"});
    REQUIRE(embedded.isOk());
    CHECK(embedded->first.find(R"(kUniformBlocks{{{"Params", 16u, 2u}, }};)") != std::string::npos);
    CHECK(embedded->first.find("{gen::blocks::kName, gen::blocks::kUniformBlocks},") != std::string::npos);
    // One block, one size across tiers.
    Result<CompiledProgram> larger = program("vec4 a; vec4 b;", Tier::High);
    REQUIRE(larger.isOk());
    auto mismatched = shaderc::generateEmbedding({current.value(), larger.value()}, {"blocks.hpp"});
    REQUIRE_FALSE(mismatched.isOk());
    CHECK(mismatched.status().message().find("uniform block 'Params' is 16 bytes on one tier and 32 on another") != std::string::npos);
}

TEST_CASE("shader compiler rejects resources outside set 0", "[shaders][bad-input]") {
    shaderc::StageSource src{ShaderStage::Fragment, "set1.frag",
                             "#version 450\nlayout(set=1, binding=0) uniform sampler2D uTex;\n"
                             "layout(location=0) out vec4 o;\nvoid main() { o = texelFetch(uTex, ivec2(0), 0); }\n"};
    Result<CompiledProgram> p = shaderc::compileProgram("set1", {src}, {});
    REQUIRE_FALSE(p.isOk());
    CHECK(p.status().message().find("set 1") != std::string::npos);
}
