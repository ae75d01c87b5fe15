// bench_mb_flicker: is motion blur stable under motion? Per scene family (mb_families.hpp) and
// speed, a sequence of frames with the objects moving on between frames and a slow camera pan
// (mb_sequence.hpp). Flicker beyond the truth's own is the error: for each pair of consecutive
// frames, the output's change D_out = out[f+1] - out[f] is scored against the truth's change
// D_truth as a PSNR (peak 1, RGB), over the pixels where either frame shows an object and over
// the frame; the same for the unblurred input. D_out - D_truth is the change of the per-frame
// error, so a steady error scores high and one that jumps about scores low. The CPU reference runs
// with both sample jitter patterns (2 = checkerboard, 4 = 4x4 randomised) on both tiers, at the
// tier's radius and at a longer one where the jitter acts, to bound what the pattern adds; the
// backends run each tier as it is. Not a test: docs/motion_blur.md shows its CSV.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "bench_args.hpp"
#include "bench_device.hpp"
#include "markdown_section.hpp"
#include "mb_family_scoring.hpp"
#include "mb_flicker_tables.hpp"
#include "mb_sequence.hpp"
#include "motion_cases.hpp"
#include "sfx/backends.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/reference/motion_blur_reference.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

// Sum of squared RGB differences and the count of channels over the masked pixels (empty: all).
struct SquareSum {
    double sum = 0;
    size_t n = 0;
    double psnr() const { return n == 0 ? NAN : sum == 0 ? 99.0 : 10.0 * std::log10(double(n) / sum); }
    double rms() const { return n == 0 ? NAN : std::sqrt(sum / double(n)); }
};

// (a1 - a0) - (b1 - b0) per channel; b0, b1 may be null (then just a1 - a0).
SquareSum changeError(const ColorGrid& a0, const ColorGrid& a1, const ColorGrid* b0, const ColorGrid* b1, const std::vector<bool>& mask) {
    SquareSum s;
    for (size_t i = 0; i < a0.values.size(); ++i) {
        if (!mask.empty() && !mask[i]) continue;
        for (int c = 0; c < 3; ++c) {
            double d = a1.values[i][c] - a0.values[i][c];
            if (b0) d -= b1->values[i][c] - b0->values[i][c];
            s.sum += d * d;
        }
        s.n += 3;
    }
    return s;
}

// Mean and minimum of the finite values (a pair or frame with no object pixels gives NaN).
struct Summary {
    double mean = NAN, worst = NAN;
};
Summary summarise(const std::vector<double>& v) {
    double sum = 0, worst = INFINITY;
    size_t n = 0;
    for (double x : v)
        if (std::isfinite(x)) sum += x, worst = std::min(worst, x), ++n;
    return n == 0 ? Summary{} : Summary{sum / double(n), worst};
}
double mean(const std::vector<double>& v) { return summarise(v).mean; }

// One open device per backend x tier with the effect and its inputs, kept for the whole run:
// creating them per frame (tools::runMotionBlur) costs more than running the effect.
struct Runner {
    std::string backend;
    Tier tier;
    std::unique_ptr<Device> device;
    std::unique_ptr<MotionBlur> effect;
    TextureHandle color, depth, velocity;
    ~Runner() {
        effect.reset();
        for (TextureHandle t : {color, depth, velocity})
            if (device && !t.isNull()) (void)device->destroyTexture(t);
    }
    Runner(std::string b, Tier t, std::unique_ptr<Device> d) : backend(std::move(b)), tier(t), device(std::move(d)) {}
    Runner(const Runner&) = delete;
    Runner& operator=(const Runner&) = delete;
};

Status openEffect(Runner& r, uint32_t w, uint32_t h) {
    Device& d = *r.device;
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(d, {w, h, tiers::profile(r.tier), Format::RGBA32F, DepthKind::Linear});
    if (!mb) return mb.status();
    r.effect = std::move(mb.value());
    Result<TextureHandle> c = d.createTexture({w, h, 1, Format::RGBA32F, kTextureSampled, "flicker-color"});
    if (!c) return c.status();
    r.color = c.value();
    Result<TextureHandle> z = d.createTexture({w, h, 1, Format::R32F, kTextureSampled, "flicker-depth"});
    if (!z) return z.status();
    r.depth = z.value();
    Result<TextureHandle> v = d.createTexture({w, h, 1, Format::RG32F, kTextureSampled, "flicker-velocity"});
    if (!v) return v.status();
    r.velocity = v.value();
    return Status::ok();
}

