// bench_families: every AO technique at its tier's defaults (and "no AO") against the ray-traced
// truth on the scene families (tools/scenes/scene_families.*), per family, tier and backend:
// PSNR over the frame, PSNR where the truth is occluded (< 0.95) and the mean signed error there
// (> 0 too bright). A peer measured on the same inputs (XeGTAO through tools/run_xegtao.sh) is
// scored against the same truth with the same metric: --write-inputs writes every view's linear
// depth and normals as PFMs, --peer-dir reads what the peer made of them. Writes
// <out-dir>/ao_families.csv, the tables of <out-dir>/ao_families.md between its markers and one
// picture per family (<out-dir>/images/ao_family_*.png). A program, not a test.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "analytic_scenes.hpp"
#include "ao_scoring.hpp"
#include "bench_device.hpp"
#include "copy_pass.hpp"
#include "markdown_section.hpp"
#include "peer_files.hpp"
#include "scene_families.hpp"
#include "sfx/image_io.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;

namespace {

using tools::fixed;

struct Options {
    uint32_t width = 320, height = 180, samples = 256;
    std::vector<std::string> backends{"vulkan", "gles"};
    std::string cacheDir = "build/truth-cache", outDir = "docs";
    std::string peerDir;      // where the peer's outputs are read from (empty: no peer rows)
    std::string writeInputs;  // where to write the peer's inputs, then stop (empty: score)
    uint32_t costWidth = 1280, costHeight = 720, runs = 7;
    std::string costView = "independent.sphere";
};

// One configuration's cost at the cost size: the SDK's (HAL-timed, beside a copy pass) or the
// peer's (its own timing).
struct CostRow {
    std::string measuredWith, backend, tier, technique;
    double ms = 0, copyMs = 0;
};

struct Row {
    size_t view;
    std::string backend, tier, technique, measuredWith;
    truth::Comparison error;
};

// A family's picture: the truth and each technique's output (high tier, first backend) and the
// peer's High preset on its first view, side by side at half size.
struct Panels {
    std::vector<std::string> labels;
    std::vector<reference::Grid> images;
};

reference::Grid truthGrid(const truth::Image& t) {
    reference::Grid g(t.width, t.height);
    for (size_t i = 0; i < g.values.size(); ++i) g.values[i] = t.visibility[i];
    return g;
}

Status writePicture(const std::string& path, const Panels& panels) {
    const uint32_t w = panels.images[0].width / 2, h = panels.images[0].height / 2, gap = 4;
    io::Image out(uint32_t(panels.images.size()) * (w + gap) - gap, h, 1, 1.0f);
    for (size_t p = 0; p < panels.images.size(); ++p) {
        const reference::Grid half = tools::downsample2x(panels.images[p]);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) out.pixels[size_t(y) * out.width + p * (w + gap) + x] = float(half.at(x, y));
    }
    return io::writePng(path, out);
}

struct Mean {
    double psnr = 0, psnrOccluded = 0, signedOccluded = 0;
    int n = 0, nOccluded = 0;
    void add(const truth::Comparison& e) {
        if (std::isfinite(e.psnr)) psnr += e.psnr, ++n;
        if (std::isfinite(e.psnrOccluded)) psnrOccluded += e.psnrOccluded, signedOccluded += e.meanSignedErrorOccluded, ++nOccluded;
    }
    // PSNR over the frame and where occluded, minus `base`'s, dB.
    std::string gainOver(const Mean& base) const {
        auto mean = [](double sum, int n) { return sum / std::max(n, 1); };
        return fixed(mean(psnr, n) - mean(base.psnr, base.n), 2) + " / " +
            fixed(mean(psnrOccluded, nOccluded) - mean(base.psnrOccluded, base.nOccluded), 2);
    }
    std::string cell() const {
        return fixed(psnr / std::max(n, 1), 2) + " / " + fixed(psnrOccluded / std::max(nOccluded, 1), 2) + " / " + (signedOccluded >= 0 ? "+" : "") +
            fixed(signedOccluded / std::max(nOccluded, 1), 3);
    }
};

