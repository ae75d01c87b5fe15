#include "sfx/shader_compiler.hpp"

#include "sfx/tiers.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv_cross/spirv_glsl.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

namespace sfx::shaderc {
namespace fs = std::filesystem;

Result<std::string> readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Status{StatusCode::FileError, path + ": cannot open for reading"};
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

bool stageFromPath(const std::string& path, ShaderStage* out) {
    const std::string ext = fs::path(path).extension().string();
    if (ext == ".vert") {
        *out = ShaderStage::Vertex;
        return true;
    }
    if (ext == ".frag") {
        *out = ShaderStage::Fragment;
        return true;
    }
    if (ext == ".comp") {
        *out = ShaderStage::Compute;
        return true;
    }
    return false;
}

namespace {

void initGlslangOnce() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

EShLanguage toGlslang(ShaderStage s) {
    switch (s) {
        case ShaderStage::Vertex: return EShLangVertex;
        case ShaderStage::Fragment: return EShLangFragment;
        case ShaderStage::Compute: return EShLangCompute;
    }
    return EShLangFragment;
}

// Resolves #include "x" against the including file's folder, then the include dirs.
class Includer : public glslang::TShader::Includer {
public:
    explicit Includer(std::vector<std::string> dirs) : dirs_(std::move(dirs)) {}

    IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
        std::vector<std::string> candidates;
        if (includer && *includer) candidates.push_back((fs::path(includer).parent_path() / header).string());
        for (const auto& d : dirs_) candidates.push_back((fs::path(d) / header).string());
        return open(candidates, depth);
    }
    IncludeResult* includeSystem(const char* header, const char*, size_t depth) override {
        std::vector<std::string> candidates;
        for (const auto& d : dirs_) candidates.push_back((fs::path(d) / header).string());
        return open(candidates, depth);
    }
    void releaseInclude(IncludeResult* result) override {
        if (!result) return;
        delete static_cast<std::string*>(result->userData);
        delete result;
    }

private:
    IncludeResult* open(const std::vector<std::string>& candidates, size_t) {
        for (const auto& c : candidates) {
            Result<std::string> text = readTextFile(c);
            if (!text) continue;
            auto* owned = new std::string(std::move(text.value()));
            return new IncludeResult(c, owned->data(), owned->size(), owned);
        }
        return nullptr;  // glslang reports "cannot find include file" at the directive's line
    }
    std::vector<std::string> dirs_;
};

// glslang logs "ERROR: path:12: 'x' : undeclared identifier"; keep "path:12: error: ...".
std::string formatGlslangLog(const std::string& log) {
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        if (line.rfind("ERROR: ", 0) == 0) {
            std::string rest = line.substr(7);
            if (rest.find("compilation terminated") != std::string::npos) continue;
            if (rest.find(" compilation errors.") != std::string::npos) continue;
            size_t c1 = rest.find(':');
            size_t c2 = c1 == std::string::npos ? c1 : rest.find(':', c1 + 1);
            if (c2 != std::string::npos)
                out += rest.substr(0, c2 + 1) + " error:" + rest.substr(c2 + 1) + "\n";
            else
                out += rest + "\n";
        } else if (line.rfind("WARNING: ", 0) == 0) {
            out += line.substr(9) + " (warning)\n";
        }
    }
    if (out.empty()) out = log;
    return out;
}