// The frame uploaded exactly as rendered (float), the effect with the tier as it is, read back.
Result<ColorGrid> runFrame(Runner& r, const SceneFrame& f, const CameraProjection& cam) {
    Device& d = *r.device;
    const uint32_t w = f.color.width, h = f.color.height;
    std::vector<float> c, z, v;
    for (const auto& px : f.color.values)
        for (double ch : px) c.push_back(float(ch));
    for (double x : f.depth.values) z.push_back(float(x));
    for (const auto& e : f.velocity.values) v.push_back(float(e[0])), v.push_back(float(e[1]));
    SFX_TRY(d.writeTexture(r.color, 0, c.data(), c.size() * 4));
    SFX_TRY(d.writeTexture(r.depth, 0, z.data(), z.size() * 4));
    SFX_TRY(d.writeTexture(r.velocity, 0, v.data(), v.size() * 4));
    MotionBlurInputs in;
    in.color = r.color, in.depth = {r.depth, DepthKind::Linear, cam}, in.velocity = r.velocity;
    SFX_TRY(r.effect->dispatch(in));
    SFX_TRY(d.flush());
    std::vector<float> out(size_t(w) * h * 4);
    SFX_TRY(d.readTexture(r.effect->output(), 0, out.data(), out.size() * 4));
    ColorGrid g(w, h);
    for (size_t i = 0; i < g.values.size(); ++i)
        for (int ch = 0; ch < 4; ++ch) g.values[i][ch] = out[i * 4 + size_t(ch)];
    return g;
}

// One output sequence being scored: the input, or the effect from one source with one profile.
struct Track {
    std::string tier = "-", source;
    uint32_t jitter = 0;  // 0: the input (no jitter)
    bool tierJitter = true;
    MotionBlurParams params{};
    Runner* runner = nullptr;  // null: the CPU reference (or the input)
    ColorGrid prev;
    // Per pair: temporal PSNR over the objects and over the frame, RMS of D_out; per frame: PSNR.
    std::vector<double> temporal, temporalFrame, rmsOut, psnr;
    bool failed = false;
};

