// trade_presets: the measured Pareto front of the quality presets. For
// every backend x tier x preset of the tier table (x technique for AO):
//   - cost at --cost-size (median of HAL-timed runs, as ms and as copy passes of that size on
//     the same device): AO on the G-buffer of one sample view, motion blur on the "pan" scene;
//   - accuracy: AO's PSNR against the ray-traced truth on the held-out scene families (each view
//     at its own radius, 320x180), motion blur's PSNR against its temporally supersampled truth
//     over the moving region of the held-out motion families (960x720, the rows the tiers' radii
//     are given at, 6-120 px, as fit_mb scores them); both computed
//     on the first backend (the backends agree).
// Writes <out-dir>/trade_presets.csv, one SVG Pareto plot per backend and effect under
// <out-dir>/images/ and the tables into <out-dir>/trade.md between its markers. A program, not a test.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "ao_scoring.hpp"
#include "bench_device.hpp"
#include "copy_pass.hpp"
#include "markdown_section.hpp"
#include "mb_family_scoring.hpp"
#include "motion_cases.hpp"
#include "peer_files.hpp"
#include "scene_families.hpp"
#include "sfx/budget.hpp"
#include "sfx/tiers.hpp"
#include "svg_plot.hpp"

using namespace sfx;

namespace {

using tools::fixed;

struct Options {
    std::vector<std::string> backends{"vulkan", "gles"};
    uint32_t costWidth = 1280, costHeight = 720, runs = 11, instants = 256;
    tools::TruthSettings truth;
    std::string costView = "contact";
    std::string outDir = "docs";
    std::string peerDir;  // the peer's outputs on the held-out views and its cost (tools/run_xegtao.sh); empty: none
};

struct Row {
    std::string backend, tier, preset, effect, technique;  // technique "-" for motion blur
    std::string resolution = "-";                          // AO: "full" or "half"
    uint32_t taps = 0, blurOrRadius = 0;                   // AO: taps, blur half-width; MB: taps, max radius px
    double ms = 0, copyPasses = 0, psnr = 0, psnrOccluded = 0;
    bool presetsTechnique = false;  // AO: the technique the preset names (what an AoSettings without one runs)
};

// The peer (Intel's XeGTAO through tools/run_xegtao.sh, beside the project, never part of it) at
// one of its presets: its PSNR on the same held-out views against the same truth, and its cost at
// the cost size (its three passes timed with glFinish on llvmpipe's GL 4.5, minutes from the SDK's).
struct PeerPoint {
    std::string preset;
    tools::AoScore score;
    double ms = 0;
};

// Every peer preset whose outputs and cost were all found in o.peerDir (none without one).
Result<std::vector<PeerPoint>> peerPoints(const Options& o, const std::vector<tools::TradeView>& views, const std::vector<tools::AoCase>& cases) {
    std::vector<PeerPoint> out;
    if (o.peerDir.empty()) return out;
    const std::vector<tools::PeerCost> costs = tools::readPeerCosts(o.peerDir);
    for (const std::string& preset : tools::kPeerPresets) {
        const auto cost = std::find_if(costs.begin(), costs.end(), [&](const tools::PeerCost& c) { return c.preset == preset; });
        std::vector<truth::Comparison> errors;
        for (const tools::AoCase& c : cases) {
            Result<tools::PeerScore> e = tools::scorePeerOutput(o.peerDir, views[c.view].name(), preset, c.truth);
            if (!e && e.status().code() == StatusCode::FileError) break;  // not measured
            if (!e) return e.status();
            errors.push_back(e->comparison);
        }
        if (cost == costs.end() || errors.size() != cases.size()) continue;
        out.push_back({preset, tools::summarise(errors), cost->totalMs});
    }
    return out;
}

std::string peerLabel(const PeerPoint& p) { return "XeGTAO " + p.preset; }
const char* const kPeerSeries = "XeGTAO (measured here: GL 4.5 compute on llvmpipe)";

std::string describe(const Row& r) {
    return r.tier + "/" + r.preset + " " + r.technique + " (" + fixed(r.psnr, 2) + " dB, " + fixed(r.ms, 1) + " ms)";
}

// One line per backend and peer preset: among the SDK's AO presets (either tier, any technique),
// the cheapest at least as accurate on the held-out views and the most accurate in no more
// milliseconds; then each tier's default horizon beside them.
std::vector<std::string> peerDominance(const Options& o, const std::vector<Row>& rows, const std::vector<PeerPoint>& peers) {
    std::vector<std::string> lines;
    for (const std::string& backend : o.backends) {
        for (const PeerPoint& peer : peers) {
            const Row *cheapest = nullptr, *best = nullptr;
            for (const Row& r : rows) {
                if (r.backend != backend || r.effect != "ao") continue;
                if (r.psnr >= peer.score.psnr && (!cheapest || r.ms < cheapest->ms)) cheapest = &r;
                if (r.ms <= peer.ms && (!best || r.psnr > best->psnr)) best = &r;
            }
            lines.push_back(backend + ", " + peerLabel(peer) + " (" + fixed(peer.score.psnr, 2) + " dB, " + fixed(peer.ms, 1) +
                            " ms): the cheapest preset at least as accurate " + (cheapest ? describe(*cheapest) : std::string("none")) +
                            "; the most accurate in no more time " + (best ? describe(*best) : std::string("none")));
        }
        std::string line = backend + ", each tier's default horizon:";
        for (const Row& r : rows)
            if (r.backend == backend && r.effect == "ao" && r.preset == kDefaultPreset && r.technique == "horizon") line += " " + describe(r) + ";";
        if (!peers.empty()) lines.push_back(line);
    }
    return lines;
}

uint32_t aoTaps(const TierProfile& p, AoTechnique t) {
    if (t == AoTechnique::Horizon) return 2 * p.aoHorizonSlices * p.aoHorizonSteps;  // both sides of every slice
    return t == AoTechnique::Alchemy ? p.aoAlchemySamples : t == AoTechnique::Scalable ? p.aoScalableTaps : p.aoCreaseTaps;
}

// AO accuracy of every preset x technique of a tier on the held-out views (AoCase::view indexes
// `views`): key "preset/technique".
Result<std::map<std::string, tools::AoScore>> aoAccuracy(Device& dev, Tier tier, const Options& o, const std::vector<tools::TradeView>& views,
                                                         const std::vector<tools::AoCase>& cases) {
    tools::AoEvaluator ev(dev, tier, o.truth.width, o.truth.height);
    SFX_TRY(ev.prepare(views));
    std::map<std::string, tools::AoScore> out;
    for (const Preset& preset : tiers::row(tier).presets)
        for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon}) {
            ev.setProfile(preset.params);
            AoSettings s;
            s.technique = t;
            s.normals = AoNormals::FromTexture;
            Result<std::vector<truth::Comparison>> errors = ev.run(s, cases);
            if (!errors) return errors.status();
            const tools::AoScore a = tools::summarise(errors.value());
            out[preset.name + "/" + toString(t)] = a;
            std::cout << "  " << toString(tier) << "/" << preset.name << "/" << toString(t) << ": held-out PSNR " << fixed(a.psnr, 2)
                      << " dB, occluded " << fixed(a.psnrOccluded, 2) << " dB" << std::endl;
        }
    return out;
}

