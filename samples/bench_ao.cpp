// bench_ao: the measured trade of the AO techniques. For each technique x tier x backend on the
// analytic scenes: GPU cost (median of runs; Vulkan GPU timestamps, GL wall clock after glFinish,
// labelled), error against the converged CPU reference of the same technique (256 samples, no
// blur, no MIP, no radius clamp), cost relative to a full-screen copy pass, and cost at several
// radii. Writes ao_bench.csv, ao_bench_table.md and PNG images. A program, not a test.
//   bench_ao [--width 320 --height 180 --runs 7 --out-dir docs --backends vulkan,gles]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "analytic_scenes.hpp"
#include "sfx/ao.hpp"
#include "sfx/backends.hpp"
#include "sfx/image_io.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shaders.hpp"

using namespace sfx;

namespace {

struct Options {
    uint32_t width = 320, height = 180, runs = 7;
    std::string outDir = "docs";
    std::vector<std::string> backends{"vulkan", "gles"};
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// Times `record` (which records passes) `runs` times; returns the median in ms and the source.
template <class Fn>
Result<std::pair<double, TimingSource>> timeIt(Device& dev, uint32_t runs, Fn record) {
    Result<TimerHandle> timer = dev.createTimer();
    if (!timer) return timer.status();
    std::vector<double> ms;
    TimingSource source = dev.caps().timing;
    for (uint32_t i = 0; i < runs + 1; ++i) {  // the first run warms caches and compiles pipelines
        SFX_TRY(dev.beginTimer(timer.value()));
        SFX_TRY(record());
        SFX_TRY(dev.endTimer(timer.value()));
        SFX_TRY(dev.flush());
        Result<TimerReading> r = dev.readTimer(timer.value());
        if (!r) return r.status();
        source = r->source;
        if (i > 0) ms.push_back(r->milliseconds);
    }
    (void)dev.destroyTimer(timer.value());
    return std::make_pair(median(ms), source);
}

struct Row {
    std::string backend, tier, technique, scene, timing;
    double radius = 0, ms = 0, copyMs = 0, rmse = 0, maxErr = 0;
};

io::Image toImage(const reference::Grid& g) {
    io::Image im(g.width, g.height, 1);
    for (size_t i = 0; i < g.values.size(); ++i) im.pixels[i] = float(g.values[i]);
    return im;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--width") o.width = uint32_t(std::stoul(v));
        else if (k == "--height") o.height = uint32_t(std::stoul(v));
        else if (k == "--runs") o.runs = uint32_t(std::stoul(v));
        else if (k == "--out-dir") o.outDir = v;
        else if (k == "--backends") {
            o.backends.clear();
            std::stringstream ss(v);
            for (std::string b; std::getline(ss, b, ',');) o.backends.push_back(b);
        } else {
            std::cerr << "bench_ao: unknown flag " << k << "\n";
            return 2;
        }
    }
    if (argc % 2 == 0) {
        std::cerr << "usage: bench_ao [--width N --height N --runs N --out-dir DIR --backends vulkan,gles]\n";
        return 2;
    }
    std::filesystem::create_directories(o.outDir + "/images");
    const std::vector<samples::AnalyticScene> scenes{samples::cornerScene(o.width, o.height), samples::sphereOnPlaneScene(o.width, o.height),
                                                   samples::columnsScene(o.width, o.height)};
    const AoTechnique techniques[] = {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease};

    // Converged CPU references: many samples, no blur, no MIP, no clamp.
    std::cout << "bench_ao: converged CPU references (" << o.width << "x" << o.height << ")..." << std::endl;
    std::vector<std::vector<reference::Grid>> converged(3);
    for (int t = 0; t < 3; ++t)
        for (const samples::AnalyticScene& s : scenes) {
            AoSettings st;
            st.technique = techniques[t];
            st.blur = false;
            AoConfig c = resolveAoConfig(st, tiers::profile(Tier::High), 1).value();
            if (c.technique != AoTechnique::Crease) c.samples = 256;
            c.depthMipLevels = 1;
            c.maxRadiusPx = 0;
            converged[size_t(t)].push_back(reference::ambientVisibility(s.aoInput(false), c));
            std::cout << "  " << toString(techniques[t]) << " / " << s.name << std::endl;
        }

