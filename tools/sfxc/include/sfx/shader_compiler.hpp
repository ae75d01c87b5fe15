// The shader compiler behind tools/sfxc and the build: GLSL 450 from shader_src/ to SPIR-V
// (validated with SPIRV-Tools), then to the GL dialects with SPIRV-Cross, with reflection.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sfx/shader_program.hpp"
#include "sfx/status.hpp"

namespace sfx::shaderc {

struct StageSource {
    ShaderStage stage = ShaderStage::Fragment;
    std::string path;  // used in error messages as "path:line: message" and to resolve includes
    std::string text;
};

struct CompileOptions {
    Tier tier = Tier::High;  // gets the defines tiers::shaderDefines generates from its row (e.g. SFX_TIER_HIGH)
    std::vector<std::string> includeDirs;
    std::vector<std::pair<std::string, std::string>> defines;
};

// Stage from a file name's extension: .vert .frag .comp.
bool stageFromPath(const std::string& path, ShaderStage* out);

// Compiles every stage to SPIR-V and every GL dialect and merges the stages' reflection.
// ShaderError with "file:line: message" lines when the source does not compile or validate.
Result<CompiledProgram> compileProgram(const std::string& name, const std::vector<StageSource>& stages, const CompileOptions& options);

// One program of shader_src/programs.txt.
struct ManifestEntry {
    std::string name;
    std::vector<Tier> tiers;
    std::vector<std::string> files;  // relative to the manifest's folder
    int line = 0;
};
Result<std::vector<ManifestEntry>> parseManifest(const std::string& path);

// How one manifest is embedded: the generated header's file name, the manifest it came from
// (named in the "generated" comment), and the namespace under sfx:: that holds find() and
// all(). Each library of programs (runtime, tests, samples) has its own namespace, so they
// can be linked together; binding constants share sfx::gen::<program> (names are unique).
struct EmbeddingDesc {
    std::string headerName;
    std::string manifestName = "programs.txt";
    std::string cppNamespace = "shaders";
};

// C++ that embeds the programs (sfx::<cppNamespace>::find) and the header with binding
// constants (sfx::gen::<program>::<resource>). Bindings must agree across a program's tiers.
Result<std::pair<std::string, std::string>> generateEmbedding(const std::vector<CompiledProgram>& programs, const EmbeddingDesc& desc);

Result<std::string> readTextFile(const std::string& path);

}  // namespace sfx::shaderc
