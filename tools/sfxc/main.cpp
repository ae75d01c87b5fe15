// sfxc: the ScalableFX shader compiler. Compiles shader_src/ GLSL 450 to SPIR-V and to the
// GL dialects the backends need, with binding reflection; the build uses its --manifest mode
// to embed every program, and users can compile single files for inspection.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "sfx/shader_compiler.hpp"

namespace fs = std::filesystem;
using namespace sfx;

namespace {

bool writeFile(const std::string& path, const void* data, size_t size) {
    std::ofstream out(path, std::ios::binary);
    if (!out) return false;
    out.write(static_cast<const char*>(data), std::streamsize(size));
    return bool(out);
}

void printReflection(const CompiledProgram& p) {
    std::cout << "program " << p.name << " (" << toString(p.tier) << " tier)\n";
    for (const ShaderResource& r : p.resources) {
        std::cout << "  binding " << r.binding << ": " << toString(r.kind) << " " << r.name;
        if (r.glName != r.name) std::cout << " (GL name " << r.glName << ")";
        if (r.blockSize) std::cout << ", " << r.blockSize << " bytes";
        std::cout << ", stages";
        for (uint32_t s = 0; s < 3; ++s)
            if (r.stages & (1u << s)) std::cout << " " << toString(ShaderStage(s));
        std::cout << "\n";
    }
}

int runManifest(const std::string& manifest, const std::vector<std::string>& includes, const std::string& outHeader, const std::string& outSource,
                const std::string& cppNamespace, bool verbose) {
    Result<std::vector<shaderc::ManifestEntry>> entries = shaderc::parseManifest(manifest);
    if (!entries) {
        std::cerr << entries.status().message() << "\n";
        return 1;
    }
    const fs::path dir = fs::path(manifest).parent_path();
    std::vector<CompiledProgram> programs;
    int failures = 0;
    size_t done = 0, total = 0;
    for (const auto& e : entries.value()) total += e.tiers.size();
    for (const auto& e : entries.value()) {
        std::vector<shaderc::StageSource> stages;
        for (const std::string& f : e.files) {
            shaderc::StageSource s;
            s.path = (dir / f).string();
            shaderc::stageFromPath(f, &s.stage);
            Result<std::string> text = shaderc::readTextFile(s.path);
            if (!text) {
                std::cerr << manifest << ":" << e.line << ": error: " << text.status().message() << "\n";
                return 1;
            }
            s.text = std::move(text.value());
            stages.push_back(std::move(s));
        }
        for (Tier tier : e.tiers) {
            shaderc::CompileOptions opts;
            opts.tier = tier;
            opts.includeDirs = includes;
            Result<CompiledProgram> p = shaderc::compileProgram(e.name, stages, opts);
            ++done;
            if (!p) {
                std::cerr << p.status().message();
                ++failures;
                continue;
            }
            if (verbose) std::cout << "sfxc [" << done << "/" << total << "] " << e.name << " (" << toString(tier) << ")\n";
            programs.push_back(std::move(p.value()));
        }
    }
    if (failures) {
        std::cerr << "sfxc: " << failures << " program build(s) failed\n";
        return 1;
    }
    if (outHeader.empty()) {
        std::cout << "sfxc: " << programs.size() << " program builds compiled to spirv, essl300, essl310, glsl330, glsl450\n";
        return 0;
    }
    shaderc::EmbeddingDesc desc;
    desc.headerName = fs::path(outHeader).filename().string();
    desc.manifestName = fs::path(manifest).filename().string();
    desc.cppNamespace = cppNamespace;
    auto gen = shaderc::generateEmbedding(programs, desc);
    if (!gen) {
        std::cerr << "sfxc: error: " << gen.status().message() << "\n";
        return 1;
    }
    if (!writeFile(outHeader, gen->first.data(), gen->first.size()) || !writeFile(outSource, gen->second.data(), gen->second.size())) {
        std::cerr << "sfxc: error: cannot write " << outHeader << " or " << outSource << "\n";
        return 1;
    }
    std::cout << "sfxc: embedded " << programs.size() << " program builds from " << manifest << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "sfxc - the ScalableFX shader compiler.\n"
        "Compiles GLSL 450 (shader_src/) with glslang to SPIR-V, validates it with SPIRV-Tools,\n"
        "and cross-compiles it with SPIRV-Cross to ESSL 300, ESSL 310, GLSL 330 and GLSL 450.\n"
        "Errors are printed as file:line: message.\n\n"
        "Examples:\n"
        "  sfxc shader_src/linearize_depth.frag --target essl300 --tier current -I shader_src/include\n"
        "  sfxc shader_src/depth_mip.frag --target spirv -o depth_mip.spv --reflect\n"
        "  sfxc --manifest shader_src/programs.txt --check\n",
        "sfxc"};
    std::vector<std::string> files;
    std::string target = "spirv", tierName = kTierNames[kTierCount - 1], output, manifest, outHeader, outSource, cppNamespace = "shaders";
    std::vector<std::string> includes, defines;
    bool reflectFlag = false, check = false, verbose = false;
    app.add_option("files", files, "shader files (.vert .frag .comp) to compile one by one");
    app.add_option("--target,-t", target, "spirv | essl300 | essl310 | glsl330 | glsl450")->capture_default_str();
    app.add_option("--tier", tierName, "the tier (" + tierNameList() + "): defines what the tier table generates for it, e.g. SFX_TIER_HIGH")
        ->capture_default_str();
    app.add_option("-o,--output", output, "output file (one input file); default: GLSL to stdout");
    app.add_option("-I,--include", includes, "include directory (repeatable)");
    app.add_option("-D,--define", defines, "NAME or NAME=VALUE (repeatable)");
    app.add_flag("--reflect", reflectFlag, "print the reflected resources and their bindings");
    app.add_option("--manifest", manifest, "programs.txt: compile every program for its tiers and all targets");
    app.add_option("--out-header", outHeader, "with --manifest: generated C++ header");
    app.add_option("--out-source", outSource, "with --manifest: generated C++ source embedding the programs");
    app.add_option("--namespace", cppNamespace, "with --manifest: namespace under sfx:: for find() and all(), one per embedded library")
        ->capture_default_str();
    app.add_flag("--check", check, "with --manifest: compile everything, write nothing");
    app.add_flag("-v,--verbose", verbose, "print each program as it compiles");
    CLI11_PARSE(app, argc, argv);

