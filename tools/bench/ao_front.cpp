// ao_front: the measured front AO's presets are chosen from. For each tier, a grid of AO
// configurations around the tier's default profile (technique; Alchemy samples, Scalable taps or
// horizon slices x steps; blur width; full or half resolution) is
//   - scored against the ray-traced truth on the training scene families, which the front and so
//     the choice read, and on the held-out ones, reported beside (each view at its own radius,
//     320x180, on the first backend: the backends compute the same shaders), and
//   - timed at --cost-size on every backend on one view's G-buffer, interleaved with full-screen
//     copies (the median of the per-run ratios beside the median milliseconds), in --rounds
//     passes over the grid, the fastest pass kept.
// Writes <out-dir>/ao_front.csv (every configuration, its front membership per backend; psnr_db
// and the columns after it are held out), one SVG
// per backend x tier under <out-dir>/images/ and, between trade.md's ao_front markers, each
// tier's front on the backends' geometric mean cost with every preset's point. The grid holds
// every preset of the tier table, so a preset off the front shows. A program, not a test.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "ao_scoring.hpp"
#include "bench_device.hpp"
#include "copy_pass.hpp"
#include "markdown_section.hpp"
#include "scene_families.hpp"
#include "sfx/tiers.hpp"
#include "svg_plot.hpp"

using namespace sfx;