// Motion blur PSNR per preset of a tier: the mean over the held-out scene families and their
// speeds of the PSNR over the moving region (docs/motion_blur.md), as bench_mb_families scores.
Result<std::map<std::string, double>> motionAccuracy(Device& dev, Tier tier, const std::vector<tools::ScoredFamilyCase>& cases) {
    std::map<std::string, double> out;
    for (const tools::ScoredFamilyCase& c : cases) {
        PerspectiveDesc pd;
        pd.aspect = double(c.truth.width) / c.truth.height;
        const CameraProjection cam = makePerspective(pd).value();
        for (const Preset& preset : tiers::row(tier).presets) {
            Result<tools::MotionBlurRun> run = tools::runMotionBlur(dev, preset.params, {}, c.frame, cam, 1);
            if (!run) return run.status();
            out[preset.name] += tools::familyPsnr(run->output, c.truth, c.masks.moving) / double(cases.size());
        }
    }
    return out;
}

// The held-out views and their cases (AoCase::view indexes views).
struct AccuracyCases {
    std::vector<tools::TradeView> views;
    std::vector<tools::AoCase> heldOut;
    std::vector<tools::ScoredFamilyCase> motion;  // the held-out motion blur families
};

Status runDevice(Device& dev, const std::string& backend, Tier tier, const Options& o, const AccuracyCases& cases,
                 std::map<std::string, tools::AoScore>& aoScores, std::map<std::string, double>& mbScores, std::vector<Row>& rows) {
    const Format outFormat = tools::aoOutputFormat(dev);
    Result<std::unique_ptr<tools::CopyPass>> copy = tools::makeCopyPass(dev, tier, o.costWidth, o.costHeight, outFormat);
    if (!copy) return copy.status();
    if (aoScores.empty()) {  // accuracy from the first backend: the backends compute the same shaders
        Result<std::map<std::string, tools::AoScore>> a = aoAccuracy(dev, tier, o, cases.views, cases.heldOut);
        if (!a) return a.status();
        aoScores = a.value();
        Result<std::map<std::string, double>> m = motionAccuracy(dev, tier, cases.motion);
        if (!m) return m.status();
        mbScores = m.value();
    }
    // AO cost on one view's G-buffer at the cost size.
    Result<std::unique_ptr<tools::ViewInputs>> in = tools::ViewInputs::create(dev, tier, tools::TradeView{o.costView, false, 0, 1, 0}, o.costWidth,
                                                                              o.costHeight);
    if (!in) return in.status();
    Result<TextureHandle> out = dev.createTexture(
        {o.costWidth, o.costHeight, 1, outFormat, kTextureSampled | kTextureRenderTarget, "trade-cost-out"});
    if (!out) return out.status();
    Status status = Status::ok();
    for (const Preset& preset : tiers::row(tier).presets) {
        for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon}) {
            AoSettings s;
            s.technique = t;
            s.normals = AoNormals::FromTexture;
            Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(
                dev, {o.costWidth, o.costHeight, preset.params, s, in.value()->depthKind()});
            if (!ao) return ao.status();
            const AoInputs inputs{DepthSource{in.value()->depth(), in.value()->depthKind(), in.value()->camera()}, in.value()->normals(),
                                  out.value()};
            // Timed interleaved with copies (CopyPass::timeAgainst): on a loaded machine the load
            // drifts between configurations, and a ratio to a copy timed minutes earlier would drift
            // with it.
            Result<tools::CopyPass::Interleaved> r = copy.value()->timeAgainst(o.runs, [&] { return ao.value()->dispatch(inputs); });
            if (!r) {
                status = r.status();
                break;
            }
            const double copyMsNow = r->copyMs;
            const tools::AoScore& score = aoScores.at(preset.name + "/" + toString(t));
            rows.push_back({backend, toString(tier), preset.name, "ao", toString(t), preset.params.aoHalfResolution ? "half" : "full",
                            aoTaps(preset.params, t), preset.params.aoBlurRadiusPx, r->effectMs, r->ratio, score.psnr, score.psnrOccluded,
                            t == preset.params.aoTechnique});
            std::cout << "  " << backend << "/" << toString(tier) << "/" << preset.name << "/" << toString(t) << ": " << fixed(r->effectMs, 2)
                      << " ms = " << fixed(rows.back().copyPasses, 1) << " copy passes (copy " << fixed(copyMsNow, 3) << " ms), PSNR "
                      << fixed(score.psnr, 2) << " dB" << std::endl;
        }
        if (!status) break;
        // Motion blur cost on the "pan" scene at the cost size.
        PerspectiveDesc pd;
        pd.aspect = double(o.costWidth) / o.costHeight;
        const reference::SceneFrame frame = tools::makeMotionScenes(o.costWidth, o.costHeight)[1].scene.render(0);
        Result<tools::MotionBlurRun> mb = tools::runMotionBlur(dev, preset.params, {}, frame, makePerspective(pd).value(), o.runs);
        if (!mb) {
            status = mb.status();
            break;
        }
        // Its unit: copies timed right after (the effect times itself in runMotionBlur).
        Result<double> copyAfter = copy.value()->medianMs(o.runs);
        if (!copyAfter) {
            status = copyAfter.status();
            break;
        }
        const MotionBlurParams p = resolveMotionBlur(preset.params, {}, o.costHeight).value();
        rows.push_back({backend, toString(tier), preset.name, "motion-blur", "-", "-", p.taps, p.radiusPx, mb->medianMs,
                        mb->medianMs / copyAfter.value(), mbScores.at(preset.name), 0});
        std::cout << "  " << backend << "/" << toString(tier) << "/" << preset.name << "/motion blur: " << fixed(mb->medianMs, 2)
                  << " ms = " << fixed(rows.back().copyPasses, 1) << " copy passes, PSNR " << fixed(mbScores.at(preset.name), 2) << " dB"
                  << std::endl;
    }
    (void)dev.destroyTexture(out.value());
    return status;
}