    std::vector<Row> rows;
    for (const std::string& backendName : o.backends)
        for (Tier tier : {Tier::High, Tier::Current}) {
            BackendConfig bc;
            if (!parseBackendConfig(backendName, &bc)) continue;
            DeviceOptions dopt;
            dopt.validation = false;
            dopt.ceiling = tier == Tier::Current ? CapabilityCeiling::GLES30 : CapabilityCeiling::None;
            Result<std::unique_ptr<Device>> dev = openDevice(bc, dopt);
            if (!dev) {
                std::cout << "bench_ao: skipping " << backendName << ": " << dev.status().toString() << std::endl;
                continue;
            }
            Device& d = *dev.value();
            Result<tiers::TierChoice> choice = tiers::choose(d.caps(), tier);
            if (!choice) {
                std::cout << "bench_ao: skipping " << backendName << "/" << toString(tier) << ": " << choice.status().toString() << std::endl;
                continue;
            }
            const Format outFormat = d.caps().renderableFormat[size_t(Format::R32F)] ? Format::R32F : Format::RGBA8;
            // The copy baseline: one full-screen pass reading a texture of the output's format.
            TextureHandle copySrc = d.createTexture({o.width, o.height, 1, outFormat, kTextureSampled | kTextureRenderTarget}).value();
            TextureHandle copyDst = d.createTexture({o.width, o.height, 1, outFormat, kTextureSampled | kTextureRenderTarget}).value();
            ProgramHandle copyProgram = d.createProgram(*shaders::find(gen::copy::kName, tier).value()).value();
            GraphicsPipelineDesc pd;
            pd.program = copyProgram;
            pd.colorFormats = {outFormat};
            PipelineHandle copyPipeline = d.createGraphicsPipeline(pd).value();
            auto copyPass = [&]() -> Status {
                RenderPassDesc rp;
                rp.colors = {ColorAttachment{copyDst, 0, LoadOp::DontCare, {}}};
                DrawDesc dr;
                dr.pipeline = copyPipeline;
                dr.bindings.textures = {TextureBinding{gen::copy::uSource, copySrc, 0, 1, {}}};
                return d.renderPass(rp, std::span<const DrawDesc>(&dr, 1));
            };
            auto copyTime = timeIt(d, o.runs, copyPass);
            const double copyMs = copyTime ? copyTime->first : 0.0;

            for (size_t si = 0; si < scenes.size(); ++si) {
                const samples::AnalyticScene& s = scenes[si];
                std::vector<float> depth(s.linearDepth.values.begin(), s.linearDepth.values.end());
                TextureHandle depthTex = d.createTexture({o.width, o.height, 1, Format::R32F, kTextureSampled}).value();
                (void)d.writeTexture(depthTex, 0, depth.data(), depth.size() * sizeof(float));
                TextureHandle outTex = d.createTexture({o.width, o.height, 1, outFormat, kTextureSampled | kTextureRenderTarget}).value();
                for (int t = 0; t < 3; ++t) {
                    const std::vector<double> radii = si == 0 ? std::vector<double>{0.25, 0.5, 1.0, 2.0} : std::vector<double>{0.5};
                    for (double radius : radii) {
                        AoSettings st;
                        st.technique = techniques[t];
                        st.radius = float(radius);
                        auto ao = AmbientObscurance::create(d, {o.width, o.height, choice->profile, st});
                        if (!ao) {
                            std::cout << "  error: " << ao.status().toString() << std::endl;
                            continue;
                        }
                        AoInputs in;
                        in.depth = DepthSource{depthTex, DepthKind::Linear, s.camera};
                        in.output = outTex;
                        auto time = timeIt(d, o.runs, [&] { return ao.value()->dispatch(in); });
                        if (!time) {
                            std::cout << "  error: " << time.status().toString() << std::endl;
                            continue;
                        }
                        Row r{backendName, toString(tier), toString(techniques[t]), s.name, toString(time->second), radius, time->first, copyMs};
                        if (radius == 0.5) {
                            reference::Grid gpu(o.width, o.height);
                            const size_t n = size_t(o.width) * o.height;
                            if (outFormat == Format::R32F) {
                                std::vector<float> px(n);
                                (void)d.readTexture(outTex, 0, px.data(), px.size() * 4);
                                for (size_t i = 0; i < n; ++i) gpu.values[i] = px[i];
                            } else {
                                std::vector<uint8_t> px(n * 4);
                                (void)d.readTexture(outTex, 0, px.data(), px.size());
                                for (size_t i = 0; i < n; ++i) gpu.values[i] = px[i * 4] / 255.0;
                            }
                            const reference::Grid& ref = converged[size_t(t)][si];
                            double sq = 0;
                            for (size_t i = 0; i < n; ++i) {
                                const double e = std::abs(gpu.values[i] - ref.values[i]);
                                sq += e * e;
                                r.maxErr = std::max(r.maxErr, e);
                            }
                            r.rmse = std::sqrt(sq / double(n));
                            const std::string img = o.outDir + "/images/ao_" + r.technique + "_" + r.tier + "_" + s.name + ".png";
                            if (backendName == o.backends.front()) (void)io::writePng(img, toImage(gpu));
                        }
                        std::printf("  %-7s %-8s %-9s %-8s r=%-5.2f %8.3f ms (%s)  copy %.3f ms  x%.1f  rmse %.4f max %.3f\n",
                                    r.backend.c_str(), r.tier.c_str(), r.technique.c_str(), r.scene.c_str(), radius, r.ms,
                                    r.timing.c_str(), copyMs, copyMs > 0 ? r.ms / copyMs : 0.0, r.rmse, r.maxErr);
                        std::fflush(stdout);
                        rows.push_back(r);
                    }
                }
                (void)d.destroyTexture(depthTex);
                (void)d.destroyTexture(outTex);
            }
            (void)d.destroyPipeline(copyPipeline);
            (void)d.destroyProgram(copyProgram);
            (void)d.destroyTexture(copySrc);
            (void)d.destroyTexture(copyDst);
        }
    for (int t = 0; t < 3; ++t)
        for (size_t si = 0; si < scenes.size(); ++si)
            (void)io::writePng(o.outDir + "/images/ao_" + std::string(toString(techniques[t])) + "_reference_" + scenes[si].name + ".png",
                               toImage(converged[size_t(t)][si]));

