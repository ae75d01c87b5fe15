// bench_mb_families: motion blur scored on scene families it was never tuned on
// (tools/scenes/mb_families.hpp). Per family, speed, tier and source (the CPU reference and each
// backend): PSNR against the truth over the moving region and over the frame, the gain over the
// unblurred input on the moving region, and PSNR at the leading edges (background covered) and
// trailing edges (background revealed) separately; for the independent square, also over the
// rows it spans. With --images, a picture per family at a few speeds: input, truth and each
// tier's CPU reference output, and their errors. With --raster, the rasterised families
// (tools/scenes/mb_raster_families.hpp) instead: drawn by --raster-backend's raster pass, the
// truth averaging --instants rendered instants. With --sweep, every 0.5 px from 0.5 px to past
// both tiers' blur (the high tier's radius at this height, doubled, plus 4 px) and, per family
// and region, the worst high - current tier and its speed: the tier promise checked between the
// scored speeds too. With --layouts N, each family laid out from N seeds, and per family and
// region the high - current tier's mean over the layouts: the promise for the family, not one
// layout of it. --hidden-near, --high-dither-pairs and --high-jitter-always score the CPU
// reference's candidate reconstructions (MotionBlurCandidate) instead of today's. Not a test:
// docs/motion_blur.md shows its CSVs and pictures, docs/motion_blur_studies.md its sweeps and
// layouts. About two minutes on 2 cores (a sweep: see docs/motion_blur_studies.md).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>

#include "bench_args.hpp"
#include "bench_device.hpp"
#include "markdown_section.hpp"
#include "mb_doc_tables.hpp"
#include "mb_family_scoring.hpp"
#include "mb_raster_families.hpp"
#include "motion_cases.hpp"
#include "sfx/backends.hpp"
#include "sfx/image_io.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/reference/motion_blur_reference.hpp"
#include "sfx/scene_render.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

using tools::familyPsnr;

struct Scores {
    double moving, frame, leading, trailing, rows;
};
Scores score(const ColorGrid& out, const ColorGrid& truth, const tools::FamilyMasks& m, const std::vector<bool>& rows) {
    return {familyPsnr(out, truth, m.moving), familyPsnr(out, truth, {}), familyPsnr(out, truth, m.leading), familyPsnr(out, truth, m.trailing),
            rows.empty() ? NAN : familyPsnr(out, truth, rows)};
}

// The picture of one family at one speed (--images), panels 4 px apart on mid grey. Top row:
// input | truth | current tier | high tier, sRGB-encoded as the renderer's PNGs are. Bottom row,
// under each but the truth (whose slot stays grey): |panel - truth| x 4 per channel on the
// linear values, written as they are (white: 0.25 or more).
Status writePicture(const std::string& path, const ColorGrid& input, const ColorGrid& truth, const ColorGrid& current, const ColorGrid& high) {
    const uint32_t w = truth.width, h = truth.height, gap = 4;
    io::Image out(4 * w + 3 * gap, 2 * h + gap, 3, 0.5f);
    const ColorGrid* panels[4] = {&input, &truth, &current, &high};
    for (uint32_t p = 0; p < 4; ++p)
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                for (uint32_t c = 0; c < 3; ++c) {
                    const double v = panels[p]->at(x, y)[c], error = std::fabs(v - truth.at(x, y)[c]);
                    out.at(p * (w + gap) + x, y, c) = float(render::linearToSrgb(v));
                    if (p != 1) out.at(p * (w + gap) + x, h + gap + y, c) = float(std::min(1.0, 4 * error));
                }
    return io::writePng(path, out);
}

// One open device per backend x tier, kept for the whole run.
struct Runner {
    std::string backend;
    Tier tier;
    std::unique_ptr<Device> device;
};

using CaseScorer = std::function<bool(const std::string& family, bool heldOut, double speed, const ColorGrid& truth, double residualPsnr,
                                      const tools::FamilyMasks& masks, const SceneFrame& frame, const std::vector<bool>& rowsMask)>;