Result<std::vector<uint32_t>> glslToSpirv(const StageSource& src, const CompileOptions& opts) {
    initGlslangOnce();
    const EShLanguage lang = toGlslang(src.stage);
    glslang::TShader shader(lang);
    const char* text = src.text.c_str();
    const int length = int(src.text.size());
    const char* name = src.path.c_str();
    shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);

    std::string preamble = "#extension GL_GOOGLE_include_directive : require\n";
    for (const tiers::ShaderDefine& d : tiers::shaderDefines(opts.tier)) preamble += "#define " + d.name + " " + d.value + "\n";
    for (const auto& [k, v] : opts.defines) preamble += "#define " + k + " " + (v.empty() ? "1" : v) + "\n";
    shader.setPreamble(preamble.c_str());
    shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);

    Includer includer(opts.includeDirs);
    const auto messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 450, false, messages, includer))
        return Status{StatusCode::ShaderError, formatGlslangLog(shader.getInfoLog())};

    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) return Status{StatusCode::ShaderError, src.path + ":0: error: link: " + formatGlslangLog(program.getInfoLog())};

    std::vector<uint32_t> spirv;
    glslang::SpvOptions spvOptions;
    spvOptions.generateDebugInfo = false;
    spvOptions.disableOptimizer = true;
    spvOptions.validate = false;  // SPIRV-Tools below, with its own message
    glslang::GlslangToSpv(*program.getIntermediate(lang), spirv, &spvOptions);

    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
    std::string validationLog;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t& pos, const char* msg) {
        validationLog += src.path + ":0: error: SPIR-V validation (word " + std::to_string(pos.index) + "): " + msg + "\n";
    });
    if (!tools.Validate(spirv)) return Status{StatusCode::ShaderError, validationLog};
    return spirv;
}

struct DialectTarget {
    ShaderDialect dialect;
    uint32_t version;
    bool es;
};
constexpr DialectTarget kGlTargets[] = {
    {ShaderDialect::Essl300, 300, true},
    {ShaderDialect::Essl310, 310, true},
    {ShaderDialect::Glsl330, 330, false},
    {ShaderDialect::Glsl450, 450, false},
};

Result<std::string> spirvToGlsl(const std::vector<uint32_t>& spirv, const DialectTarget& t, const std::string& path,
                                std::vector<std::pair<uint32_t, std::string>>* blockNames) {
    try {
        spirv_cross::CompilerGLSL glsl(spirv);
        spirv_cross::CompilerGLSL::Options o = glsl.get_common_options();
        o.version = t.version;
        o.es = t.es;
        o.vulkan_semantics = false;
        o.enable_420pack_extension = false;  // GL 3.3 gets bindings by name, not an extension
        o.fragment.default_float_precision = spirv_cross::CompilerGLSL::Options::Highp;
        o.fragment.default_int_precision = spirv_cross::CompilerGLSL::Options::Highp;
        o.vertex.fixup_clipspace = false;  // each API keeps its own clip depth range (caps.clipDepth)
        o.vertex.flip_vert_y = false;      // NDC y = -1 is memory row 0 on every API
        glsl.set_common_options(o);
        std::string out = glsl.compile();
        if (blockNames) {
            spirv_cross::ShaderResources res = glsl.get_shader_resources();
            for (const auto& r : res.uniform_buffers)
                blockNames->push_back({glsl.get_decoration(r.id, spv::DecorationBinding), glsl.get_remapped_declared_block_name(r.id)});
            for (const auto& r : res.storage_buffers)
                blockNames->push_back({glsl.get_decoration(r.id, spv::DecorationBinding), glsl.get_remapped_declared_block_name(r.id)});
        }
        return out;
    } catch (const std::exception& e) {
        return Status{StatusCode::ShaderError, path + ":0: error: SPIRV-Cross (" + toString(t.dialect) + "): " + e.what() + "\n"};
    }
}