std::string markdown(const Options& o, const std::vector<tools::TradeView>& views, const std::vector<Row>& rows, const std::string& machine,
                     const std::vector<CostRow>& costs) {
    const std::vector<tools::SceneFamily> families = tools::sceneFamilies();
    std::ostringstream md;
    md << "Measured by `build/tools/bench/bench_families` on " << machine << "; " << o.width << "x" << o.height << ", truth " << o.samples
       << " directions per pixel, each technique at its tier's defaults (blur on, G-buffer normals).\n\n";
    md << "| family | | how it is made | views: camera about the target |\n| --- | --- | --- | --- |\n";
    for (const tools::SceneFamily& f : families) {
        md << "| " << f.name << " | " << (f.heldOut ? "held out" : "training") << " | " << f.made << " |";
        for (const tools::TradeView& v : views)
            if (v.family == f.name) md << " `" << v.name() << "`: " << tools::describeCamera(v) << ";";
        md << " |\n";
    }
    std::map<bool, Mean> none;  // held out? -> no AO's mean
    for (const Row& r : rows)
        for (const tools::SceneFamily& f : families)
            if (r.technique == "none" && f.name == views[r.view].family) none[f.heldOut].add(r.error);
    const std::string first = o.backends.empty() ? "" : o.backends[0];
    for (const std::string& backend : {first, std::string("peer")}) {
        std::vector<std::string> keys;
        std::map<std::string, std::map<std::string, Mean>> cells;  // configuration -> family -> mean
        std::map<std::string, std::map<bool, Mean>> split;         // configuration -> held out? -> mean
        for (const Row& r : rows) {
            const bool peer = r.measuredWith != "sdk";
            if (peer != (backend == "peer") || (!peer && r.backend != backend && r.technique != "none")) continue;
            const std::string key = r.technique + " | " + r.tier;
            if (!cells.count(key)) keys.push_back(key);
            cells[key][views[r.view].family].add(r.error);
            for (const tools::SceneFamily& f : families)
                if (f.name == views[r.view].family) split[key][f.heldOut].add(r.error);
        }
        if (keys.empty()) continue;
        md << "\n"
           << (backend == "peer"
                   ? "Measured with the peer (XeGTAO, Intel's unmodified shaders, GL 4.5 compute on llvmpipe; the same PFM inputs, the same truth)"
                   : "Backend " + backend + " (and no AO)")
           << ": mean over each family's views of PSNR over the frame / PSNR where the truth < 0.95 (dB) / mean signed error there:\n\n";
        md << "| technique | tier |";
        for (const tools::SceneFamily& f : families) md << " " << f.name << (f.heldOut ? " (held out)" : "") << " |";
        md << " training families | held-out families | gain over no AO, training: frame / occluded | held out |\n| --- | --- |";
        for (size_t i = 0; i < families.size() + 4; ++i) md << " --- |";
        for (const std::string& key : keys) {
            md << "\n| " << key << " |";
            for (const tools::SceneFamily& f : families) md << " " << (cells[key].count(f.name) ? cells[key][f.name].cell() : "-") << " |";
            md << " " << split[key][false].cell() << " | " << split[key][true].cell() << " |";
            for (bool heldOut : {false, true}) md << " " << split[key][heldOut].gainOver(none[heldOut]) << " |";
        }
        md << "\n";
    }
    if (!costs.empty()) {
        md << "\nCost at " << o.costWidth << "x" << o.costHeight << " on `" << o.costView
           << "` at its radius, this machine, one run of tools/run_trade.sh: the SDK's effect dispatch timed by the HAL (median of " << o.runs
           << " runs, each beside a copy pass of the same size, whose median is given: load moves both), the peer's three passes timed "
              "with glFinish around each (median of its runs, minutes earlier in the same run):\n\n"
              "| measured with | backend | tier | technique | ms | copy pass ms |\n| --- | --- | --- | --- | --- | --- |\n";
        for (const CostRow& c : costs)
            md << "| " << c.measuredWith << " | " << c.backend << " | " << c.tier << " | " << c.technique << " | " << fixed(c.ms, 1) << " | "
               << (c.measuredWith == "sdk" ? fixed(c.copyMs, 2) : "-") << " |\n";
    }
    return md.str();
}