// The rasterised families (tools/scenes/mb_raster_families.hpp), all held out: each case drawn by
// `backend`'s raster pass, its truth the average of `instants` rendered instants, then scored;
// each family laid out from `firstLayout` to firstLayout + layouts - 1, `layout` set to the one
// being scored.
bool scoreRasterFamilies(const std::string& backend, const std::string& familiesFlag, const std::vector<double>& speeds, uint32_t w, uint32_t h,
                         uint32_t instants, uint32_t firstLayout, uint32_t layouts, uint32_t& layout, const CaseScorer& scoreCase) {
    Result<std::unique_ptr<Device>> opened = tools::openNamedForTier(backend, Tier::Current);
    if (!opened) {
        std::cerr << "bench_mb_families: raster backend " << backend << ": " << opened.status().toString() << "\n";
        return false;
    }
    std::unique_ptr<Device> device = std::move(opened.value());
    Result<std::unique_ptr<tools::SceneRenderer>> renderer = tools::SceneRenderer::create(*device, Tier::Current);
    if (!renderer) {
        std::cerr << "bench_mb_families: " << renderer.status().toString() << "\n";
        return false;
    }
    for (const std::string& family : tools::rasterFamilyNames()) {
        if (familiesFlag != "all" && !tools::inList(familiesFlag, family)) continue;
        for (layout = firstLayout; layout < firstLayout + layouts; ++layout)
            for (double speed : speeds) {
                Result<tools::RasterFamilyCase> c = tools::makeRasterFamilyCase(*device, *renderer.value(), family, speed, w, h, instants, layout);
                if (!c) {
                    std::cerr << "bench_mb_families: " << family << " at " << speed << " px, layout " << layout << ": " << c.status().toString()
                              << "\n";
                    return false;
                }
                std::printf("[%s %.1f px, layout %u] rendered by %s: fastest point %.3f px; truth's residual noise rmse %.5f (%u/2 vs %u instants)\n",
                            family.c_str(), speed, layout, backend.c_str(), c->measuredSpeedPx, c->residualRmse, instants, instants);
                const double residualPsnr = c->residualRmse > 0 ? -20.0 * std::log10(c->residualRmse) : 99.0;
                if (!scoreCase(family, true, speed, c->truth, residualPsnr, c->masks, c->frame, {})) return false;
            }
    }
    return true;
}

// What a generated section was measured with (its opening sentence).
struct DocSetup {
    bool raster = false, sweep = false;
    uint32_t width = 0, height = 0, instants = 0, seed = 0, layouts = 1;
    std::string rasterBackend;
    const TierProfile* profiles = nullptr;  // current, high
    MotionBlurSettings settings;
};

// The sentence that opens a generated section, for the speeds the CSV holds.
std::string setupText(const DocSetup& d, const std::vector<double>& speeds) {
    std::string text = std::string("Measured by `bench_mb_families") + (d.raster ? " --raster" : "") + (d.sweep ? " --sweep" : "") + "` at " +
        std::to_string(d.width) + " × " + std::to_string(d.height) + ", ";
    if (d.sweep) {
        text += "every 0.5 px from " + tools::compactNumber(speeds.front()) + " to " + tools::compactNumber(speeds.back()) + " px";
    } else {
        text += "speeds";
        for (size_t i = 0; i < speeds.size(); ++i) text += (i ? ", " : " ") + tools::compactNumber(speeds[i]);
        text += " px";
    }
    text += ", the truth the average of " + std::to_string(d.instants) + " instants" +
        (d.raster ? ", drawn by " + d.rasterBackend + "'s raster pass" : "") +
        (d.layouts > 1  ? ", layouts from seeds " + std::to_string(d.seed) + "-" + std::to_string(d.seed + d.layouts - 1)
             : d.raster ? ""
                        : ", layout seed " + std::to_string(d.seed));
    for (int t = 0; t < 2; ++t)
        if (Result<MotionBlurParams> p = resolveMotionBlur(d.profiles[t], d.settings, d.height))
            text += std::string(t ? "; high tier " : "; current tier ") + std::to_string(p->taps) + " taps, radius " + std::to_string(p->radiusPx) +
                " px";
    return text + " at this height.";
}