Status reflect(const std::vector<uint32_t>& spirv, ShaderStage stage, const std::string& path, std::vector<ShaderResource>* merged) {
    try {
        spirv_cross::Compiler comp(spirv);
        spirv_cross::ShaderResources res = comp.get_shader_resources();
        auto add = [&](const spirv_cross::Resource& r, ResourceKind kind) -> Status {
            const uint32_t set = comp.get_decoration(r.id, spv::DecorationDescriptorSet);
            const uint32_t binding = comp.get_decoration(r.id, spv::DecorationBinding);
            if (set != 0)
                return {StatusCode::ShaderError,
                        path + ":0: error: resource '" + r.name + "' is in set " + std::to_string(set) + "; the SDK uses set 0 only"};
            const bool isBlock = kind == ResourceKind::UniformBuffer || kind == ResourceKind::StorageBuffer;
            ShaderResource sr;
            sr.name = isBlock ? comp.get_name(r.base_type_id) : comp.get_name(r.id);
            sr.glName = sr.name;
            sr.kind = kind;
            sr.binding = binding;
            sr.stages = stageBit(stage);
            if (isBlock) sr.blockSize = uint32_t(comp.get_declared_struct_size(comp.get_type(r.base_type_id)));
            for (ShaderResource& m : *merged) {
                if (m.binding != binding) continue;
                if (m.name != sr.name || m.kind != sr.kind)
                    return {
                        StatusCode::ShaderError,
                        path + ":0: error: binding " + std::to_string(binding) + " is '" + sr.name + "' here and '" + m.name + "' in another stage"};
                m.stages |= sr.stages;
                return Status::ok();
            }
            merged->push_back(sr);
            return Status::ok();
        };
        for (const auto& r : res.uniform_buffers) SFX_TRY(add(r, ResourceKind::UniformBuffer));
        for (const auto& r : res.sampled_images) SFX_TRY(add(r, ResourceKind::SampledTexture));
        for (const auto& r : res.storage_buffers) SFX_TRY(add(r, ResourceKind::StorageBuffer));
        for (const auto& r : res.storage_images) SFX_TRY(add(r, ResourceKind::StorageImage));
        if (!res.separate_images.empty() || !res.separate_samplers.empty())
            return {StatusCode::ShaderError, path + ":0: error: separate images/samplers are not supported; use combined sampler2D"};
        return Status::ok();
    } catch (const std::exception& e) {
        return {StatusCode::ShaderError, path + ":0: error: reflection: " + e.what()};
    }
}

}  // namespace

Result<CompiledProgram> compileProgram(const std::string& name, const std::vector<StageSource>& stages, const CompileOptions& options) {
    if (uint32_t(options.tier) >= kTierCount) return invalidArgument("CompileOptions.tier", std::to_string(uint32_t(options.tier)), tierNameList());
    CompiledProgram program;
    program.name = name;
    program.tier = options.tier;
    const std::vector<ShaderDialect>& glDialects = tiers::row(options.tier).glDialects;
    std::string errors;
    for (const StageSource& src : stages) {
        Result<std::vector<uint32_t>> spirv = glslToSpirv(src, options);
        if (!spirv) {
            errors += spirv.status().message();
            continue;
        }
        StageCode code;
        code.stage = src.stage;
        code.spirv = std::move(spirv.value());
        SFX_TRY(reflect(code.spirv, src.stage, src.path, &program.resources));
        for (const DialectTarget& t : kGlTargets) {
            // Only the dialects of devices that can run the tier (its row of the tier table).
            if (std::find(glDialects.begin(), glDialects.end(), t.dialect) == glDialects.end()) continue;
            std::vector<std::pair<uint32_t, std::string>> blockNames;
            Result<std::string> text = spirvToGlsl(code.spirv, t, src.path, &blockNames);
            if (!text) return text.status();
            code.glsl[size_t(t.dialect)] = std::move(text.value());
            // The GL dialects name blocks as SPIRV-Cross declared them; GL binds by that name.
            for (const auto& [binding, blockName] : blockNames)
                for (ShaderResource& r : program.resources)
                    if (r.binding == binding && !blockName.empty()) r.glName = blockName;
        }
        program.stages.push_back(std::move(code));
    }
    if (!errors.empty()) return Status{StatusCode::ShaderError, errors};
    std::sort(program.resources.begin(), program.resources.end(),
              [](const ShaderResource& a, const ShaderResource& b) { return a.binding < b.binding; });
    return program;
}