namespace {

using tools::fixed;

struct Options {
    std::vector<std::string> backends{"vulkan", "gles"};
    std::vector<std::string> tiers{"high", "current"};
    std::vector<std::string> techniques{"alchemy", "scalable", "crease", "horizon"};
    uint32_t costWidth = 1280, costHeight = 720, runs = 7, rounds = 3;
    tools::TruthSettings truth;
    std::string costView = "contact";
    std::string outDir = "docs";
};

// One AO configuration: the tier's default profile with these changed.
struct Config {
    AoTechnique technique = AoTechnique::Scalable;
    bool half = true;
    uint32_t count = 0;                        // Alchemy samples or Scalable taps; crease: the tier's
    uint32_t slices = 0, steps = 0, blur = 0;  // horizon's counts; blur half-width, output pixels
    std::string counts() const {
        if (technique == AoTechnique::Horizon) return std::to_string(slices) + "x" + std::to_string(steps);
        return std::to_string(count);
    }
    std::string name() const {
        return std::string(toString(technique)) + " " + counts() + " blur " + std::to_string(blur) + (half ? " half" : " full");
    }
    TierProfile apply(TierProfile p) const {
        p.aoTechnique = technique;
        p.aoHalfResolution = half;
        p.aoBlurRadiusPx = blur;
        if (technique == AoTechnique::Alchemy) p.aoAlchemySamples = count;
        if (technique == AoTechnique::Scalable) p.aoScalableTaps = count;
        if (technique == AoTechnique::Horizon) p.aoHorizonSlices = slices, p.aoHorizonSteps = steps;
        if (technique == AoTechnique::Crease) p.aoCreaseTaps = count;
        return p;
    }
};

bool wanted(const std::vector<std::string>& techniques, AoTechnique t) {
    return std::find(techniques.begin(), techniques.end(), toString(t)) != techniques.end();
}

// The grid: every technique at counts from its cheapest useful to beyond the tier's ultra preset,
// at half resolution with three blur widths and at full resolution with the widest.
std::vector<Config> grid(const TierProfile& d, const std::vector<std::string>& techniques) {
    const bool high = d.tier == Tier::High;
    // Half-width in output pixels; at half size the blur takes (r + 1) / 2 taps a side, so 1 and 2
    // are the same pass and only 2 is measured.
    const std::vector<uint32_t> blurs = high ? std::vector<uint32_t>{2, 4, 6} : std::vector<uint32_t>{2, 4};
    const uint32_t fullBlur = high ? 8 : 4;
    std::vector<Config> out;
    if (wanted(techniques, AoTechnique::Alchemy))
        for (uint32_t n : {3u, 4u, 6u, 8u, 12u, 16u}) {
            for (uint32_t b : blurs) out.push_back({AoTechnique::Alchemy, true, n, 0, 0, b});
            if (n >= 8) out.push_back({AoTechnique::Alchemy, false, n, 0, 0, fullBlur});
        }
    if (wanted(techniques, AoTechnique::Scalable))
        // Mirrored taps come in pairs (the current tier's).
        for (uint32_t n : d.aoScalableMirrored ? std::vector<uint32_t>{2, 4, 6, 8, 12, 16} : std::vector<uint32_t>{2, 4, 6, 9, 12, 16}) {
            for (uint32_t b : blurs) out.push_back({AoTechnique::Scalable, true, n, 0, 0, b});
            if (n >= 6) out.push_back({AoTechnique::Scalable, false, n, 0, 0, fullBlur});
        }
    if (wanted(techniques, AoTechnique::Crease))
        for (uint32_t b : blurs) out.push_back({AoTechnique::Crease, true, d.aoCreaseTaps, 0, 0, b});
    if (wanted(techniques, AoTechnique::Horizon)) {
        const std::pair<uint32_t, uint32_t> counts[] = {{1, 2}, {1, 3}, {1, 4}, {1, 6}, {2, 2},  {2, 3}, {2, 4}, {2, 6},
                                                        {2, 8}, {3, 4}, {3, 6}, {3, 8}, {2, 12}, {4, 6}, {4, 8}, {3, 12}};
        for (auto [slices, steps] : counts) {
            for (uint32_t b : blurs) out.push_back({AoTechnique::Horizon, true, 0, slices, steps, b});
            if (slices * steps >= 8) out.push_back({AoTechnique::Horizon, false, 0, slices, steps, fullBlur});
        }
    }
    return out;
}

bool sameConfig(const Config& a, const Config& b) {
    return a.technique == b.technique && a.half == b.half && a.counts() == b.counts() && a.blur == b.blur;
}

// A preset's point: its technique at its counts, blur and resolution.
Config presetConfig(const TierProfile& p) {
    const uint32_t count = p.aoTechnique == AoTechnique::Alchemy ? p.aoAlchemySamples
        : p.aoTechnique == AoTechnique::Scalable                 ? p.aoScalableTaps
                                                                 : p.aoCreaseTaps;
    return {p.aoTechnique, p.aoHalfResolution, count, p.aoHorizonSlices, p.aoHorizonSteps, p.aoBlurRadiusPx};
}

// The grid with every preset of the tier added where it is not already a point of it.
std::vector<Config> configsOf(Tier tier, const std::vector<std::string>& techniques) {
    std::vector<Config> out = grid(tiers::profile(tier), techniques);
    for (const Preset& preset : tiers::row(tier).presets) {
        const Config c = presetConfig(preset.params);
        if (!wanted(techniques, c.technique)) continue;
        if (std::none_of(out.begin(), out.end(), [&](const Config& g) { return sameConfig(g, c); })) out.push_back(c);
    }
    return out;
}

struct Cost {
    double ms = 0, copyPasses = 0;
};

struct Row {
    Tier tier;
    Config config;
    tools::AoScore training, score;                  // score: on the held-out families
    std::map<std::string, tools::AoScore> families;  // each held-out family's
    std::map<std::string, Cost> cost;                // by backend: the fastest round
    std::map<std::string, std::vector<Cost>> rounds;
};

// The score over `cases` and, when `families` is given, each scene family's (keyed by name).
Result<tools::AoScore> accuracy(tools::AoEvaluator& ev, const TierProfile& d, const Config& c, const std::vector<tools::AoCase>& cases,
                                const std::vector<tools::TradeView>& views, std::map<std::string, tools::AoScore>* families = nullptr) {
    ev.setProfile(c.apply(d));
    AoSettings s;
    s.technique = c.technique;
    s.normals = AoNormals::FromTexture;
    Result<std::vector<truth::Comparison>> errors = ev.run(s, cases);
    if (!errors) return errors.status();
    if (families) {
        std::map<std::string, std::vector<truth::Comparison>> byFamily;
        for (size_t i = 0; i < cases.size(); ++i) byFamily[views[cases[i].view].family].push_back(errors.value()[i]);
        for (const auto& [family, e] : byFamily) (*families)[family] = tools::summarise(e);
    }
    return tools::summarise(errors.value());
}

// "family PSNR; ..." over the held-out families: what the adoption rule reads (no family may fall).
std::string familyPsnrs(const std::map<std::string, tools::AoScore>& families) {
    std::string out;
    for (const auto& [family, score] : families) out += (out.empty() ? "" : "; ") + family + " " + fixed(score.psnr, 2);
    return out;
}

Status timeRows(Device& dev, const std::string& backend, Tier tier, const Options& o, std::vector<Row>& rows,
                const std::function<void(const std::string&)>& progress) {
    const Format outFormat = tools::aoOutputFormat(dev);
    Result<std::unique_ptr<tools::CopyPass>> copy = tools::makeCopyPass(dev, tier, o.costWidth, o.costHeight, outFormat);
    if (!copy) return copy.status();
    Result<std::unique_ptr<tools::ViewInputs>> in = tools::ViewInputs::create(dev, tier, tools::TradeView{o.costView, false, 0, 1, 0}, o.costWidth,
                                                                              o.costHeight);
    if (!in) return in.status();
    Result<TextureHandle> out = dev.createTexture({o.costWidth, o.costHeight, 1, outFormat, kTextureSampled | kTextureRenderTarget, "ao-front-out"});
    if (!out) return out.status();
    const TierProfile d = tiers::profile(tier);
    Status status = Status::ok();
    // Every configuration once per round, the rounds in turn, and each cost is its fastest round:
    // on a CPU rasteriser the time of one pass switches between two levels for seconds at a time
    // (a 4-tap Scalable pass: 13.9 ms in one round, 19.3 and 18.5 in the next two), and the slow
    // level is the machine's state, not the configuration's cost.
    for (uint32_t round = 0; round < o.rounds && status; ++round)
        for (Row& r : rows) {
            if (r.tier != tier) continue;
            AoSettings s;
            s.technique = r.config.technique;
            s.normals = AoNormals::FromTexture;
            Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(
                dev, {o.costWidth, o.costHeight, r.config.apply(d), s, in.value()->depthKind()});
            if (!ao) {
                status = ao.status();
                break;
            }
            const AoInputs inputs{DepthSource{in.value()->depth(), in.value()->depthKind(), in.value()->camera()}, in.value()->normals(),
                                  out.value()};
            Result<tools::CopyPass::Interleaved> t = copy.value()->timeAgainst(o.runs, [&] { return ao.value()->dispatch(inputs); });
            if (!t) {
                status = t.status();
                break;
            }
            std::vector<Cost>& measured = r.rounds[backend];
            measured.push_back({t->effectMs, t->ratio});
            r.cost[backend] = *std::min_element(measured.begin(), measured.end(), [](const Cost& a, const Cost& b) { return a.ms < b.ms; });
            progress(backend + "/" + toString(tier) + " round " + std::to_string(round + 1) + " " + r.config.name() + ": " + fixed(t->effectMs, 2) +
                     " ms = " + fixed(t->ratio, 1) + " copy passes, PSNR " + fixed(r.training.psnr, 2) + " dB training, " + fixed(r.score.psnr, 2) +
                     " dB held out");
        }
    (void)dev.destroyTexture(out.value());
    return status;
}

// The share of a cost within which two costs are not told apart: on this machine's CPU
// rasterisers the fastest of three passes over the grid still moves by up to 10% between runs.
constexpr double kCostResolution = 0.10;

// Indices of the points no other point measurably dominates: none at least as accurate for at
// least kCostResolution less cost.
std::vector<size_t> measuredFront(const std::vector<tools::PlotPoint>& points) {
    std::vector<size_t> out;
    for (size_t i = 0; i < points.size(); ++i)
        if (std::none_of(points.begin(), points.end(),
                         [&](const tools::PlotPoint& o) { return o.y >= points[i].y && o.x <= points[i].x * (1.0 - kCostResolution); }))
            out.push_back(i);
    return out;
}

// The tier's rows on the front of (cost, training PSNR), `cost` giving a row's cost where it has
// one (nullopt: not timed there).
std::vector<size_t> frontOf(const std::vector<Row>& rows, Tier tier, const std::function<std::optional<double>(const Row&)>& cost) {
    std::vector<tools::PlotPoint> points;
    std::vector<size_t> index;
    for (size_t i = 0; i < rows.size(); ++i)
        if (const std::optional<double> c = rows[i].tier == tier ? cost(rows[i]) : std::nullopt) {
            points.push_back({*c, rows[i].training.psnr, "", ""});
            index.push_back(i);
        }
    std::vector<size_t> out;
    for (size_t k : measuredFront(points)) out.push_back(index[k]);
    return out;
}

// Per backend: whether each row is on its tier's front of (that backend's milliseconds, training PSNR).
std::map<std::string, std::vector<bool>> fronts(const Options& o, const std::vector<Row>& rows) {
    std::map<std::string, std::vector<bool>> out;
    for (const std::string& backend : o.backends) {
        std::vector<bool>& on = out[backend];
        on.resize(rows.size(), false);
        for (Tier tier : {Tier::High, Tier::Current})
            for (size_t i : frontOf(rows, tier, [&](const Row& r) -> std::optional<double> {
                     const auto c = r.cost.find(backend);
                     return c == r.cost.end() ? std::nullopt : std::optional<double>(c->second.ms);
                 }))
                on[i] = true;
    }
    return out;
}

// The cost a backend-independent choice is made on: the geometric mean of the backends' costs.
double meanMs(const Row& r) {
    double logSum = 0;
    for (const auto& [backend, cost] : r.cost) logSum += std::log(cost.ms);
    return r.cost.empty() ? 0 : std::exp(logSum / double(r.cost.size()));
}

// The tier's rows on the front of (meanMs, training PSNR).
std::vector<size_t> meanFront(const std::vector<Row>& rows, Tier tier) {
    return frontOf(rows, tier, [](const Row& r) { return r.cost.empty() ? std::nullopt : std::optional<double>(meanMs(r)); });
}

std::string presetsAt(Tier tier, const Config& c) {
    std::string names;
    for (const Preset& p : tiers::row(tier).presets)
        if (sameConfig(presetConfig(p.params), c)) names += (names.empty() ? "" : ", ") + p.name;
    return names;
}

std::string markdown(const Options& o, const std::vector<Row>& rows, const std::string& machine) {
    std::ostringstream md;
    md << "Measured by `build/tools/bench/ao_front` on " << machine << ": " << rows.size()
       << " configurations (technique; samples, taps or horizon's slices x steps; blur half-width in output pixels; half or full "
          "resolution), each scored against the ray-traced truth (320x180, each view at its own radius) on the training scene families, "
          "which the front reads, and on the held-out families beside them, and timed at "
       << o.costWidth << "x" << o.costHeight << " (median of " << o.runs << " HAL-timed runs interleaved with copies, in each of " << o.rounds
       << " passes over the grid; a cost is its fastest pass, as a CPU rasteriser's times switch between two levels for seconds at a "
          "time). `mean ms` is the geometric mean of the backends' medians, the cost a preset, which "
          "every backend runs, is chosen on. The table lists each tier's front on it (nothing at least as accurate on the training "
          "families for 10% less time or more: costs closer than that are not told apart here) and every preset's point; the plots draw training "
          "PSNR against each backend's milliseconds; `ao_front.csv` has the "
          "whole grid.\n\n";
    for (const std::string& b : o.backends)
        for (Tier tier : {Tier::High, Tier::Current})
            md << "![AO configurations, " << toString(tier) << " tier, " << b << "](images/ao_front_" << toString(tier) << "_" << b << ".svg)\n\n";
    md << "| tier | technique | counts | blur px | resolution |";
    for (const std::string& b : o.backends) md << " " << b << " ms |";
    md << " mean ms | training PSNR | training signed error occluded | held-out PSNR | held-out PSNR occluded | held-out signed error occluded | "
          "front | preset |\n| --- | --- | --- | --- | --- |";
    for (size_t i = 0; i < o.backends.size(); ++i) md << " --- |";
    md << " --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (Tier tier : {Tier::High, Tier::Current}) {
        const std::vector<size_t> front = meanFront(rows, tier);
        for (size_t i = 0; i < rows.size(); ++i) {
            const Row& r = rows[i];
            const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
            const std::string presets = presetsAt(tier, r.config);
            if (r.tier != tier || r.cost.empty() || (!onFront && presets.empty())) continue;
            md << "| " << toString(tier) << " | " << toString(r.config.technique) << " | " << r.config.counts() << " | " << r.config.blur << " | "
               << (r.config.half ? "half" : "full") << " |";
            for (const std::string& b : o.backends) md << " " << (r.cost.count(b) ? fixed(r.cost.at(b).ms, 2) : "-") << " |";
            md << " " << fixed(meanMs(r), 2) << " | " << fixed(r.training.psnr, 2) << " | " << fixed(r.training.signedOccluded, 3) << " | "
               << fixed(r.score.psnr, 2) << " | " << fixed(r.score.psnrOccluded, 2) << " | " << fixed(r.score.signedOccluded, 3) << " | "
               << (onFront ? "yes" : "no") << " | " << (presets.empty() ? "" : "**" + presets + "**") << " |\n";
        }
    }
    return md.str();
}

