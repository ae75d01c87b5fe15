// A shader program as tools/sfxc produces it: per stage, SPIR-V and the GL dialects,
// plus the reflected resources so that no backend hard-codes a binding number.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sfx/tier.hpp"

namespace sfx {

enum class ShaderDialect : uint32_t {
    Spirv = 0,  // Vulkan
    Essl300,    // GL ES 3.0 (current tier on GL ES)
    Essl310,    // GL ES 3.1+ (high tier on GL ES)
    Glsl330,    // desktop GL 3.3 (current tier on desktop GL)
    Glsl450,    // desktop GL 4.3+ (high tier on desktop GL)
    Count
};
const char* toString(ShaderDialect dialect);
bool parseShaderDialect(const std::string& text, ShaderDialect* out);

enum class ShaderStage : uint32_t { Vertex = 0, Fragment, Compute };
const char* toString(ShaderStage stage);
inline constexpr uint32_t stageBit(ShaderStage s) { return 1u << uint32_t(s); }

enum class ResourceKind : uint32_t { UniformBuffer, SampledTexture, StorageBuffer, StorageImage };
const char* toString(ResourceKind kind);  // "uniform buffer", "sampled texture", ... (words for messages)

struct ShaderResource {
    std::string name;    // as declared in shader_src (the variable, or the block type for buffers)
    std::string glName;  // what GL's glGetUniformLocation / glGetUniformBlockIndex / glGetProgramResourceIndex take
    ResourceKind kind = ResourceKind::UniformBuffer;
    uint32_t binding = 0;    // descriptor binding (set 0) in Vulkan; texture unit / block binding in GL
    uint32_t stages = 0;     // stageBit mask
    uint32_t blockSize = 0;  // bytes, for uniform and storage blocks (storage: fixed part)
};

// One uniform block of a program as sfxc reflected it (the generated headers' kUniformBlocks).
struct UniformBlockInfo {
    const char* name;  // the block type, as SFX_BLOCK(Name, binding) declares it
    uint32_t size;     // bytes (std140)
    uint32_t binding;
};
struct ProgramUniformBlocks {
    const char* program;
    std::span<const UniformBlockInfo> blocks;
};

struct StageCode {
    ShaderStage stage = ShaderStage::Vertex;
    std::vector<uint32_t> spirv;
    std::string glsl[size_t(ShaderDialect::Count)];  // index Essl300..Glsl450; [Spirv] unused
};

struct CompiledProgram {
    std::string name;  // e.g. "linearize_depth"
    Tier tier = Tier::Current;
    std::vector<StageCode> stages;
    std::vector<ShaderResource> resources;

    bool isCompute() const { return stages.size() == 1 && stages[0].stage == ShaderStage::Compute; }
    bool usesStorage() const;  // storage buffers or images
    const ShaderResource* findResource(const std::string& name) const;
};

}  // namespace sfx