std::string markdown(const Options& o, const std::vector<Row>& rows, const std::vector<PeerPoint>& peers, const std::string& machine) {
    std::ostringstream md;
    md << "Measured by `build/tools/bench/trade_presets` on " << machine << ". Cost at " << o.costWidth << "x" << o.costHeight << " (median of "
       << o.runs
       << " HAL-timed runs; copy passes = that cost over one full-screen copy of the same size on the same device: for AO the median ratio of runs "
          "timed interleaved with copies, for motion blur copies timed right after it); AO PSNR "
          "over the held-out scene families at each view's radius (docs/ao_families.md, "
       << o.truth.width << "x" << o.truth.height << "), motion blur PSNR over the moving region against " << o.instants
       << " supersampled instants, the mean over the held-out motion families at 6-120 px (docs/motion_blur.md, 960x720).\n\n";
    for (const std::string& backend : o.backends) {
        md << "![Pareto plot, AO, " << backend << "](images/pareto_ao_" << backend << ".svg)\n\n";
        md << "![Pareto plot, motion blur, " << backend << "](images/pareto_mb_" << backend << ".svg)\n\n";
    }
    if (peers.empty()) {
        md << "The peer (XeGTAO) was not measured in this run (no --peer-dir, or its harness did not build).\n\n";
    } else {
        md << "XeGTAO, measured beside the project in the same run of tools/run_trade.sh (Intel's unmodified shaders on llvmpipe's GL 4.5, its "
              "three passes timed with glFinish, minutes from the SDK's runs) on the same held-out views against the same truth:\n\n"
              "| XeGTAO preset | PSNR | PSNR occluded | signed error occluded | ms |\n| --- | --- | --- | --- | --- |\n";
        for (const PeerPoint& p : peers)
            md << "| " << p.preset << " | " << fixed(p.score.psnr, 2) << " | " << fixed(p.score.psnrOccluded, 2) << " | "
               << fixed(p.score.signedOccluded, 3) << " | " << fixed(p.ms, 1) << " |\n";
        md << "\n";
        for (const std::string& line : peerDominance(o, rows, peers)) md << "- " << line << "\n";
        md << "\n";
    }
    md << "Each preset names the AO technique an `AoSettings` without one runs; its row is marked *.\n\n";
    md << "| backend | tier | preset | effect | technique | AO resolution | taps | blur px / max radius px | ms | copy passes | PSNR | PSNR occluded "
          "|\n"
          "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const Row& r : rows)
        md << "| " << r.backend << " | " << r.tier << " | " << r.preset << " | " << r.effect << " | " << r.technique
           << (r.presetsTechnique ? " *" : "") << " | " << r.resolution << " | " << r.taps << " | " << r.blurOrRadius << " | " << fixed(r.ms, 2)
           << " | " << fixed(r.copyPasses, 1) << " | " << fixed(r.psnr, 2) << " | " << (r.effect == "ao" ? fixed(r.psnrOccluded, 2) : "-") << " |\n";
    return md.str();
}