// Every technique at the tier's defaults on the cost view at the cost size: the median of
// o.runs HAL-timed dispatches, each beside a copy pass of that size (CopyPass::timeAgainst).
Status timeDefaults(Device& dev, const std::string& backend, Tier tier, const Options& o, const std::vector<tools::TradeView>& views,
                    std::vector<CostRow>& costs) {
    const tools::TradeView* view = nullptr;
    for (const tools::TradeView& v : views)
        if (v.name() == o.costView) view = &v;
    if (!view) return invalidArgument("cost view", "'" + o.costView + "'", "a family view");
    Result<tiers::TierChoice> choice = tiers::choose(dev.caps(), tier);
    if (!choice) return choice.status();
    const Format format = tools::aoOutputFormat(dev);
    Result<std::unique_ptr<tools::CopyPass>> copy = tools::makeCopyPass(dev, tier, o.costWidth, o.costHeight, format);
    if (!copy) return copy.status();
    Result<std::unique_ptr<tools::ViewInputs>> in = tools::ViewInputs::create(dev, tier, *view, o.costWidth, o.costHeight);
    if (!in) return in.status();
    Result<TextureHandle> out = dev.createTexture(
        {o.costWidth, o.costHeight, 1, format, kTextureSampled | kTextureRenderTarget, "families-cost-out"});
    if (!out) return out.status();
    Status status = Status::ok();
    for (AoTechnique technique : tools::allAoTechniques()) {
        AoSettings s;
        s.technique = technique;
        s.normals = AoNormals::FromTexture;
        s.radius = float(view->radius);
        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(
            dev, {o.costWidth, o.costHeight, choice->profile, s, in.value()->depthKind()});
        if (!ao) {
            status = ao.status();
            break;
        }
        const AoInputs inputs{DepthSource{in.value()->depth(), in.value()->depthKind(), in.value()->camera()}, in.value()->normals(), out.value()};
        Result<tools::CopyPass::Interleaved> r = copy.value()->timeAgainst(o.runs, [&] { return ao.value()->dispatch(inputs); });
        if (!r) {
            status = r.status();
            break;
        }
        costs.push_back({"sdk", backend, toString(tier), toString(technique), r->effectMs, r->copyMs});
        std::cout << "  " << backend << " " << toString(tier) << " " << toString(technique) << ": " << fixed(r->effectMs, 2) << " ms at "
                  << o.costWidth << "x" << o.costHeight << " (copy pass " << fixed(r->copyMs, 2) << " ms)" << std::endl;
    }
    (void)dev.destroyTexture(out.value());
    return status;
}