Status writePlots(const Options& o, const std::vector<Row>& rows, const std::map<std::string, std::vector<bool>>& front) {
    std::filesystem::create_directories(o.outDir + "/images");
    for (const std::string& backend : o.backends)
        for (Tier tier : {Tier::High, Tier::Current}) {
            tools::Plot plot;
            plot.title = std::string("AO configurations, ") + toString(tier) + " tier, " + backend + " at " + std::to_string(o.costWidth) + "x" +
                std::to_string(o.costHeight);
            plot.xLabel = "cost, ms (this run)";
            plot.yLabel = "PSNR against ray-traced truth, dB (training families)";
            for (size_t i = 0; i < rows.size(); ++i) {
                const Row& r = rows[i];
                if (r.tier != tier || !r.cost.count(backend)) continue;
                // Only the front's points are named: the grid has some seventy per plot.
                const std::string label = front.at(backend)[i] ? r.config.counts() + "/" + std::to_string(r.config.blur) + (r.config.half ? "" : "F")
                                                               : "";
                plot.points.push_back({r.cost.at(backend).ms, r.training.psnr, label, toString(r.config.technique)});
            }
            if (plot.points.empty()) continue;
            SFX_TRY(tools::writeSvg(o.outDir + "/images/ao_front_" + toString(tier) + "_" + backend + ".svg", plot));
        }
    return Status::ok();
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"ao_front - accuracy and cost of a grid of AO configurations per tier, the front presets are chosen from", "ao_front"};
    app.add_option("--backends", o.backends, "comma-separated: vulkan, gles, gl, gl-egl, gl-osmesa")->delimiter(',')->capture_default_str();
    app.add_option("--tiers", o.tiers, "comma-separated: high, current")->delimiter(',')->capture_default_str();
    app.add_option("--techniques", o.techniques, "comma-separated: alchemy, scalable, crease, horizon")->delimiter(',')->capture_default_str();
    app.add_option("--cost-width", o.costWidth, "pixels of the timed runs")->capture_default_str();
    app.add_option("--cost-height", o.costHeight, "pixels of the timed runs")->capture_default_str();
    app.add_option("--runs", o.runs, "timed runs per configuration and round (median)")->capture_default_str();
    app.add_option("--rounds", o.rounds, "passes over the grid per backend; a cost is its fastest round")
        ->capture_default_str()
        ->check(CLI::Range(1u, 15u));
    app.add_option("--cache-dir", o.truth.cacheDir, "where truth images are cached")->capture_default_str();
    app.add_option("--out-dir", o.outDir, "ao_front.csv and images/ao_front_*.svg")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    const auto started = std::chrono::steady_clock::now();
    const auto progress = [&](const std::string& line) {
        std::cout << "[" << fixed(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 1) << " s] " << line
                  << std::endl;
    };
    std::vector<Tier> tiers;
    for (const std::string& name : o.tiers) {
        if (name != "high" && name != "current") {
            std::cerr << "ao_front: --tiers: '" << name << "' (allowed: high, current)\n";
            return 2;
        }
        tiers.push_back(name == "high" ? Tier::High : Tier::Current);
    }
    for (const std::string& name : o.techniques)
        if (AoTechnique t; !parseAoTechnique(name, &t)) {
            std::cerr << "ao_front: --techniques: '" << name << "' (allowed: alchemy, scalable, crease, horizon)\n";
            return 2;
        }

    const std::vector<tools::TradeView> trainingViews = tools::familyViews(false), heldOutViews = tools::familyViews(true);
    std::vector<tools::TradeView> views = trainingViews;
    views.insert(views.end(), heldOutViews.begin(), heldOutViews.end());
    Result<std::vector<tools::AoCase>> training = tools::loadCases(views, 0, trainingViews.size(), {}, o.truth, progress);
    Result<std::vector<tools::AoCase>> cases = training ? tools::loadCases(views, trainingViews.size(), views.size(), {}, o.truth, progress)
                                                        : training;
    if (!cases) {
        std::cerr << "ao_front: " << cases.status().toString() << "\n";
        return 1;
    }
    std::vector<Row> rows;
    std::string machine;
    const Status run = tools::forEachDevice(o.backends, tiers, "ao_front", [&](Device& dev, const std::string& backend, Tier tier) -> Status {
        progress(dev.caps().summary() + ", tier " + toString(tier));
        if (machine.empty()) machine = dev.caps().deviceName;
        const TierProfile d = tiers::profile(tier);
        if (backend == o.backends.front()) {  // accuracy from the first backend
            tools::AoEvaluator ev(dev, tier, o.truth.width, o.truth.height);
            SFX_TRY(ev.prepare(views));
            for (const Config& c : configsOf(tier, o.techniques)) {
                Result<tools::AoScore> t = accuracy(ev, d, c, training.value(), views);
                if (!t) return t.status();
                std::map<std::string, tools::AoScore> families;
                Result<tools::AoScore> a = accuracy(ev, d, c, cases.value(), views, &families);
                if (!a) return a.status();
                rows.push_back({tier, c, t.value(), a.value(), families, {}, {}});
                progress(std::string(toString(tier)) + " " + c.name() + ": training PSNR " + fixed(t->psnr, 2) + " dB; held-out PSNR " +
                         fixed(a->psnr, 2) + " dB, occluded " + fixed(a->psnrOccluded, 2) + " dB, signed error occluded " +
                         fixed(a->signedOccluded, 3) + " (" + familyPsnrs(families) + ")");
            }
        }
        return timeRows(dev, backend, tier, o, rows, progress);
    });
    if (!run) {
        std::cerr << "ao_front: " << run.toString() << "\n";
        return 1;
    }
    std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.tier != b.tier ? a.tier > b.tier : meanMs(a) < meanMs(b); });
    const std::map<std::string, std::vector<bool>> front = fronts(o, rows);
    std::filesystem::create_directories(o.outDir);
    std::ofstream csv(o.outDir + "/ao_front.csv");
    csv << "tier,technique,counts,blur_px,resolution,training_psnr_db,training_psnr_occluded_db,training_signed_error_occluded,psnr_db,psnr_"
           "occluded_db,signed_error_occluded,worst_case_psnr_db,held_out_family_psnr_db";
    for (const std::string& b : o.backends) csv << "," << b << "_ms," << b << "_copy_passes," << b << "_front";
    csv << "\n";
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        csv << toString(r.tier) << "," << toString(r.config.technique) << "," << r.config.counts() << "," << r.config.blur << ","
            << (r.config.half ? "half" : "full") << "," << fixed(r.training.psnr, 3) << "," << fixed(r.training.psnrOccluded, 3) << ","
            << fixed(r.training.signedOccluded, 4) << "," << fixed(r.score.psnr, 3) << "," << fixed(r.score.psnrOccluded, 3) << ","
            << fixed(r.score.signedOccluded, 4) << "," << fixed(r.score.worstPsnr, 3);
        csv << "," << familyPsnrs(r.families);
        for (const std::string& b : o.backends) {
            const auto c = r.cost.find(b);
            csv << "," << (c == r.cost.end() ? "-" : fixed(c->second.ms, 3)) << "," << (c == r.cost.end() ? "-" : fixed(c->second.copyPasses, 2))
                << "," << (front.at(b)[i] ? 1 : 0);
        }
        csv << "\n";
    }
    Status plots = writePlots(o, rows, front);
    if (plots) plots = tools::replaceMarkdownSection(o.outDir + "/trade.md", "ao_front", markdown(o, rows, machine.empty() ? "no device" : machine));
    if (!plots) {
        std::cerr << "ao_front: " << plots.toString() << "\n";
        return 1;
    }
    progress("ao_front: " + std::to_string(rows.size()) + " configurations -> " + o.outDir + "/ao_front.csv, images/ao_front_*.svg");
    return rows.empty() ? 1 : 0;
}