Result<std::vector<ManifestEntry>> parseManifest(const std::string& path) {
    Result<std::string> text = readTextFile(path);
    if (!text) return text.status();
    std::vector<ManifestEntry> entries;
    std::istringstream in(text.value());
    std::string line;
    int lineNo = 0;
    std::set<std::string> names;
    std::string allTiers;  // "current,high": the manifest's spelling of every tier
    for (uint32_t t = 0; t < kTierCount; ++t) allTiers += std::string(t ? "," : "") + kTierNames[t];
    while (std::getline(in, line)) {
        ++lineNo;
        if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string s; words >> s;) w.push_back(s);
        if (w.empty()) continue;
        const std::string where = path + ":" + std::to_string(lineNo) + ": error: ";
        if (w.size() < 3)
            return Status{StatusCode::FileError, where + "expected 'name tiers file...', e.g. 'blur " + allTiers + " fullscreen.vert blur.frag'"};
        ManifestEntry e;
        e.name = w[0];
        e.line = lineNo;
        if (!names.insert(e.name).second) return Status{StatusCode::FileError, where + "program '" + e.name + "' listed twice"};
        std::istringstream tiers(w[1]);
        for (std::string t; std::getline(tiers, t, ',');) {
            Tier tier;
            if (!parseTier(t, &tier)) return Status{StatusCode::FileError, where + "unknown tier '" + t + "'; allowed " + tierNameList()};
            e.tiers.push_back(tier);
        }
        for (size_t i = 2; i < w.size(); ++i) {
            ShaderStage s;
            if (!stageFromPath(w[i], &s)) return Status{StatusCode::FileError, where + "'" + w[i] + "' has no stage extension (.vert .frag .comp)"};
            e.files.push_back(w[i]);
        }
        entries.push_back(std::move(e));
    }
    return entries;
}

namespace {
std::string identifier(const std::string& s) {
    std::string out;
    for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '_') ? c : '_';
    return out;
}

// Raw string literal with a delimiter that cannot occur in GLSL.
std::string rawString(const std::string& s) { return "R\"sfxglsl(" + s + ")sfxglsl\""; }
}  // namespace

// The SPIR-V array of stage `stage` of `p`, named after the program and tier so that the symbol
// table of a library shows which programs it embeds (tests/check_runtime_library.sh reads it).
static std::string spirvArrayName(const CompiledProgram& p, size_t stage) {
    return "kSpirv_" + identifier(p.name) + "_" + toString(p.tier) + "_" + std::to_string(stage);
}

