// bench_ao: the measured trade of the AO techniques. For each backend x tier x technique on the
// sample scenes (tools/scenes/scene.*, rasterised through the HAL, bunny included):
//   - cost of the whole effect (median of runs, profiling off), labelled GPU timestamps (Vulkan)
//     or wall clock after glFinish (GL);
//   - cost of each planned pass (linearize, depth_mip levels, obscurance, blur h, blur v) from
//     the effect's own profiling, as median ms and as a ratio to one full-screen copy pass of
//     the same size on the same backend;
//   - error (RMSE, max) against the converged CPU reference of the same technique (256 samples,
//     no blur, no MIP, no radius clamp) run on the G-buffer read back from the device;
//   - on one scene, the cost at several radii (the high tier's depth MIP should keep it flat).
// Writes ao_bench.csv, ao_bench_table.md and PNG images. A program, not a test.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>

#include "bench_args.hpp"
#include "bench_device.hpp"
#include "copy_pass.hpp"
#include "pass_profile.hpp"
#include "scene.hpp"
#include "sfx/ao.hpp"
#include "sfx/backends.hpp"
#include "sfx/budget.hpp"
#include "sfx/image_io.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;
using tools::median;
using tools::PassCost;
using tools::splitList;

namespace {

const char* kUsage =
    "usage: bench_ao [--width 320] [--height 180] [--runs 9] [--out-dir docs]\n"
    "                [--backends vulkan,gles] [--scenes bunny,corner,steps,columns,contact]\n"
    "                [--radii 0.25,0.5,1,2,4] [--sweep-scene corner] [--image-scenes bunny,corner]\n"
    "                [--reference-samples 256]\n";

struct Options {
    uint32_t width = 320, height = 180, runs = 9, referenceSamples = 256;
    std::string outDir = "docs";
    std::vector<std::string> backends{"vulkan", "gles"};
    std::vector<std::string> scenes{"bunny", "corner", "steps", "columns", "contact"};
    std::vector<double> radii{0.25, 0.5, 1.0, 2.0, 4.0};
    std::string sweepScene = "corner";
    std::vector<std::string> imageScenes{"bunny", "corner"};
};
constexpr double kErrorRadius = 0.5;  // the radius the error columns and images use

bool parseOptions(int argc, char** argv, Options* o) {
    for (int i = 1; i < argc; i += 2) {
        const std::string k = argv[i];
        if (k == "--help" || i + 1 >= argc) return false;
        const std::string v = argv[i + 1];
        if (k == "--width")
            o->width = uint32_t(std::stoul(v));
        else if (k == "--height")
            o->height = uint32_t(std::stoul(v));
        else if (k == "--runs")
            o->runs = std::max(1u, uint32_t(std::stoul(v)));
        else if (k == "--reference-samples")
            o->referenceSamples = uint32_t(std::stoul(v));
        else if (k == "--out-dir")
            o->outDir = v;
        else if (k == "--backends")
            o->backends = splitList(v);
        else if (k == "--scenes")
            o->scenes = splitList(v);
        else if (k == "--image-scenes")
            o->imageScenes = splitList(v);
        else if (k == "--sweep-scene")
            o->sweepScene = v;
        else if (k == "--radii") {
            o->radii.clear();
            for (const std::string& r : splitList(v)) o->radii.push_back(std::stod(r));
        } else {
            std::cerr << "bench_ao: unknown flag " << k << "\n";
            return false;
        }
    }
    return true;
}

bool contains(const std::vector<std::string>& list, const std::string& item) { return std::find(list.begin(), list.end(), item) != list.end(); }

// The reference's input from what the device rendered: D32F depth linearised on the CPU by
// the reference's own formula, normals exactly as the GPU reads them (half floats).
Result<reference::AoInput> readGBuffer(Device& dev, const tools::GBuffer& g) {
    Result<tools::GBufferContents> contents = tools::readBack(dev, g);
    if (!contents) return contents.status();
    Result<DepthReconstruction> rec = makeDepthReconstruction(g.camera, g.width, g.height);
    if (!rec) return rec.status();
    const size_t n = size_t(g.width) * g.height;
    reference::AoInput in;
    in.reconstruction = rec.value();
    reference::Grid storedGrid(g.width, g.height);
    for (size_t i = 0; i < n; ++i) storedGrid.values[i] = contents->storedDepth[i];
    in.linearDepth = reference::linearizeDepth(storedGrid, in.reconstruction);
    in.normals.resize(n);
    for (size_t i = 0; i < n; ++i) in.normals[i] = glm::dvec3(contents->normals[i]);
    return in;
}

// A cheap fingerprint of a G-buffer read-back, so identical renders (the same backend on both
// tiers) share one converged reference instead of recomputing it.
uint64_t fingerprint(const reference::AoInput& in) {
    uint64_t h = 1469598103934665603ull;
    auto mix = [&](double v) {
        uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = (h ^ bits) * 1099511628211ull;
    };
    for (double v : in.linearDepth.values) mix(v);
    for (const glm::dvec3& n : in.normals) mix(n.x), mix(n.y), mix(n.z);
    return h;
}

// The same technique, converged: many samples, no blur, no MIP, no radius clamp.
AoConfig convergedConfig(const AoSettings& settings, uint32_t samples, uint32_t rows) {
    AoSettings s = settings;
    s.blur = false;
    AoConfig c = resolveAoConfig(s, tiers::profile(Tier::High), 1, rows).value();
    if (c.technique == AoTechnique::Alchemy || c.technique == AoTechnique::Scalable) c.samples = samples;  // Crease's 24-tap pattern is fixed
    if (c.technique == AoTechnique::Horizon) c.horizon = {16, 32, c.horizon.thickness, c.horizon.falloff}, c.samples = 16;
    c.depthMipLevels = 1;
    c.maxRadiusPx = 0;
    return c;
}

io::Image toImage(const reference::Grid& g) {
    io::Image im(g.width, g.height, 1);
    for (size_t i = 0; i < g.values.size(); ++i) im.pixels[i] = float(g.values[i]);
    return im;
}

struct Row {
    std::string backend, tier, technique, scene, timing;
    double radius = 0;
    double totalMs = 0;            // whole effect, profiling off
    double totalRatio = 0;         // whole effect in copy passes, timed interleaved with the copy
    std::vector<PassCost> passes;  // per pass, profiling on
    double copyMs = 0;             // the interleaved copy's median: the unit of the per-pass ratios
    bool hasError = false;
    double rmse = 0, maxErr = 0;
};

double ratio(double ms, double copyMs) { return copyMs > 0 ? ms / copyMs : 0.0; }

void printRow(const Row& r) {
    std::printf("  %-6s %-7s %-8s %-7s r=%-4.2f  %7.3f ms = x%-6.1f", r.backend.c_str(), r.tier.c_str(), r.technique.c_str(), r.scene.c_str(),
                r.radius, r.totalMs, r.totalRatio);
    if (r.hasError) std::printf("  rmse %.4f max %.3f", r.rmse, r.maxErr);
    std::printf("  |");
    for (const PassCost& p : r.passes) std::printf(" %s %.2f", p.name.c_str(), p.ms);
    std::printf("\n");
    std::fflush(stdout);
}

// Table cell "ms (x copy)".
std::string cellOfRatio(double ms, double toCopy) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f (%.1f)", ms, toCopy);
    return buf;
}
std::string cell(double ms, double copyMs) { return cellOfRatio(ms, ratio(ms, copyMs)); }
std::string totalCell(const Row& r) { return cellOfRatio(r.totalMs, r.totalRatio); }