// Every technique at the tier's defaults on every view of one device, then its cost.
Status runDevice(Device& dev, const std::string& backend, Tier tier, const Options& o, const std::vector<tools::TradeView>& views,
                 const std::vector<tools::AoCase>& cases, std::vector<Row>& rows, std::vector<CostRow>& costs,
                 std::map<std::string, Panels>* pictures) {
    tools::AoEvaluator ev(dev, tier, o.width, o.height);
    SFX_TRY(ev.prepare(views));
    for (AoTechnique technique : tools::allAoTechniques()) {
        AoSettings s;
        s.technique = technique;
        s.normals = AoNormals::FromTexture;  // the G-buffer's normals, as a deferred renderer would
        std::vector<reference::Grid> outputs;
        Result<std::vector<truth::Comparison>> errors = ev.run(s, cases, &outputs);
        if (!errors) return errors.status();
        for (size_t c = 0; c < cases.size(); ++c) {
            rows.push_back({cases[c].view, backend, toString(tier), toString(technique), "sdk", errors.value()[c]});
            const tools::TradeView& v = views[cases[c].view];
            if (pictures && v.index == 0)
                (*pictures)[v.family].labels.push_back(toString(technique)), (*pictures)[v.family].images.push_back(outputs[c]);
        }
        Mean all;
        for (const truth::Comparison& e : errors.value()) all.add(e);
        std::cout << "  " << backend << " " << toString(tier) << " " << toString(technique) << ": mean over the views " << all.cell() << std::endl;
    }
    return timeDefaults(dev, backend, tier, o, views, costs);
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"bench_families - AO techniques against ray-traced truth, per scene family", "bench_families"};
    app.add_option("--width", o.width, "pixels")->capture_default_str();
    app.add_option("--height", o.height, "pixels")->capture_default_str();
    app.add_option("--samples", o.samples, "truth directions per pixel (a square >= 256)")->capture_default_str();
    app.add_option("--backends", o.backends, "comma-separated: vulkan, gles, gl, gl-egl, gl-osmesa")->delimiter(',')->capture_default_str();
    app.add_option("--cache-dir", o.cacheDir, "where truth images are cached")->capture_default_str();
    app.add_option("--out-dir", o.outDir, "ao_families.csv, ao_families.md (between its markers), images/")->capture_default_str();
    app.add_option("--peer-dir", o.peerDir, "score the peer's outputs found here (<view>.xegtao-<preset>.pfm, xegtao_cost.txt)");
    app.add_option("--write-inputs", o.writeInputs, "write every view's depth and normals PFMs and views.txt here (first backend), then stop");
    app.add_option("--cost-width", o.costWidth, "pixels of the timed runs (the SDK's and the peer's)")->capture_default_str();
    app.add_option("--cost-height", o.costHeight, "pixels of the timed runs (the SDK's and the peer's)")->capture_default_str();
    app.add_option("--runs", o.runs, "timed runs of each technique at the cost size (median)")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    const auto started = std::chrono::steady_clock::now();
    auto elapsed = [&] { return fixed(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 1); };
    auto fail = [](const Status& st) {
        std::cerr << "bench_families: " << st.toString() << "\n";
        return 1;
    };

    const std::vector<tools::TradeView> views = tools::allFamilyViews();
    if (!o.writeInputs.empty()) {
        const tools::PeerInputs inputs{o.writeInputs, o.backends.empty() ? "vulkan" : o.backends[0], o.width, o.height, o.costView, o.costWidth,
                                       o.costHeight};
        if (Status st = tools::writePeerInputs(inputs, views); !st) return fail(st);
        std::cout << "bench_families: the inputs of " << views.size() << " views and the cost view -> " << o.writeInputs << " in " << elapsed()
                  << " s" << std::endl;
        return 0;
    }
    const auto progress = [&](const std::string& line) { std::cout << "[" << elapsed() << " s] " << line << std::endl; };
    Result<std::vector<tools::AoCase>> cases = tools::loadCases(views, 0, views.size(), {}, {o.width, o.height, o.samples, o.cacheDir}, progress);
    if (!cases) return fail(cases.status());
    std::vector<Row> rows;
    std::map<std::string, Panels> pictures;
    std::vector<CostRow> costs;
    for (const tools::AoCase& c : cases.value()) {
        rows.push_back({c.view, "-", "-", "none", "sdk", truth::compare(c.truth, std::vector<double>(c.truth.visibility.size(), 1.0)).value()});
        if (views[c.view].index == 0) pictures[views[c.view].family] = {{"truth"}, {truthGrid(c.truth)}};
    }
    std::string machine;
    const Status run = tools::forEachDevice(
        o.backends, {Tier::High, Tier::Current}, "bench_families", [&](Device& dev, const std::string& backend, Tier tier) {
            if (machine.empty()) machine = dev.caps().deviceName;
            std::cout << "[" << elapsed() << " s] " << dev.caps().summary() << ", tier " << toString(tier) << std::endl;
            const bool pictured = backend == o.backends[0] && tier == Tier::High;
            return runDevice(dev, backend, tier, o, views, cases.value(), rows, costs, pictured ? &pictures : nullptr);
        });
    if (!run) return fail(run);
    if (!o.peerDir.empty()) {
        size_t found = 0;
        for (const tools::AoCase& c : cases.value())
            for (const std::string& preset : tools::kPeerPresets) {
                Result<tools::PeerScore> e = tools::scorePeerOutput(o.peerDir, views[c.view].name(), preset, c.truth);
                if (!e && e.status().code() == StatusCode::FileError) continue;  // not measured
                if (!e) return fail(e.status());
                rows.push_back({c.view, "gl4.5-llvmpipe", "-", "xegtao-" + preset, "peer", e->comparison});
                ++found;
                if (preset == "high" && views[c.view].index == 0) {
                    Panels& p = pictures[views[c.view].family];
                    p.labels.push_back("xegtao-high");
                    p.images.push_back(reference::Grid(c.truth.width, c.truth.height));
                    p.images.back().values = e->visibility;
                }
            }
        const std::vector<tools::PeerCost> peerCosts = tools::readPeerCosts(o.peerDir);
        for (const tools::PeerCost& c : peerCosts) costs.push_back({"peer", "gl4.5-llvmpipe", "-", "xegtao-" + c.preset, c.totalMs, 0});
        std::cout << "[" << elapsed() << " s] peer: " << found << " outputs scored from " << o.peerDir << ", " << peerCosts.size() << " timed presets"
                  << std::endl;
    }
    std::filesystem::create_directories(o.outDir + "/images");
    std::ofstream csv(o.outDir + "/ao_families.csv");
    csv << "family,held_out,view,width,height,radius,truth_samples,measured_with,backend,tier,technique,psnr_db,psnr_occluded_db,occluded_pixels,"
           "mean_signed_error,mean_signed_error_occluded\n";
    const std::vector<tools::SceneFamily> families = tools::sceneFamilies();
    for (const Row& r : rows) {
        const tools::TradeView& v = views[r.view];
        bool heldOut = false;
        for (const tools::SceneFamily& f : families) heldOut |= f.name == v.family && f.heldOut;
        csv << v.family << "," << (heldOut ? 1 : 0) << "," << v.name() << "," << o.width << "," << o.height << "," << v.radius << "," << o.samples
            << "," << r.measuredWith << "," << r.backend << "," << r.tier << "," << r.technique << "," << fixed(r.error.psnr, 3) << ","
            << fixed(r.error.psnrOccluded, 3) << "," << r.error.occludedPixels << "," << fixed(r.error.meanSignedError, 5) << ","
            << fixed(r.error.meanSignedErrorOccluded, 5) << "\n";
    }
    std::ofstream costCsv(o.outDir + "/ao_families_cost.csv");
    costCsv << "view,width,height,measured_with,backend,tier,technique,ms,copy_pass_ms\n";
    for (const CostRow& c : costs)
        costCsv << o.costView << "," << o.costWidth << "," << o.costHeight << "," << c.measuredWith << "," << c.backend << "," << c.tier << ","
                << c.technique << "," << fixed(c.ms, 3) << "," << (c.measuredWith == "sdk" ? fixed(c.copyMs, 3) : "-") << "\n";
    for (const auto& [family, panels] : pictures)
        if (Status st = writePicture(o.outDir + "/images/ao_family_" + family + ".png", panels); !st) return fail(st);
    if (Status st = tools::replaceMarkdownSection(o.outDir + "/ao_families.md", "bench_families",
                                                  markdown(o, views, rows, machine.empty() ? "no device" : machine, costs));
        !st)
        return fail(st);
    std::cout << "bench_families: " << rows.size() << " rows -> " << o.outDir << "/ao_families.csv, ao_families.md, images/ao_family_*.png in "
              << elapsed() << " s" << std::endl;
    return 0;
}