Result<std::pair<std::string, std::string>> generateEmbedding(const std::vector<CompiledProgram>& programs, const EmbeddingDesc& desc) {
    const std::string ns = "sfx::" + desc.cppNamespace;
    const std::string generated = "// Generated by tools/sfxc from shader_src/" + desc.manifestName + ". Do not edit.\n";
    // Binding constants: one namespace per program; a resource must have one binding across tiers,
    // a uniform block one size.
    std::map<std::string, std::map<std::string, uint32_t>> bindings;
    std::map<std::string, std::map<std::string, const ShaderResource*>> uniformBlocks;
    for (const CompiledProgram& p : programs) {
        auto& names = bindings[p.name];
        auto& blocks = uniformBlocks[p.name];
        for (const ShaderResource& r : p.resources) {
            auto [it, inserted] = names.emplace(r.name, r.binding);
            if (!inserted && it->second != r.binding)
                return Status{StatusCode::ShaderError,
                              "program '" + p.name + "': resource '" + r.name + "' has binding " + std::to_string(it->second) + " on one tier and " +
                                  std::to_string(r.binding) + " on another"};
            if (r.kind != ResourceKind::UniformBuffer) continue;
            auto [block, added] = blocks.emplace(r.name, &r);
            if (!added && block->second->blockSize != r.blockSize)
                return Status{StatusCode::ShaderError,
                              "program '" + p.name + "': uniform block '" + r.name + "' is " + std::to_string(block->second->blockSize) +
                                  " bytes on one tier and " + std::to_string(r.blockSize) + " on another"};
        }
    }
    std::ostringstream h;
    h << generated
      << "#pragma once\n\n"
         "#include <array>\n#include <cstdint>\n#include <span>\n#include <string_view>\n\n#include \"sfx/shader_program.hpp\"\n"
         "#include \"sfx/status.hpp\"\n\n"
         "// Binding numbers reflected from the shaders, so no backend or effect hard-codes one, and\n"
         "// each program's uniform blocks (kUniformBlocks) for the check against the C++ structs.\n"
         "namespace sfx::gen {\n";
    for (const auto& [program, names] : bindings) {
        h << "namespace " << identifier(program) << " {\n";
        h << "inline constexpr const char* kName = \"" << program << "\";\n";
        for (const auto& [name, binding] : names) h << "inline constexpr uint32_t " << identifier(name) << " = " << binding << ";\n";
        const auto& blocks = uniformBlocks[program];
        h << "inline constexpr std::array<UniformBlockInfo, " << blocks.size() << "> kUniformBlocks{";
        if (!blocks.empty()) {
            h << "{";
            for (const auto& [name, r] : blocks) h << "{\"" << name << "\", " << r->blockSize << "u, " << r->binding << "u}, ";
            h << "}";
        }
        h << "};\n";
        h << "}  // namespace " << identifier(program) << "\n";
    }
    h << "}  // namespace sfx::gen\n\nnamespace " << ns
      << " {\n"
         "// Every program's reflected uniform blocks, by program name.\n"
         "inline constexpr ProgramUniformBlocks kUniformBlocks[] = {\n";
    for (const auto& [program, names] : bindings)
        h << "    {gen::" << identifier(program) << "::kName, gen::" << identifier(program) << "::kUniformBlocks},\n";
    h << "};\n"
         "// The embedded program `name` compiled for `tier`; InvalidArgument names the known ones.\n"
         "Result<const CompiledProgram*> find(std::string_view name, Tier tier);\n"
         "std::span<const CompiledProgram> all();\n}  // namespace "
      << ns << "\n";

    std::ostringstream c;
    c << generated << "#include \"" << desc.headerName << "\"\n\n#include <string>\n#include <vector>\n\nnamespace " << ns << " {\nnamespace {\n";
    for (size_t pi = 0; pi < programs.size(); ++pi) {
        const CompiledProgram& p = programs[pi];
        for (size_t si = 0; si < p.stages.size(); ++si) {
            c << "const uint32_t " << spirvArrayName(p, si) << "[] = {";
            const auto& words = p.stages[si].spirv;
            for (size_t w = 0; w < words.size(); ++w) c << (w % 12 == 0 ? "\n    " : " ") << words[w] << "u,";
            c << "\n};\n";
        }
    }
    c << "std::vector<CompiledProgram> build() {\n    std::vector<CompiledProgram> out;\n";
    for (size_t pi = 0; pi < programs.size(); ++pi) {
        const CompiledProgram& p = programs[pi];
        c << "    {\n        CompiledProgram p;\n        p.name = \"" << p.name << "\";\n        p.tier = Tier(" << uint32_t(p.tier) << ");\n";
        for (size_t si = 0; si < p.stages.size(); ++si) {
            const StageCode& s = p.stages[si];
            c << "        {\n            StageCode s;\n            s.stage = ShaderStage(" << uint32_t(s.stage) << ");\n"
              << "            s.spirv.assign(std::begin(" << spirvArrayName(p, si) << "), std::end(" << spirvArrayName(p, si) << "));\n";
            for (const DialectTarget& t : kGlTargets)
                c << "            s.glsl[" << size_t(t.dialect) << "] = " << rawString(s.glsl[size_t(t.dialect)]) << ";\n";
            c << "            p.stages.push_back(std::move(s));\n        }\n";
        }
        for (const ShaderResource& r : p.resources)
            c << "        p.resources.push_back({\"" << r.name << "\", \"" << r.glName << "\", ResourceKind(" << uint32_t(r.kind) << "), "
              << r.binding << "u, " << r.stages << "u, " << r.blockSize << "u});\n";
        c << "        out.push_back(std::move(p));\n    }\n";
    }
    c << "    return out;\n}\n\nconst std::vector<CompiledProgram>& library() {\n"
         "    static const std::vector<CompiledProgram> programs = build();\n    return programs;\n}\n}  // namespace\n\n"
         "std::span<const CompiledProgram> all() { return library(); }\n\n"
         "Result<const CompiledProgram*> find(std::string_view name, Tier tier) {\n"
         "    std::string known;\n"
         "    for (const CompiledProgram& p : library()) {\n"
         "        if (p.name == name && p.tier == tier) return &p;\n"
         "        if (p.tier == tier) known += (known.empty() ? \"\" : \", \") + p.name;\n"
         "    }\n"
         "    return Status{StatusCode::InvalidArgument, \"shader program '\" + std::string(name) + \"' has no \" +\n"
         "                      toString(tier) + \"-tier build; known: \" + known};\n"
         "}\n}  // namespace " +
            ns + "\n";
    return std::make_pair(h.str(), c.str());
}

}  // namespace sfx::shaderc