double passMs(const Row& r, const std::string& prefix) {
    double sum = 0;
    for (const PassCost& p : r.passes)
        if (p.name.rfind(prefix, 0) == 0) sum += p.ms;
    return sum;
}

void writeOutputs(const Options& o, const std::vector<Row>& rows, const std::string& machine) {
    std::ofstream csv(o.outDir + "/ao_bench.csv");
    // Long format: one line for the whole effect (pass "total", profiling off) and one per
    // planned pass (profiling on) of every configuration.
    csv << "backend,tier,technique,scene,radius,timing,pass,ms,copy_ms,ratio_to_copy,rmse,max_error\n";
    for (const Row& r : rows) {
        auto line = [&](const std::string& pass, double ms, double toCopy, bool error) {
            csv << r.backend << "," << r.tier << "," << r.technique << "," << r.scene << "," << r.radius << "," << r.timing << "," << pass << ","
                << ms << "," << r.copyMs << "," << toCopy << ",";
            if (error)
                csv << r.rmse << "," << r.maxErr;
            else
                csv << ",";
            csv << "\n";
        };
        line("total", r.totalMs, r.totalRatio, r.hasError);
        for (const PassCost& p : r.passes) line(p.name, p.ms, ratio(p.ms, r.copyMs), false);
    }

    std::ofstream md(o.outDir + "/ao_bench_table.md");
    md << "Machine: " << machine << "; " << o.width << "x" << o.height << ", median of " << o.runs << " runs.\n\n";
    md << "Whole effect (profiling off) and error against the converged reference, radius " << kErrorRadius << ":\n\n";
    md << "| backend | tier | technique | scene | timing | ms (x copy) | RMSE | max err |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const Row& r : rows) {
        if (!r.hasError) continue;
        char line[512];
        std::snprintf(line, sizeof line, "| %s | %s | %s | %s | %s | %s | %.4f | %.3f |\n", r.backend.c_str(), r.tier.c_str(), r.technique.c_str(),
                      r.scene.c_str(), r.timing.c_str(), totalCell(r).c_str(), r.rmse, r.maxErr);
        md << line;
    }
    const std::string passScene = contains(o.scenes, "bunny") ? "bunny" : o.scenes.front();
    md << "\nPer pass (profiling on), scene " << passScene << ", radius " << kErrorRadius
       << "; ms (x copy); depth_mip is the sum of its levels (each in the CSV):\n\n";
    md << "| backend | tier | technique | copy ms | linearize | depth_mip | half-size depth | obscurance | blur h | blur v | upsample | sum of "
          "passes | whole effect |\n";
    md << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const Row& r : rows) {
        if (!r.hasError || r.scene != passScene) continue;
        double sum = 0;
        for (const PassCost& p : r.passes) sum += p.ms;
        // A pass the configuration does not plan (no MIP, full resolution, no linearisation) is "-".
        const auto optional = [&](const std::string& prefix) {
            const double ms = passMs(r, prefix);
            return ms > 0 ? cell(ms, r.copyMs) : std::string("-");
        };
        char line[1024];
        std::snprintf(line, sizeof line, "| %s | %s | %s | %.3f | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.backend.c_str(), r.tier.c_str(),
                      r.technique.c_str(), r.copyMs, optional("linearize").c_str(), optional("depth_mip").c_str(),
                      optional("half-size depth").c_str(), cell(passMs(r, "obscurance"), r.copyMs).c_str(), optional("bilateral blur h").c_str(),
                      optional("bilateral blur v").c_str(), optional("depth-aware upsample").c_str(), cell(sum, r.copyMs).c_str(),
                      totalCell(r).c_str());
        md << line;
    }
    md << "\nRadius sweep, scene " << o.sweepScene << ": obscurance pass ms (x copy) / whole effect ms:\n\n| backend | tier | technique |";
    for (double radius : o.radii) md << " r = " << radius << " |";
    md << "\n| --- | --- | --- |";
    for (size_t i = 0; i < o.radii.size(); ++i) md << " --- |";
    md << "\n";
    std::map<std::string, std::map<double, const Row*>> sweep;  // "backend|tier|technique" -> radius -> row
    std::vector<std::string> order;
    for (const Row& r : rows) {
        if (r.scene != o.sweepScene) continue;
        const std::string key = r.backend + " | " + r.tier + " | " + r.technique;
        if (!sweep.count(key)) order.push_back(key);
        sweep[key][r.radius] = &r;
    }
    for (const std::string& key : order) {
        md << "| " << key << " |";
        for (double radius : o.radii) {
            const auto it = sweep[key].find(radius);
            if (it == sweep[key].end()) {
                md << " - |";
                continue;
            }
            char buf[96];
            std::snprintf(buf, sizeof buf, " %s / %.2f |", cell(passMs(*it->second, "obscurance"), it->second->copyMs).c_str(), it->second->totalMs);
            md << buf;
        }
        md << "\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parseOptions(argc, argv, &o) || o.scenes.empty()) {
        std::cerr << kUsage;
        return 2;
    }
    const auto started = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
    std::filesystem::create_directories(o.outDir + "/images");
    std::vector<tools::RasterScene> scenes;
    for (const std::string& name : o.scenes) {
        Result<tools::RasterScene> scene = tools::makeScene(name);
        if (!scene) {
            std::cerr << "bench_ao: scene " << name << ": " << scene.status().toString() << "\n";
            return 1;
        }
        scenes.push_back(std::move(scene.value()));
    }
    const AoTechnique techniques[] = {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon};
    std::cout << "bench_ao: " << o.width << "x" << o.height << ", " << o.runs << " runs, scenes";
    for (const std::string& s : o.scenes) std::cout << " " << s;
    std::cout << "; backends";
    for (const std::string& b : o.backends) std::cout << " " << b;
    std::cout << std::endl;

    std::map<std::pair<uint64_t, int>, reference::Grid> converged;  // (G-buffer fingerprint, technique)
    std::vector<Row> rows;
    std::string machine;
    for (const std::string& backendName : o.backends)
        for (Tier tier : {Tier::High, Tier::Current}) {
            BackendConfig bc;
            if (!parseBackendConfig(backendName, &bc)) {
                std::cout << "bench_ao: unknown backend " << backendName << std::endl;
                continue;
            }
            Result<std::unique_ptr<Device>> opened = tools::openForTier(bc, tier);
            if (!opened) {
                std::cout << "bench_ao: skipping " << backendName << ": " << opened.status().toString() << std::endl;
                continue;
            }
            Device& dev = *opened.value();
            Result<tiers::TierChoice> choice = tiers::choose(dev.caps(), tier);
            if (!choice) {
                std::cout << "bench_ao: skipping " << backendName << "/" << toString(tier) << ": " << choice.status().toString() << std::endl;
                continue;
            }
            if (machine.empty()) machine = dev.caps().deviceName;
            std::cout << "[" << elapsed() << " s] " << dev.caps().summary() << std::endl;
            Result<std::unique_ptr<tools::SceneRenderer>> renderer = tools::SceneRenderer::create(dev, tier);
            if (!renderer) {
                std::cout << "bench_ao: scene renderer: " << renderer.status().toString() << std::endl;
                continue;
            }
            const Format outFormat = tools::aoOutputFormat(dev);
            Result<std::unique_ptr<tools::CopyPass>> copy = tools::makeCopyPass(dev, tier, o.width, o.height, outFormat);
            if (!copy) {
                std::cout << "bench_ao: copy pass: " << copy.status().toString() << std::endl;
                continue;
            }
            Result<TextureHandle> outTex = dev.createTexture(
                {o.width, o.height, 1, outFormat, kTextureSampled | kTextureRenderTarget, "bench-ao-out"});
            if (!outTex) {
                std::cout << "bench_ao: output: " << outTex.status().toString() << std::endl;
                continue;
            }

            for (const tools::RasterScene& scene : scenes) {
                Status loaded = renderer.value()->load(scene);
                Result<tools::GBuffer> g = loaded ? renderer.value()->render(scene, o.width, o.height) : Result<tools::GBuffer>(loaded);
                if (!g) {
                    std::cout << "  " << scene.name << ": " << g.status().toString() << std::endl;
                    continue;
                }
                Result<reference::AoInput> refInput = readGBuffer(dev, g.value());
                if (!refInput) {
                    std::cout << "  " << scene.name << ": G-buffer read-back: " << refInput.status().toString() << std::endl;
                    renderer.value()->destroy(g.value());
                    continue;
                }
                const uint64_t print = fingerprint(refInput.value());
                for (int t = 0; t < 3; ++t) {
                    AoSettings settings;
                    settings.technique = techniques[t];
                    settings.normals = AoNormals::FromTexture;  // the G-buffer's normals, as a deferred renderer would
                    const bool sweep = scene.name == o.sweepScene;
                    std::vector<double> radii{kErrorRadius};
                    if (sweep)
                        for (double r : o.radii)
                            if (r != kErrorRadius) radii.push_back(r);
                    std::sort(radii.begin(), radii.end());
                    for (double radius : radii) {
                        settings.radius = float(radius);
                        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(dev,
                                                                                                  {o.width, o.height, choice->profile, settings});
                        if (!ao) {
                            std::cout << "  error: " << ao.status().toString() << std::endl;
                            continue;
                        }
                        const AoInputs in{DepthSource{g->depth, DepthKind::Hardware, g->camera}, g->normals, outTex.value()};
                        Result<tools::CopyPass::Interleaved> total = copy.value()->timeAgainst(o.runs, [&] { return ao.value()->dispatch(in); });
                        Result<tools::DispatchCost> passes = total ? tools::profilePasses(
                                                                         dev, *ao.value(), [&] { return ao.value()->dispatch(in); }, o.runs)
                                                                   : Result<tools::DispatchCost>(total.status());
                        if (!passes) {
                            std::cout << "  error: " << passes.status().toString() << std::endl;
                            continue;
                        }
                        Row r{backendName,     toString(tier), toString(techniques[t]), scene.name,   toString(dev.caps().timing), radius,
                              total->effectMs, total->ratio,   passes->passes,          total->copyMs};
                        if (radius == kErrorRadius) {
                            // The last profiled dispatch left its output: identical to an unprofiled one (conformance).
                            Result<reference::Grid> gpu = tools::readVisibility(dev, outTex.value(), outFormat, o.width, o.height);
                            if (!gpu) {
                                std::cout << "  error: " << gpu.status().toString() << std::endl;
                                continue;
                            }
                            const auto key = std::make_pair(print, t);
                            if (!converged.count(key))
                                converged[key] = reference::ambientVisibility(refInput.value(),
                                                                              convergedConfig(settings, o.referenceSamples, o.height));
                            const reference::Grid& ref = converged[key];
                            double sq = 0;
                            for (size_t i = 0; i < ref.values.size(); ++i) {
                                const double e = std::abs(gpu->values[i] - ref.values[i]);
                                sq += e * e;
                                r.maxErr = std::max(r.maxErr, e);
                            }
                            r.rmse = std::sqrt(sq / double(ref.values.size()));
                            r.hasError = true;
                            // Images from the first backend only: the backends agree (cross-backend tests).
                            if (backendName == o.backends.front() && contains(o.imageScenes, scene.name)) {
                                const std::string base = o.outDir + "/images/ao_" + r.technique + "_";
                                (void)io::writePng(base + r.tier + "_" + scene.name + ".png", toImage(gpu.value()));
                                if (tier == Tier::High) (void)io::writePng(base + "reference_" + scene.name + ".png", toImage(ref));
                            }
                        }
                        printRow(r);
                        rows.push_back(std::move(r));
                    }
                }
                renderer.value()->destroy(g.value());
            }
            (void)dev.destroyTexture(outTex.value());
        }
    writeOutputs(o, rows, machine.empty() ? "unknown" : machine);
    std::cout << "bench_ao: wrote " << o.outDir << "/ao_bench.csv, ao_bench_table.md and images/ao_*.png (" << rows.size() << " configurations) in "
              << elapsed() << " s" << std::endl;
    return rows.empty() ? 1 : 0;
}
