// bench_trade: the AO techniques' error against ray-traced ground truth.
// For each sample scene, the truth (tools/truth: Embree, docs/trade.md gives the definition) is
// traced once per size, radius and sample count and cached under --cache-dir; then for every
// backend x tier x technique x blur on/off the SDK renders AO of the scene's G-buffer with the
// same camera and radius, and the result is scored: PSNR (peak 1) over the frame and where the
// truth is below 0.95, mean signed error, worst pixel. "none" (visibility 1) is the baseline.
// Writes <out-dir>/trade.csv and the tables into <out-dir>/trade.md between its markers. The
// numbers are for accuracy, not cost (software rasterisers). A program, not a test.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "bench_device.hpp"
#include "markdown_section.hpp"
#include "scene.hpp"
#include "sfx/ao.hpp"
#include "sfx/tiers.hpp"
#include "sfx/truth_metrics.hpp"
#include "truth_cache.hpp"

using namespace sfx;

namespace {

using tools::fixed;

struct Options {
    uint32_t width = 320, height = 180, samples = 256;
    double radius = 0.5;
    std::vector<std::string> backends{"vulkan", "gles"};
    std::vector<std::string> scenes = tools::sceneNames();
    std::string cacheDir = "build/truth-cache", outDir = "docs";
};

struct Truth {
    truth::Image image;
    double seconds = 0;       // 0 when read from the cache
    double measuredStdError;  // from a second, independently seeded trace
};

// The truth for one scene and seed, from the cache or traced (and then cached).
Result<truth::Image> cachedTruth(const Options& o, const tools::TruthScene& scene, uint32_t seed, double* seconds) {
    truth::Settings s;
    s.radius = o.radius;
    s.samples = o.samples;
    s.seed = seed;
    return tools::cachedTruth(o.cacheDir, scene, s, seconds);
}

Result<Truth> truthFor(const Options& o, const std::string& name) {
    Result<tools::TruthScene> scene = tools::makeTruthScene(name, o.width, o.height);
    if (!scene) return scene.status();
    Truth t;
    Result<truth::Image> main = cachedTruth(o, scene.value(), 0, &t.seconds);
    if (!main) return main.status();
    double seconds2 = 0;
    Result<truth::Image> second = cachedTruth(o, scene.value(), 1, &seconds2);
    if (!second) return second.status();
    double sq = 0;
    size_t n = 0;
    for (size_t i = 0; i < main->visibility.size(); ++i)
        if (main->isSurface(i)) {
            const double d = double(main->visibility[i]) - second->visibility[i];
            sq += d * d;
            ++n;
        }
    t.measuredStdError = n ? std::sqrt(sq / double(n) / 2.0) : 0.0;  // Var(a - b) = 2 Var(a)
    t.image = std::move(main.value());
    return t;
}

struct Row {
    std::string scene, backend, tier, technique;
    bool blur = false;
    truth::Comparison error;
};

void printRow(const Row& r) {
    std::printf("  %-8s %-6s %-7s %-8s blur %-3s  PSNR %6s dB, occluded %6s dB (%zu px), signed %+.4f (occluded %+.4f), worst %.3f at (%u, %u)\n",
                r.scene.c_str(), r.backend.c_str(), r.tier.c_str(), r.technique.c_str(), r.blur ? "on" : "off", fixed(r.error.psnr, 2).c_str(),
                fixed(r.error.psnrOccluded, 2).c_str(), r.error.occludedPixels, r.error.meanSignedError, r.error.meanSignedErrorOccluded,
                r.error.worstError, r.error.worstX, r.error.worstY);
    std::fflush(stdout);
}

// Every technique x tier x blur on one device, for every scene.
Status runDevice(Device& dev, const std::string& backend, Tier tier, const Options& o, const std::map<std::string, Truth>& truths,
                 std::vector<Row>& rows) {
    Result<tiers::TierChoice> choice = tiers::choose(dev.caps(), tier);
    if (!choice) return choice.status();
    Result<std::unique_ptr<tools::SceneRenderer>> renderer = tools::SceneRenderer::create(dev, tier);
    if (!renderer) return renderer.status();
    const Format outFormat = tools::aoOutputFormat(dev);
    Result<TextureHandle> out = dev.createTexture({o.width, o.height, 1, outFormat, kTextureSampled | kTextureRenderTarget, "trade-ao-out"});
    if (!out) return out.status();
    Status status = Status::ok();
    for (const std::string& name : o.scenes) {
        Result<tools::RasterScene> scene = tools::makeScene(name);
        if (!scene) return scene.status();
        SFX_TRY(renderer.value()->load(scene.value()));
        Result<tools::GBuffer> g = renderer.value()->render(scene.value(), o.width, o.height);
        if (!g) return g.status();
        for (AoTechnique technique : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon})
            for (bool blur : {true, false}) {
                AoSettings s;
                s.technique = technique;
                s.radius = float(o.radius);
                s.blur = blur;
                s.normals = AoNormals::FromTexture;  // the G-buffer's normals, as a deferred renderer would
                Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(dev, {o.width, o.height, choice->profile, s});
                if (!ao) return ao.status();
                status = ao.value()->dispatch({DepthSource{g->depth, DepthKind::Hardware, g->camera}, g->normals, out.value()});
                if (status) status = dev.flush();
                if (!status) break;
                Result<reference::Grid> vis = tools::readVisibility(dev, out.value(), outFormat, o.width, o.height);
                if (!vis) return vis.status();
                Result<truth::Comparison> e = truth::compare(truths.at(name).image, vis->values);
                if (!e) return e.status();
                rows.push_back({name, backend, toString(tier), toString(technique), blur, e.value()});
                printRow(rows.back());
            }
        renderer.value()->destroy(g.value());
        if (!status) break;
    }
    (void)dev.destroyTexture(out.value());
    return status;
}