    std::ofstream csv(o.outDir + "/ao_bench.csv");
    csv << "backend,tier,technique,scene,radius,ms,timing,copy_ms,ratio_to_copy,rmse,max_error\n";
    std::ofstream md(o.outDir + "/ao_bench_table.md");
    md << "| backend | tier | technique | scene | radius | ms (median) | timing | x copy | RMSE | max err |\n";
    md << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const Row& r : rows) {
        const double ratio = r.copyMs > 0 ? r.ms / r.copyMs : 0.0;
        csv << r.backend << "," << r.tier << "," << r.technique << "," << r.scene << "," << r.radius << "," << r.ms << "," << r.timing
            << "," << r.copyMs << "," << ratio << "," << (r.radius == 0.5 ? std::to_string(r.rmse) : "") << ","
            << (r.radius == 0.5 ? std::to_string(r.maxErr) : "") << "\n";
        char line[512];
        std::snprintf(line, sizeof line, "| %s | %s | %s | %s | %.2f | %.3f | %s | %.1f | %s | %s |\n", r.backend.c_str(), r.tier.c_str(),
                      r.technique.c_str(), r.scene.c_str(), r.radius, r.ms, r.timing.c_str(), ratio,
                      r.radius == 0.5 ? std::to_string(r.rmse).substr(0, 6).c_str() : "-",
                      r.radius == 0.5 ? std::to_string(r.maxErr).substr(0, 5).c_str() : "-");
        md << line;
    }
    std::cout << "bench_ao: wrote " << o.outDir << "/ao_bench.csv, ao_bench_table.md and images/ao_*.png (" << rows.size() << " rows)\n";
    return 0;
}