// Writes the page's section of this mode (bench_mb_families, _raster, _sweep, _raster_sweep,
// _layouts or _raster_layouts)
// from the CSV at `csvPath`, as a run wrote it or as --doc-only finds it.
Status writeDocSection(const std::string& docPath, const std::string& csvPath, const std::string& beforePath, const DocSetup& setup) {
    Result<std::vector<tools::MbFamilyRow>> rows = tools::readMbFamilyCsv(csvPath);
    if (!rows) return rows.status();
    std::vector<tools::MbFamilyRow> before;
    if (!beforePath.empty()) {
        Result<std::vector<tools::MbFamilyRow>> b = tools::readMbFamilyCsv(beforePath);
        if (!b) return b.status();
        before = std::move(b.value());
    }
    std::vector<double> speeds;
    for (const tools::MbFamilyRow& r : rows.value())
        if (std::find(speeds.begin(), speeds.end(), r.speed) == speeds.end()) speeds.push_back(r.speed);
    std::sort(speeds.begin(), speeds.end());
    if (speeds.empty()) return Status{StatusCode::InvalidArgument, csvPath + ": no rows"};
    // Every table but the layouts' keys its rows by family, speed and tier: one layout only.
    const int firstLayout = rows->front().layout;
    if (setup.layouts == 1)
        for (const tools::MbFamilyRow& r : rows.value())
            if (r.layout != firstLayout)
                return Status{StatusCode::InvalidArgument,
                              csvPath + ": rows of layouts " + std::to_string(firstLayout) + " and " + std::to_string(r.layout) +
                                  "; pass --layouts N for a CSV of N layouts"};
    const std::string text = setupText(setup, speeds);
    if (setup.layouts > 1)
        return tools::replaceMarkdownSection(docPath, std::string("bench_mb_families") + (setup.raster ? "_raster" : "") + "_layouts",
                                             tools::mbLayoutsTable(rows.value(), text));
    const std::string section = std::string("bench_mb_families") + (setup.raster ? "_raster" : "") + (setup.sweep ? "_sweep" : "");
    return tools::replaceMarkdownSection(docPath, section,
                                         setup.sweep        ? tools::mbSweepTable(rows.value(), text)
                                             : setup.raster ? tools::mbRasterTables(rows.value(), text)
                                                            : tools::mbFamilyTables(rows.value(), before, text));
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"bench_mb_families: motion blur per scene family, speed, tier and backend against temporal supersampling"};
    uint32_t width = 320, height = 240, instants = 256, seed = 1, layouts = 1;
    std::string csvPath = "mb_families.csv", backendsFlag = "vulkan,gles", speedsFlag = "0.5,2,6,12,24,40", familiesFlag = "all";
    std::string imagesDir, imageSpeedsFlag = "6,12,24", docPath, beforePath;
    std::string rasterBackend = "vulkan";
    bool raster = false, sweep = false;
    double sweepFrom = 0.5;
    std::optional<uint32_t> taps;
    std::optional<float> radius;
    std::optional<uint32_t> highTaps;
    std::optional<float> highRadius;
    std::optional<uint32_t> currentTaps;
    std::optional<float> currentRadius;
    MotionBlurCandidate candidates[2];  // the CPU reference's, current and high tier
    double hiddenNear = 0;
    app.add_option("--width", width, "picture width")->capture_default_str();
    app.add_option("--height", height, "picture height")->capture_default_str();
    app.add_option("--instants", instants, "instants averaged for the truth")->capture_default_str();
    app.add_option("--seed", seed, "layout seed of every family")->capture_default_str();
    app.add_option("--layouts", layouts,
                   "lay out each family from seeds --seed to --seed + N - 1 and print the high - current tier's mean over them "
                   "(with --doc, the section bench_mb_families_layouts or _raster_layouts)")
        ->capture_default_str();
    app.add_option("--speeds", speedsFlag, "displacements across the shutter, pixels, comma-separated")->capture_default_str();
    app.add_option("--families", familiesFlag, "comma-separated families, or all")->capture_default_str();
    app.add_flag("--raster", raster, "score the rasterised families (models, camera, turning) instead of the 2D ones");
    app.add_option("--raster-backend", rasterBackend, "the backend whose raster pass draws the rasterised families")->capture_default_str();
    app.add_option("--backends", backendsFlag, "comma-separated backends; none = CPU reference only")->capture_default_str();
    app.add_flag("--sweep", sweep, "speeds every 0.5 px past both tiers' blur (replaces --speeds); print the worst high - current per region");
    app.add_option("--sweep-from", sweepFrom, "the sweep's first speed, px (a multiple of 0.5)")->capture_default_str();
    app.add_option("--taps", taps, "override MotionBlurSettings::samples on both tiers");
    app.add_option("--radius", radius, "override MotionBlurSettings::maxRadiusPx (at 720 rows) on both tiers");
    app.add_option("--high-taps", highTaps, "the high tier's profile taps (a candidate default; --taps overrides it)");
    app.add_option("--high-radius", highRadius, "the high tier's profile radius at 720 rows (a candidate default)");
    app.add_option("--current-taps", currentTaps, "the current tier's profile taps (a candidate default; --taps overrides it)");
    app.add_option("--current-radius", currentRadius, "the current tier's profile radius at 720 rows (a candidate default)");
    app.add_option("--hidden-near", hiddenNear,
                   "candidate, both tiers' CPU reference: the hidden background's colour weighted by distance^-P (0 = today's)")
        ->capture_default_str();
    app.add_flag("--high-dither-pairs", candidates[1].ditherPairs, "candidate, the high tier's CPU reference: per-pixel dither of the pair count");
    app.add_flag("--high-jitter-always", candidates[1].jitterAlways,
                 "candidate, the high tier's CPU reference: 4 x 4 position jitter at full share everywhere");
    app.add_option("--csv", csvPath, "CSV output file")->capture_default_str();
    app.add_option("--images", imagesDir, "write DIR/mb_<family>_<speed>px.png: input, truth, current, high tier (CPU reference) and errors x4");
    app.add_option("--image-speeds", imageSpeedsFlag, "speeds of the --images pictures, comma-separated (each also in --speeds)")
        ->capture_default_str();
    app.add_option(
        "--doc", docPath,
        "write this run's tables into the page's generated section (bench_mb_families, _raster, _sweep, _raster_sweep, _layouts or _raster_layouts)");
    app.add_option("--before", beforePath, "with --doc (2D families): the baseline CSV the tables compare with");
    bool docOnly = false;
    app.add_flag("--doc-only", docOnly, "with --doc: write the section from --csv as it is, without running anything");
    CLI11_PARSE(app, argc, argv);
    if (width == 0 || height == 0 || instants < 2) {
        std::cerr << "bench_mb_families: --width and --height must be > 0, --instants >= 2\n";
        return 1;
    }
    if (layouts < 1 || layouts > 1000 || (layouts > 1 && !imagesDir.empty())) {
        std::cerr << "bench_mb_families: --layouts must be in [1, 1000], and 1 with --images\n";
        return 1;
    }
    if (!(hiddenNear >= 0 && hiddenNear <= 8)) {
        std::cerr << "bench_mb_families: --hidden-near must be in [0, 8]\n";
        return 1;
    }
    candidates[0].hiddenNearExponent = candidates[1].hiddenNearExponent = hiddenNear;
    if (docOnly && docPath.empty()) {
        std::cerr << "bench_mb_families: --doc-only needs --doc\n";
        return 1;
    }
    MotionBlurSettings settings;
    settings.samples = taps, settings.maxRadiusPx = radius;
    TierProfile profiles[2] = {tiers::profile(Tier::Current), tiers::profile(Tier::High)};  // indexed by tier == High
    if (highTaps) profiles[1].mbTaps = *highTaps;
    if (highRadius) profiles[1].mbMaxRadiusPx = *highRadius;
    if (currentTaps) profiles[0].mbTaps = *currentTaps;
    if (currentRadius) profiles[0].mbMaxRadiusPx = *currentRadius;

    auto writeDoc = [&]() -> int {
        const DocSetup setup{raster, sweep, width, height, instants, seed, layouts, rasterBackend, profiles, settings};
        if (Status st = writeDocSection(docPath, csvPath, beforePath, setup); !st) {
            std::cerr << "bench_mb_families: " << st.toString() << "\n";
            return 1;
        }
        std::cout << "wrote " << docPath << "'s generated section from " << csvPath << "\n";
        return 0;
    };
    if (docOnly) return writeDoc();
    std::vector<Runner> runners;
    for (Tier tier : {Tier::Current, Tier::High})
        for (const BackendConfig& config : compiledBackends()) {
            if (config.backend == BackendKind::Null || !tools::inList(backendsFlag, toString(config))) continue;
            Result<std::unique_ptr<Device>> d = tools::openForTier(config, tier);
            if (!d) {
                std::cout << toString(config) << "/" << toString(tier) << ": skipped (" << d.status().toString() << ")\n";
                continue;
            }
            runners.push_back({toString(config), tier, std::move(d.value())});
        }
    PerspectiveDesc pd;
    pd.aspect = double(width) / height;
    const CameraProjection cam = makePerspective(pd).value();

    std::ofstream csv(csvPath);
    csv << "family,split,speed_px,layout,tier,source,taps,radius_px,psnr_moving,psnr_frame,input_psnr_moving,gain_db,psnr_leading,psnr_trailing,"
           "psnr_rows,input_psnr_leading,input_psnr_trailing,input_psnr_rows,truth_residual_psnr\n";
    // Per family x tier (CPU reference): the sum of gains, for the summary.
    std::map<std::string, std::array<double, 2>> gainSum;
    std::map<std::string, int> gainCount;
    // Per family, over the speeds of 2 px and more: the worst high - current PSNR, moving region and frame.
    std::map<std::string, std::array<double, 2>> worstHighMinusCurrent;
    std::vector<double> speeds = tools::splitNumberList(speedsFlag);
    const std::vector<double> imageSpeeds = tools::splitNumberList(imageSpeedsFlag);
    if (sweep) {
        Result<MotionBlurParams> high = resolveMotionBlur(profiles[1], settings, height);
        Result<MotionBlurParams> current = resolveMotionBlur(profiles[0], settings, height);
        if (!high || !current) {
            std::cerr << "bench_mb_families: " << (high ? current.status() : high.status()).toString() << "\n";
            return 1;
        }
        // A speed is a displacement across the shutter: twice the blur radius.
        const double last = 2.0 * std::max(high->radiusPx, current->radiusPx) + 4.0;
        speeds.clear();
        for (int half = std::max(1, int(std::lround(2.0 * sweepFrom))); half <= int(2.0 * last); ++half) speeds.push_back(0.5 * half);
    }
    // --sweep: per family and region (moving, frame, leading, trailing), the worst high - current
    // tier (CPU reference) and the speed where it is.
    struct Worst {
        double db = INFINITY, speed = 0;
    };
    std::map<std::string, std::array<Worst, 4>> sweepWorst;
    std::map<std::string, std::array<int, 2>> sweepIdentical;  // speeds where the tiers' outputs are identical, of all
    if (!imagesDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(imagesDir, ec);
        for (double s : imageSpeeds)
            if (std::find(speeds.begin(), speeds.end(), s) == speeds.end())
                std::cerr << "bench_mb_families: image speed " << s << " is not in --speeds\n";
    }
    uint32_t layout = seed;  // the layout being scored, for the CSV
    // One scored case: the family's truth, masks and the input frame the effect gets.
    auto scoreCase = [&](const std::string& family, bool heldOut, double speed, const ColorGrid& truth, double residual,
                         const tools::FamilyMasks& masks, const SceneFrame& frame, const std::vector<bool>& rowsMask) -> bool {
        const Scores in = score(frame.color, truth, masks, rowsMask);
        std::printf("[%s%s %.1f px] input: moving %s dB, frame %s, leading %s, trailing %s, rows %s; truth(%u/2) vs truth(%u) %s dB\n",
                    family.c_str(), heldOut ? " held-out" : " training", speed, tools::fixedOrDash(in.moving).c_str(),
                    tools::fixedOrDash(in.frame).c_str(), tools::fixedOrDash(in.leading).c_str(), tools::fixedOrDash(in.trailing).c_str(),
                    tools::fixedOrDash(in.rows).c_str(), instants, instants, tools::fixedOrDash(residual).c_str());
        auto emit = [&](Tier tier, const std::string& source, const MotionBlurParams& p, const ColorGrid& out) {
            const Scores s = score(out, truth, masks, rowsMask);
            std::printf("  %-8s %-10s %2u taps r=%2u: moving %s (%+.2f), frame %s, leading %s, trailing %s, rows %s\n", toString(tier),
                        source.c_str(), p.taps, p.radiusPx, tools::fixedOrDash(s.moving).c_str(), s.moving - in.moving,
                        tools::fixedOrDash(s.frame).c_str(), tools::fixedOrDash(s.leading).c_str(), tools::fixedOrDash(s.trailing).c_str(),
                        tools::fixedOrDash(s.rows).c_str());
            csv << family << "," << (heldOut ? "held-out" : "training") << "," << speed << "," << layout << "," << toString(tier) << "," << source
                << "," << p.taps << "," << p.radiusPx << "," << tools::fixedOrDash(s.moving) << "," << tools::fixedOrDash(s.frame) << ","
                << tools::fixedOrDash(in.moving) << "," << tools::fixedOrDash(s.moving - in.moving) << "," << tools::fixedOrDash(s.leading) << ","
                << tools::fixedOrDash(s.trailing) << "," << tools::fixedOrDash(s.rows) << "," << tools::fixedOrDash(in.leading) << ","
                << tools::fixedOrDash(in.trailing) << "," << tools::fixedOrDash(in.rows) << "," << tools::fixedOrDash(residual) << "\n";
            return s;
        };
        ColorGrid referenceOut[2];  // the CPU reference's output, current and high tier
        Scores referenceScores[2];
        for (Tier tier : {Tier::Current, Tier::High}) {
            Result<MotionBlurParams> p = resolveMotionBlur(profiles[tier == Tier::High], settings, height);
            if (!p) {
                std::cerr << "bench_mb_families: " << p.status().toString() << "\n";
                return false;
            }
            ColorGrid& out = referenceOut[tier == Tier::High];
            out = motionBlur(frame.color, frame.depth, frame.velocity, p.value(), kSkyDepth, candidates[tier == Tier::High]).color;
            const Scores s = emit(tier, "reference", p.value(), out);
            referenceScores[tier == Tier::High] = s;
            gainSum[family][tier == Tier::High] += s.moving - in.moving;
            if (tier == Tier::High) ++gainCount[family];
            for (Runner& r : runners) {
                if (r.tier != tier) continue;
                Result<tools::MotionBlurRun> run = tools::runMotionBlur(*r.device, profiles[tier == Tier::High], settings, frame, cam, 1);
                if (!run) {
                    std::printf("  %-8s %-10s FAILED %s\n", toString(tier), r.backend.c_str(), run.status().toString().c_str());
                    continue;
                }
                emit(tier, r.backend, p.value(), run->output);
            }
        }
        const double regions[4][2] = {{referenceScores[0].moving, referenceScores[1].moving},
                                      {referenceScores[0].frame, referenceScores[1].frame},
                                      {referenceScores[0].leading, referenceScores[1].leading},
                                      {referenceScores[0].trailing, referenceScores[1].trailing}};
        auto& identical = sweepIdentical[family];
        identical[0] += referenceOut[0].values == referenceOut[1].values, ++identical[1];
        for (int r = 0; r < 4; ++r) {
            const double d = regions[r][1] - regions[r][0];  // NaN where the region is empty: never the worst
            Worst& w = sweepWorst[family][r];
            if (d < w.db) w = {d, speed};
        }
        if (speed >= 2) {
            const double d[] = {referenceScores[1].moving - referenceScores[0].moving, referenceScores[1].frame - referenceScores[0].frame};
            auto [it, added] = worstHighMinusCurrent.try_emplace(family, std::array<double, 2>{d[0], d[1]});
            if (!added) it->second = {std::min(it->second[0], d[0]), std::min(it->second[1], d[1])};
        }
        if (!imagesDir.empty() && std::find(imageSpeeds.begin(), imageSpeeds.end(), speed) != imageSpeeds.end()) {
            char name[96];
            std::snprintf(name, sizeof name, "/mb_%s_%gpx.png", family.c_str(), speed);
            if (Status st = writePicture(imagesDir + name, frame.color, truth, referenceOut[0], referenceOut[1]); !st) {
                std::cerr << "bench_mb_families: " << st.toString() << "\n";
                return false;
            }
            std::printf("  wrote %s%s\n", imagesDir.c_str(), name);
        }
        std::fflush(stdout);
        return true;
    };
    if (raster) {
        if (!scoreRasterFamilies(rasterBackend, familiesFlag, speeds, width, height, instants, seed, layouts, layout, scoreCase)) return 1;
    } else {
        for (const std::string& family : tools::familyNames()) {
            if (familiesFlag != "all" && !tools::inList(familiesFlag, family)) continue;
            for (layout = seed; layout < seed + layouts; ++layout)
                for (double speed : speeds) {
                    if (layouts > 1) std::printf("layout %u: ", layout);
                    const tools::FamilyCase fc = tools::makeFamilyCase(family, speed, layout, width, height);
                    const ColorGrid truth = fc.scene.truth(instants);
                    // Residual noise of the truth: how far half the instants are from all of them.
                    const double residual = familyPsnr(fc.scene.truth(instants / 2), truth, {});
                    const SceneFrame frame = fc.scene.render(0);
                    if (!scoreCase(family, fc.heldOut, speed, truth, residual, tools::familyMasks(fc.scene, 64), frame, fc.rowsMask)) return 1;
                }
        }
    }
    std::printf("mean gain over the input on the moving region (CPU reference), current / high:\n");
    for (const auto& [family, g] : gainSum)
        std::printf("  %-9s %-9s %+.2f / %+.2f dB\n", family.c_str(), tools::familyHeldOut(family) ? "held-out" : "training",
                    g[0] / gainCount[family], g[1] / gainCount[family]);
    std::printf("worst high - current tier over the speeds of 2 px and more (CPU reference), moving region / frame:\n");
    for (const auto& [family, d] : worstHighMinusCurrent) std::printf("  %-9s %+.3f / %+.3f dB\n", family.c_str(), d[0], d[1]);
    if (sweep) {
        std::printf("sweep, %g to %g px every 0.5 px at %ux%u: worst high - current tier (CPU reference), dB at speed px\n", speeds.front(),
                    speeds.back(), width, height);
        std::printf("  %-9s %-16s %-16s %-16s %-16s %s\n", "family", "moving", "frame", "leading", "trailing", "identical outputs");
        for (const auto& [family, w] : sweepWorst) {
            std::printf("  %-9s", family.c_str());
            for (const Worst& r : w) {
                char cell[40] = "-";
                if (std::isfinite(r.db)) std::snprintf(cell, sizeof cell, "%+.3f at %g", r.db, r.speed);
                std::printf(" %-16s", cell);
            }
            std::printf(" %d of %d speeds\n", sweepIdentical[family][0], sweepIdentical[family][1]);
        }
    }
    csv.close();
    std::cout << "wrote " << csvPath << "\n";
    if (layouts > 1) {
        Result<std::vector<tools::MbFamilyRow>> rows = tools::readMbFamilyCsv(csvPath);
        if (!rows) {
            std::cerr << "bench_mb_families: " << rows.status().toString() << "\n";
            return 1;
        }
        std::printf("over layouts %u-%u:\n%s", seed, seed + layouts - 1, tools::mbLayoutsTable(rows.value(), "").c_str());
    }
    return docPath.empty() ? 0 : writeDoc();
}