// Means over the scenes of each configuration (PSNR averaged in dB), then per scene.
std::string markdown(const Options& o, const std::vector<Row>& rows, const std::map<std::string, Truth>& truths, const std::string& machine) {
    std::ostringstream md;
    md << "Measured by `build/tools/bench/bench_trade` on " << machine << " (software rasterisers: the numbers are for accuracy, not cost); "
       << o.width << "x" << o.height << ", radius " << o.radius << ", truth " << o.samples << " directions per pixel.\n\n";
    md << "Truth per scene: surface pixels, occluded pixels (truth < 0.95), the binomial standard-error bound averaged over the surface, "
          "the measured per-pixel standard error (two seeds), trace time on this machine:\n\n";
    md << "| scene | surface px | occluded px | mean bound | measured std error | trace s |\n| --- | --- | --- | --- | --- | --- |\n";
    for (const std::string& name : o.scenes) {
        const Truth& t = truths.at(name);
        size_t surface = 0, occluded = 0;
        for (size_t i = 0; i < t.image.visibility.size(); ++i) {
            surface += t.image.isSurface(i);
            occluded += t.image.isSurface(i) && t.image.visibility[i] < truth::kOccludedBelow;
        }
        md << "| " << name << " | " << surface << " | " << occluded << " | " << fixed(truth::meanStdErrorBound(t.image), 4) << " | "
           << fixed(t.measuredStdError, 4) << " | " << (t.seconds > 0 ? fixed(t.seconds, 2) : "cached") << " |\n";
    }
    struct Sum {
        double psnr = 0, psnrOccluded = 0, signedOccluded = 0, worst = 0;
        int n = 0;
    };
    std::vector<std::string> order;
    std::map<std::string, Sum> sums;
    for (const Row& r : rows) {
        const std::string key = r.technique + " | " + r.tier + " | " + (r.technique == "none" ? "-" : r.blur ? "on" : "off") + " | " + r.backend;
        if (!sums.count(key)) order.push_back(key);
        Sum& s = sums[key];
        s.psnr += r.error.psnr, s.psnrOccluded += r.error.psnrOccluded, s.signedOccluded += r.error.meanSignedErrorOccluded;
        s.worst = std::max(s.worst, r.error.worstError);
        ++s.n;
    }
    md << "\nMean over the " << o.scenes.size()
       << " scenes (PSNR in dB averaged; signed error where the truth < 0.95: > 0 too bright; "
          "worst = the largest |error| of any pixel of any scene):\n\n";
    md << "| technique | tier | blur | backend | PSNR | PSNR occluded | signed error occluded | worst |\n| --- | --- | --- | --- | --- | --- | --- | "
          "--- |\n";
    for (const std::string& key : order) {
        const Sum& s = sums[key];
        md << "| " << key << " | " << fixed(s.psnr / s.n, 2) << " | " << fixed(s.psnrOccluded / s.n, 2) << " | " << fixed(s.signedOccluded / s.n, 3)
           << " | " << fixed(s.worst, 3) << " |\n";
    }
    const std::string first = rows.size() > o.scenes.size() ? rows[o.scenes.size()].backend : "";
    md << "\nPer scene, backend " << first << " (and the baseline): PSNR over the frame / where the truth < 0.95, dB:\n\n| technique | tier | blur |";
    for (const std::string& name : o.scenes) md << " " << name << " |";
    md << "\n| --- | --- | --- |";
    for (size_t i = 0; i < o.scenes.size(); ++i) md << " --- |";
    std::vector<std::string> keys;
    std::map<std::string, std::map<std::string, const Row*>> byScene;  // configuration -> scene -> row
    for (const Row& r : rows) {
        if (r.backend != first && r.technique != "none") continue;
        const std::string key = r.technique + " | " + r.tier + " | " + (r.technique == "none" ? "-" : r.blur ? "on" : "off");
        if (!byScene.count(key)) keys.push_back(key);
        byScene[key][r.scene] = &r;
    }
    for (const std::string& key : keys) {
        md << "\n| " << key << " |";
        for (const std::string& name : o.scenes) {
            const auto it = byScene[key].find(name);
            if (it == byScene[key].end())
                md << " - |";
            else
                md << " " << fixed(it->second->error.psnr, 1) << " / " << fixed(it->second->error.psnrOccluded, 1) << " |";
        }
    }
    md << "\n";
    return md.str();
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"bench_trade - AO techniques against ray-traced ground truth", "bench_trade"};
    app.add_option("--width", o.width, "pixels")->capture_default_str();
    app.add_option("--height", o.height, "pixels")->capture_default_str();
    app.add_option("--radius", o.radius, "world-space AO radius of the effects and the truth")->capture_default_str();
    app.add_option("--samples", o.samples, "truth directions per pixel (a square >= 256)")->capture_default_str();
    app.add_option("--backends", o.backends, "comma-separated: vulkan, gles, gl, gl-egl, gl-osmesa")->delimiter(',')->capture_default_str();
    app.add_option("--scenes", o.scenes, "comma-separated sample scenes")->delimiter(',')->capture_default_str();
    app.add_option("--cache-dir", o.cacheDir, "where truth images are cached (keyed by scene, size, radius, samples, seed)")->capture_default_str();
    app.add_option("--out-dir", o.outDir, "trade.csv and trade.md (tables between its bench_trade markers)")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    const auto started = std::chrono::steady_clock::now();
    auto elapsed = [&] { return fixed(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 1); };

    std::map<std::string, Truth> truths;
    std::vector<Row> rows;
    for (const std::string& name : o.scenes) {
        Result<Truth> t = truthFor(o, name);
        if (!t) {
            std::cerr << "bench_trade: truth of " << name << ": " << t.status().toString() << "\n";
            return 1;
        }
        std::cout << "[" << elapsed() << " s] truth " << name << ": " << (t->seconds > 0 ? fixed(t->seconds, 2) + " s" : "cached")
                  << ", measured per-pixel std error " << fixed(t->measuredStdError, 4) << std::endl;
        Row none{name, "-", "-", "none", false, truth::compare(t->image, std::vector<double>(t->image.visibility.size(), 1.0)).value()};
        printRow(none);
        rows.push_back(none);
        truths.emplace(name, std::move(t.value()));
    }
    std::string machine;
    const Status run = tools::forEachDevice(
        o.backends, {Tier::High, Tier::Current}, "bench_trade", [&](Device& dev, const std::string& backend, Tier tier) {
            if (machine.empty()) machine = dev.caps().deviceName;
            std::cout << "[" << elapsed() << " s] " << dev.caps().summary() << ", tier " << toString(tier) << std::endl;
            return runDevice(dev, backend, tier, o, truths, rows);
        });
    if (!run) {
        std::cerr << "bench_trade: " << run.toString() << "\n";
        return 1;
    }
    std::filesystem::create_directories(o.outDir);
    std::ofstream csv(o.outDir + "/trade.csv");
    csv << "scene,width,height,radius,truth_samples,backend,tier,technique,blur,psnr_db,psnr_occluded_db,occluded_pixels,"
           "mean_signed_error,mean_signed_error_occluded,worst_error,worst_x,worst_y\n";
    for (const Row& r : rows)
        csv << r.scene << "," << o.width << "," << o.height << "," << o.radius << "," << o.samples << "," << r.backend << "," << r.tier << ","
            << r.technique << ","
            << (r.technique == "none" ? "-"
                    : r.blur          ? "on"
                                      : "off")
            << "," << fixed(r.error.psnr, 3) << "," << fixed(r.error.psnrOccluded, 3) << "," << r.error.occludedPixels << ","
            << fixed(r.error.meanSignedError, 5) << "," << fixed(r.error.meanSignedErrorOccluded, 5) << "," << fixed(r.error.worstError, 4) << ","
            << r.error.worstX << "," << r.error.worstY << "\n";
    if (Status st = tools::replaceMarkdownSection(o.outDir + "/trade.md", "bench_trade",
                                                  markdown(o, rows, truths, machine.empty() ? "no device" : machine));
        !st) {
        std::cerr << "bench_trade: " << st.toString() << "\n";
        return 1;
    }
    std::cout << "bench_trade: " << rows.size() << " rows -> " << o.outDir << "/trade.csv and " << o.outDir << "/trade.md in " << elapsed() << " s"
              << std::endl;
    return 0;
}
