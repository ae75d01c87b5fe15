// Every uniform block sfxc reflected from the compiled programs (the generated headers'
// kUniformBlocks) against the C++ struct SFX_BLOCK declares for it: size and binding. A block
// declared with SFX_BLOCK in shader_src/include must be listed here, or the last case fails.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <string_view>

#include "sfx_scene_shaders.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared.h"
#include "sfx_shared_ao.h"
#include "sfx_shared_mb.h"
#include "sfx_shared_oit.h"
#include "sfx_shared_oit_params.h"
#include "sfx_shared_raster.h"
#include "sfx_test_shaders.hpp"

using namespace sfx;

namespace {

struct CppBlock {
    std::string_view name;
    size_t size;
    uint32_t binding;
};
#define SFX_CPP_BLOCK(B) \
    CppBlock { #B, sizeof(shared::B), shared::B::kBinding }
// Every SFX_BLOCK of shader_src/include, as C++ declares it.
constexpr CppBlock kCppBlocks[] = {
    SFX_CPP_BLOCK(LinearizeParams), SFX_CPP_BLOCK(AoParams),         SFX_CPP_BLOCK(BlurParams),
    SFX_CPP_BLOCK(UpsampleParams),  SFX_CPP_BLOCK(MbPackParams),     SFX_CPP_BLOCK(MbReconstructParams),
    SFX_CPP_BLOCK(OitDrawParams),   SFX_CPP_BLOCK(OitResolveParams), SFX_CPP_BLOCK(OitAoParams),
    SFX_CPP_BLOCK(RasterParams),
};
#undef SFX_CPP_BLOCK
// Blocks of the HAL tests' own programs, declared in GLSL only (no C++ twin to compare).
constexpr std::string_view kGlslOnly[] = {"PatternParams", "ColorParams"};

const CppBlock* cppBlock(std::string_view name) {
    for (const CppBlock& b : kCppBlocks)
        if (b.name == name) return &b;
    return nullptr;
}

}  // namespace

TEST_CASE("uniform blocks: every reflected block has its C++ struct's size and binding", "[shaders]") {
    std::set<std::string_view> seen;
    size_t blocks = 0;
    for (std::span<const ProgramUniformBlocks> library :
         {std::span<const ProgramUniformBlocks>(shaders::kUniformBlocks), std::span<const ProgramUniformBlocks>(scene_shaders::kUniformBlocks),
          std::span<const ProgramUniformBlocks>(test_shaders::kUniformBlocks)})
        for (const ProgramUniformBlocks& p : library)
            for (const UniformBlockInfo& b : p.blocks) {
                INFO(p.program << ": uniform block " << b.name);
                ++blocks;
                const CppBlock* cpp = cppBlock(b.name);
                if (!cpp) {
                    CHECK(std::find(std::begin(kGlslOnly), std::end(kGlslOnly), std::string_view(b.name)) != std::end(kGlslOnly));
                    continue;
                }
                seen.insert(cpp->name);
                CHECK(b.size == cpp->size);
                CHECK(b.binding == cpp->binding);
            }
    CHECK(blocks > 0);
    // Each C++ block is some program's: none is compared against nothing.
    for (const CppBlock& b : kCppBlocks) {
        INFO(b.name);
        CHECK(seen.count(b.name) == 1);
    }
}

TEST_CASE("uniform blocks: every SFX_BLOCK of shader_src/include is in the checked list", "[shaders]") {
    const std::regex declaration(R"(^SFX_BLOCK\((\w+),)");
    std::set<std::string> declared;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(SFX_SOURCE_DIR) + "/shader_src/include")) {
        std::ifstream file(entry.path());
        std::string line;
        std::smatch m;
        while (std::getline(file, line))
            if (std::regex_search(line, m, declaration)) declared.insert(m[1]);
    }
    CHECK(declared.size() == std::size(kCppBlocks));
    for (const std::string& name : declared) {
        INFO(name << " is declared with SFX_BLOCK but not checked against its reflection (add it to kCppBlocks)");
        CHECK(cppBlock(name) != nullptr);
    }
}