    if (!manifest.empty()) {
        if (!check && (outHeader.empty() || outSource.empty())) {
            std::cerr << "sfxc: error: --manifest needs --out-header and --out-source, or --check\n";
            return 2;
        }
        if (includes.empty()) includes.push_back((fs::path(manifest).parent_path() / "include").string());
        const bool identifier = !cppNamespace.empty() && !std::isdigit(static_cast<unsigned char>(cppNamespace[0])) &&
            std::all_of(cppNamespace.begin(), cppNamespace.end(), [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; });
        if (!identifier) {
            std::cerr << "sfxc: error: --namespace '" << cppNamespace << "' is not a C++ identifier (letters, digits, _)\n";
            return 2;
        }
        return runManifest(manifest, includes, check ? "" : outHeader, outSource, cppNamespace, verbose || check);
    }
    if (files.empty()) {
        std::cerr << "sfxc: error: no input files (see --help)\n";
        return 2;
    }
    ShaderDialect dialect;
    if (!parseShaderDialect(target, &dialect)) {
        std::cerr << "sfxc: error: --target '" << target << "' is unknown; allowed spirv, essl300, essl310, glsl330, glsl450\n";
        return 2;
    }
    Tier tier;
    if (!parseTier(tierName, &tier)) {
        std::cerr << "sfxc: error: --tier '" << tierName << "' is unknown; allowed " << tierNameList() << "\n";
        return 2;
    }
    if (!output.empty() && files.size() != 1) {
        std::cerr << "sfxc: error: -o takes one input file; " << files.size() << " given\n";
        return 2;
    }
    shaderc::CompileOptions opts;
    opts.tier = tier;
    opts.includeDirs = includes;
    for (const std::string& d : defines) {
        size_t eq = d.find('=');
        opts.defines.push_back({d.substr(0, eq), eq == std::string::npos ? "" : d.substr(eq + 1)});
    }
    int rc = 0;
    for (const std::string& f : files) {
        shaderc::StageSource s;
        s.path = f;
        if (!shaderc::stageFromPath(f, &s.stage)) {
            std::cerr << f << ":0: error: unknown stage; name the file .vert, .frag or .comp\n";
            rc = 1;
            continue;
        }
        Result<std::string> text = shaderc::readTextFile(f);
        if (!text) {
            std::cerr << text.status().message() << "\n";
            rc = 1;
            continue;
        }
        s.text = std::move(text.value());
        Result<CompiledProgram> p = shaderc::compileProgram(fs::path(f).stem().string(), {s}, opts);
        if (!p) {
            std::cerr << p.status().message();
            rc = 1;
            continue;
        }
        const StageCode& code = p->stages[0];
        if (reflectFlag) printReflection(p.value());
        if (dialect == ShaderDialect::Spirv) {
            if (!output.empty() && !writeFile(output, code.spirv.data(), code.spirv.size() * 4)) {
                std::cerr << output << ":0: error: cannot write\n";
                rc = 1;
            } else if (output.empty() && !reflectFlag) {
                std::cout << f << ": " << code.spirv.size() << " SPIR-V words, valid (use -o to write them)\n";
            }
        } else {
            const std::string& glsl = code.glsl[size_t(dialect)];
            if (!output.empty()) {
                if (!writeFile(output, glsl.data(), glsl.size())) {
                    std::cerr << output << ":0: error: cannot write\n";
                    rc = 1;
                }
            } else {
                std::cout << glsl;
            }
        }
    }
    return rc;
}