// The tracks of one case: the input, then per tier the CPU reference with each jitter pattern
// (the tier's own first), at the tier's radius for this height and, where jitterRows asks, at the
// longer radius of the look defined at that many rows; then each backend with the tier as it is.
std::vector<Track> makeTracks(const std::vector<std::unique_ptr<Runner>>& runners, uint32_t height, uint32_t jitterRows) {
    const MotionBlurSettings settings;
    std::vector<Track> tracks(1);
    tracks[0].source = "input";
    for (Tier tier : {Tier::Current, Tier::High}) {
        const TierProfile own = tiers::profile(tier);
        for (uint32_t rows : {settings.referenceRows, jitterRows}) {
            if (rows == 0) continue;
            MotionBlurSettings at = settings;
            at.referenceRows = rows;
            for (uint32_t jitter : {own.mbJitterSize, own.mbJitterSize == 2 ? 4u : 2u}) {
                TierProfile profile = own;
                profile.mbJitterSize = jitter;  // the SDK has no jitter switch: resolveMotionBlur takes the pattern from the profile
                Track t;
                t.tier = toString(tier), t.source = "reference", t.jitter = jitter, t.tierJitter = jitter == own.mbJitterSize;
                t.params = resolveMotionBlur(profile, at, height).value();  // the tier table's values and the defaults are valid
                tracks.push_back(t);
            }
        }
        for (const std::unique_ptr<Runner>& r : runners) {
            if (r->tier != tier) continue;
            Track t;
            t.tier = toString(tier), t.source = r->backend, t.jitter = own.mbJitterSize, t.runner = r.get();
            t.params = resolveMotionBlur(own, settings, height).value();
            tracks.push_back(t);
        }
    }
    return tracks;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"bench_mb_flicker: motion blur's frame-to-frame change against the truth's, per scene family, speed, tier and backend"};
    uint32_t width = 320, height = 240, instants = 64, seed = 1, frames = 8, jitterRows = 240;
    double period = 2, pan = 0.3;
    std::string csvPath = "mb_flicker.csv", backendsFlag = "vulkan,gles", speedsFlag = "2,6,12,24", familiesFlag = "all";
    app.add_option("--width", width, "picture width")->capture_default_str();
    app.add_option("--height", height, "picture height")->capture_default_str();
    app.add_option("--frames", frames, "frames per sequence (>= 2)")->capture_default_str();
    app.add_option("--period", period, "frame period in shutter intervals (2 = a 180 degree shutter)")->capture_default_str();
    app.add_option("--pan", pan, "camera pan, pixels per shutter interval (direction 0.8, 0.6)")->capture_default_str();
    app.add_option("--instants", instants, "instants averaged for each frame's truth")->capture_default_str();
    app.add_option("--seed", seed, "layout seed of every family")->capture_default_str();
    app.add_option("--speeds", speedsFlag, "displacements across the shutter, pixels, comma-separated")->capture_default_str();
    app.add_option("--families", familiesFlag, "comma-separated families, or all")->capture_default_str();
    app.add_option("--backends", backendsFlag, "comma-separated backends; none = CPU reference only")->capture_default_str();
    app.add_option("--jitter-rows", jitterRows,
                   "also run the reference with the tiers' radius defined at this many rows (MotionBlurSettings::referenceRows), "
                   "long enough for the jitter to act; 0 = not")
        ->capture_default_str();
    app.add_option("--csv", csvPath, "CSV output file")->capture_default_str();
    std::string docPath;
    bool docOnly = false;
    app.add_option("--doc", docPath, "write the flicker tables into this page's section bench_mb_flicker");
    app.add_flag("--doc-only", docOnly, "with --doc: write the section from --csv as it is, without running anything");
    CLI11_PARSE(app, argc, argv);
    auto writeDoc = [&]() -> int {
        char setup[256];
        std::snprintf(setup, sizeof setup,
                      "Measured by `bench_mb_flicker` at %u × %u: %u frames per sequence, %g shutter intervals apart, a pan of %g px per interval, "
                      "each frame's truth the average of %u instants.",
                      width, height, frames, period, pan, instants);
        Result<std::string> text = tools::mbFlickerTables(csvPath, setup);
        Status st = text ? tools::replaceMarkdownSection(docPath, "bench_mb_flicker", text.value()) : text.status();
        if (!st) {
            std::cerr << "bench_mb_flicker: " << st.toString() << "\n";
            return 1;
        }
        std::printf("wrote the section bench_mb_flicker of %s\n", docPath.c_str());
        return 0;
    };
    if (docOnly) return docPath.empty() ? (std::cerr << "bench_mb_flicker: --doc-only needs --doc\n", 1) : writeDoc();
    if (width == 0 || height == 0 || instants < 2 || frames < 2 || !(period > 0)) {
        std::cerr << "bench_mb_flicker: --width and --height must be > 0, --instants and --frames >= 2, --period > 0\n";
        return 1;
    }
    const auto started = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };

    std::vector<std::unique_ptr<Runner>> runners;
    for (Tier tier : {Tier::Current, Tier::High})
        for (const BackendConfig& config : compiledBackends()) {
            if (config.backend == BackendKind::Null || (backendsFlag != "all" && !tools::inList(backendsFlag, toString(config)))) continue;
            Result<std::unique_ptr<Device>> d = tools::openForTier(config, tier);
            if (!d) {
                std::cout << toString(config) << "/" << toString(tier) << ": skipped (" << d.status().toString() << ")\n";
                continue;
            }
            auto r = std::make_unique<Runner>(toString(config), tier, std::move(d.value()));
            if (Status st = openEffect(*r, width, height); !st) {
                std::cout << toString(config) << "/" << toString(tier) << ": skipped (" << st.toString() << ")\n";
                continue;
            }
            runners.push_back(std::move(r));
        }
    PerspectiveDesc pd;
    pd.aspect = double(width) / height;
    const CameraProjection cam = makePerspective(pd).value();
    const std::array<double, 2> panPx{0.8 * pan, 0.6 * pan};

    std::ofstream csv(csvPath);
    csv << "family,split,speed_px,tier,source,radius_px,jitter,tier_jitter,frames,period,pan_px,temporal_psnr_mean,temporal_psnr_worst,"
           "temporal_psnr_frame_mean,input_temporal_psnr_mean,temporal_gain_db,rms_dtruth,rms_dout,rms_dinput,psnr_mean,psnr_worst,"
           "input_psnr_mean,truth_floor_psnr\n";
    const std::vector<double> speeds = tools::splitNumberList(speedsFlag);
    for (const std::string& family : tools::familyNames()) {
        if (familiesFlag != "all" && !tools::inList(familiesFlag, family)) continue;
        for (double speed : speeds) {
            const tools::FamilyCase fc = tools::makeFamilyCase(family, speed, seed, width, height);
            std::vector<Track> tracks = makeTracks(runners, height, jitterRows);
            // Frames centred on the family's layout, so the middle frame is the one bench_mb_families scores.
            ColorGrid prevTruth, prevTruthHalf;
            std::vector<bool> prevObjects;
            std::vector<double> rmsTruth, floorPsnr;
            for (uint32_t f = 0; f < frames; ++f) {
                const double centre = (double(f) - 0.5 * (frames - 1)) * period;
                const tools::SequenceFrame sf = tools::sequenceFrame(tools::sequenceScene(fc.scene, centre, panPx), instants);
                std::vector<bool> pairMask;
                if (f > 0) {
                    pairMask = sf.objects;
                    for (size_t i = 0; i < pairMask.size(); ++i) pairMask[i] = pairMask[i] || prevObjects[i];
                    rmsTruth.push_back(changeError(prevTruth, sf.truth, nullptr, nullptr, pairMask).rms());
                    floorPsnr.push_back(changeError(prevTruthHalf, sf.truthHalf, &prevTruth, &sf.truth, pairMask).psnr());
                }
                for (Track& t : tracks) {
                    if (t.failed) continue;
                    ColorGrid out;
                    if (t.source == "input") {
                        out = sf.input.color;
                    } else if (!t.runner) {
                        out = motionBlur(sf.input.color, sf.input.depth, sf.input.velocity, t.params).color;
                    } else {
                        Result<ColorGrid> run = runFrame(*t.runner, sf.input, cam);
                        if (!run) {
                            std::printf("  %s %s FAILED %s\n", t.tier.c_str(), t.source.c_str(), run.status().toString().c_str());
                            t.failed = true;
                            continue;
                        }
                        out = std::move(run.value());
                    }
                    t.psnr.push_back(tools::familyPsnr(out, sf.truth, sf.objects));
                    if (f > 0) {
                        t.temporal.push_back(changeError(t.prev, out, &prevTruth, &sf.truth, pairMask).psnr());
                        t.temporalFrame.push_back(changeError(t.prev, out, &prevTruth, &sf.truth, {}).psnr());
                        t.rmsOut.push_back(changeError(t.prev, out, nullptr, nullptr, pairMask).rms());
                    }
                    t.prev = std::move(out);
                }
                prevTruth = sf.truth, prevTruthHalf = sf.truthHalf, prevObjects = sf.objects;
            }

            const Track& in = tracks[0];
            const Summary inTemporal = summarise(in.temporal);
            std::printf("[%s%s %g px, %u frames] input: temporal %s dB (worst %s), per frame %s dB; |D_truth| %s; truth floor %s dB; %.1f s\n",
                        family.c_str(), fc.heldOut ? " held-out" : " training", speed, frames, tools::fixedOrDash(inTemporal.mean).c_str(),
                        tools::fixedOrDash(inTemporal.worst).c_str(), tools::fixedOrDash(mean(in.psnr)).c_str(),
                        tools::fixedOrDash(mean(rmsTruth), 4).c_str(), tools::fixedOrDash(mean(floorPsnr)).c_str(), elapsed());
            for (const Track& t : tracks) {
                if (t.failed) continue;
                const Summary temporal = summarise(t.temporal), perFrame = summarise(t.psnr);
                if (&t != &in)
                    std::printf("  %-8s %-10s r=%2u jitter %u%s: temporal %s dB (worst %s, %+.2f over the input), frame %s; per frame %s dB\n",
                                t.tier.c_str(), t.source.c_str(), t.params.radiusPx, t.jitter, t.tierJitter ? " " : "*",
                                tools::fixedOrDash(temporal.mean).c_str(), tools::fixedOrDash(temporal.worst).c_str(),
                                temporal.mean - inTemporal.mean, tools::fixedOrDash(mean(t.temporalFrame)).c_str(),
                                tools::fixedOrDash(perFrame.mean).c_str());
                csv << family << "," << (fc.heldOut ? "held-out" : "training") << "," << speed << "," << t.tier << "," << t.source << ","
                    << (t.jitter ? std::to_string(t.params.radiusPx) : "-") << "," << (t.jitter ? std::to_string(t.jitter) : "-") << ","
                    << (t.tierJitter ? 1 : 0) << "," << frames << "," << period << "," << pan << "," << tools::fixedOrDash(temporal.mean) << ","
                    << tools::fixedOrDash(temporal.worst) << "," << tools::fixedOrDash(mean(t.temporalFrame)) << ","
                    << tools::fixedOrDash(inTemporal.mean) << "," << tools::fixedOrDash(temporal.mean - inTemporal.mean) << ","
                    << tools::fixedOrDash(mean(rmsTruth), 5) << "," << tools::fixedOrDash(mean(t.rmsOut), 5) << ","
                    << tools::fixedOrDash(mean(in.rmsOut), 5) << "," << tools::fixedOrDash(perFrame.mean) << "," << tools::fixedOrDash(perFrame.worst)
                    << "," << tools::fixedOrDash(mean(in.psnr)) << "," << tools::fixedOrDash(mean(floorPsnr)) << "\n";
            }
            std::fflush(stdout);
        }
    }
    std::printf("(* = the other tier's jitter pattern) %.1f s\nwrote %s\n", elapsed(), csvPath.c_str());
    csv.close();
    return docPath.empty() ? 0 : writeDoc();
}