Status writePlots(const Options& o, const std::vector<Row>& rows, const std::vector<PeerPoint>& peers) {
    std::filesystem::create_directories(o.outDir + "/images");
    for (const std::string& backend : o.backends)
        for (const std::string effect : {"ao", "motion-blur"}) {
            tools::Plot plot;
            plot.title = (effect == "ao" ? "AO" : "Motion blur") + std::string(" presets on ") + backend + " at " + std::to_string(o.costWidth) +
                "x" + std::to_string(o.costHeight);
            plot.xLabel = "cost, ms (this run)";
            plot.yLabel = effect == "ao" ? "PSNR against ray-traced truth, dB (held-out views)" : "PSNR against supersampled truth, dB";
            for (const Row& r : rows)
                if (r.backend == backend && r.effect == effect)
                    plot.points.push_back({r.ms, r.psnr, r.tier + "/" + r.preset + (r.presetsTechnique ? "*" : ""),
                                           effect == "ao" ? r.technique + " (" + r.tier + ")" : r.tier});
            if (effect == "ao")
                for (const PeerPoint& p : peers) plot.anchors.push_back({p.ms, p.score.psnr, peerLabel(p), kPeerSeries});
            SFX_TRY(tools::writeSvg(o.outDir + "/images/pareto_" + (effect == "ao" ? "ao_" : "mb_") + backend + ".svg", plot));
        }
    return Status::ok();
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"trade_presets - cost and accuracy of every tier preset, Pareto plots", "trade_presets"};
    app.add_option("--backends", o.backends, "comma-separated: vulkan, gles, gl, gl-egl, gl-osmesa")->delimiter(',')->capture_default_str();
    app.add_option("--cost-width", o.costWidth, "pixels of the timed runs")->capture_default_str();
    app.add_option("--cost-height", o.costHeight, "pixels of the timed runs")->capture_default_str();
    app.add_option("--runs", o.runs, "timed runs per configuration (median)")->capture_default_str();
    app.add_option("--instants", o.instants, "instants of the motion blur truth")->capture_default_str();
    app.add_option("--cache-dir", o.truth.cacheDir, "where truth images are cached")->capture_default_str();
    app.add_option("--peer-dir", o.peerDir, "the peer's outputs on the held-out views and its cost (tools/run_xegtao.sh): plotted and compared");
    app.add_option("--out-dir", o.outDir, "trade_presets.csv, images/pareto_*.svg and trade.md")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    const auto started = std::chrono::steady_clock::now();
    auto elapsed = [&] { return fixed(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 1); };

    AccuracyCases cases;
    cases.views = tools::familyViews(true);
    const auto progress = [&](const std::string& line) { std::cout << "[" << elapsed() << " s] " << line << std::endl; };
    Result<std::vector<tools::AoCase>> heldOut = tools::loadCases(cases.views, 0, cases.views.size(), {}, o.truth, progress);
    Result<std::vector<PeerPoint>> peers = heldOut ? peerPoints(o, cases.views, heldOut.value()) : Result<std::vector<PeerPoint>>(heldOut.status());
    if (!peers) {
        std::cerr << "trade_presets: " << peers.status().toString() << "\n";
        return 1;
    }
    if (!o.peerDir.empty()) progress(std::to_string(peers->size()) + " peer presets measured in " + o.peerDir);
    cases.heldOut = std::move(heldOut.value());
    // At 720 rows, where the tiers' radii are given: a preset's samples as far apart as in use.
    std::vector<double> motionSpeeds;
    for (double speed : tools::kScoredFamilySpeedsPx) motionSpeeds.push_back(speed * 3.0);
    cases.motion = tools::scoredFamilyCases(true, motionSpeeds, o.instants, 1, 960, 720, progress);
    std::map<Tier, std::map<std::string, tools::AoScore>> aoScores;
    std::map<Tier, std::map<std::string, double>> mbScores;
    std::vector<Row> rows;
    std::string machine;
    const Status run = tools::forEachDevice(
        o.backends, {Tier::High, Tier::Current}, "trade_presets", [&](Device& dev, const std::string& backend, Tier tier) {
            if (machine.empty()) machine = dev.caps().deviceName;
            std::cout << "[" << elapsed() << " s] " << dev.caps().summary() << ", tier " << toString(tier) << std::endl;
            return runDevice(dev, backend, tier, o, cases, aoScores[tier], mbScores[tier], rows);
        });
    if (!run) {
        std::cerr << "trade_presets: " << run.toString() << "\n";
        return 1;
    }
    std::filesystem::create_directories(o.outDir);
    std::ofstream csv(o.outDir + "/trade_presets.csv");
    csv << "backend,tier,preset,effect,technique,ao_resolution,taps,blur_or_max_radius_px,cost_width,cost_height,ms,copy_passes,psnr_db,psnr_"
           "occluded_db,presets_technique\n";
    for (const Row& r : rows)
        csv << r.backend << "," << r.tier << "," << r.preset << "," << r.effect << "," << r.technique << "," << r.resolution << "," << r.taps << ","
            << r.blurOrRadius << "," << o.costWidth << "," << o.costHeight << "," << fixed(r.ms, 3) << "," << fixed(r.copyPasses, 2) << ","
            << fixed(r.psnr, 3) << "," << fixed(r.psnrOccluded, 3) << "," << (r.presetsTechnique ? 1 : 0) << "\n";
    for (const PeerPoint& p : peers.value())
        csv << "peer,-," << p.preset << ",ao,xegtao,-,-,-," << o.costWidth << "," << o.costHeight << "," << fixed(p.ms, 3) << ",-,"
            << fixed(p.score.psnr, 3) << "," << fixed(p.score.psnrOccluded, 3) << ",-\n";
    for (const std::string& line : peerDominance(o, rows, peers.value())) std::cout << "versus the peer: " << line << std::endl;
    Status st = writePlots(o, rows, peers.value());
    if (st)
        st = tools::replaceMarkdownSection(o.outDir + "/trade.md", "trade_presets",
                                           markdown(o, rows, peers.value(), machine.empty() ? "no device" : machine));
    if (!st) {
        std::cerr << "trade_presets: " << st.toString() << "\n";
        return 1;
    }
    std::cout << "trade_presets: " << rows.size() << " rows -> " << o.outDir << "/trade_presets.csv, images/pareto_*.svg, trade.md in " << elapsed()
              << " s" << std::endl;
    return rows.empty() ? 1 : 0;
}
