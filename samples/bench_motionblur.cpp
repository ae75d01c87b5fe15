// bench_motionblur: the cost and the error of motion blur reconstruction per backend x tier.
// Not a test. For each procedural scene (sfx::reference::Scene: textured layers with analytic
// motion) the ground truth is the average of many instants across the shutter interval; the
// effect gets the mid-shutter frame with its exact depth and velocity. Reports, per scene,
// backend and tier: median cost (Vulkan: GPU timestamps; GL: wall clock after glFinish, as
// TimerReading.source says), RMSE against the ground truth over the picture and near moving
// silhouettes, and the same errors of the unblurred input for scale. CSV to --csv, PNGs to
// --images. The default run (320x180) takes well under 3 minutes on 2 cores; --large is 1280x720.
//
// --write-inputs DIR writes one scene as CLI inputs (colour.exr, depth.pfm, velocity.exr) plus
// deliberately malformed files, for the `sfx motionblur` CTest entries.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "sfx/backends.hpp"
#include "sfx/image_io.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/reference/motion_blur_reference.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

struct NamedScene {
    std::string name;
    Scene scene;
};

// Scenes laid out in fractions of the picture, so every size shows the same thing; velocities
// scale with the height as the tier radii do. At 180 rows the displacements (8-10 px, a blur
// radius of 4-5 px) sit at the high tier's radius (4.5 px there) and beyond the current
// tier's (2.5 px): the current tier is expected to clamp, the high tier barely.
std::vector<NamedScene> makeScenes(uint32_t w, uint32_t h) {
    const double s = h / 180.0;  // pixels per "design pixel" (designed at 320x180)
    std::vector<NamedScene> out;
    {
        // A ball flying across a still textured wall.
        Scene sc{w, h, {}};
        SceneLayer wall;
        wall.depth = 20, wall.cell = 10 * s, wall.colorA = {0.55, 0.5, 0.45, 1}, wall.colorB = {0.25, 0.3, 0.35, 1};
        SceneLayer ball;
        ball.shape = SceneLayer::Shape::Disc, ball.depth = 6, ball.centre = {w * 0.45, h * 0.5}, ball.halfSize = {28 * s, 0};
        ball.cell = 7 * s, ball.colorA = {1.0, 0.85, 0.2, 1}, ball.colorB = {0.9, 0.2, 0.1, 1}, ball.velocityPx = {10 * s, 2 * s};
        sc.layers = {wall, ball};
        out.push_back({"ball", sc});
    }
    {
        // A camera pan: the background slides, a post tracked by the camera stays still in front,
        // and a box moves against the pan behind the post.
        Scene sc{w, h, {}};
        SceneLayer bg;
        bg.depth = 40, bg.cell = 12 * s, bg.colorA = {0.2, 0.45, 0.7, 1}, bg.colorB = {0.8, 0.85, 0.9, 1}, bg.velocityPx = {-8 * s, 0};
        SceneLayer box;
        box.shape = SceneLayer::Shape::Rect, box.depth = 15, box.centre = {w * 0.55, h * 0.45}, box.halfSize = {30 * s, 22 * s};
        box.cell = 6 * s, box.colorA = {0.9, 0.3, 0.3, 1}, box.colorB = {0.3, 0.1, 0.1, 1}, box.velocityPx = {9 * s, -3 * s};
        SceneLayer post;
        post.shape = SceneLayer::Shape::Rect, post.depth = 4, post.centre = {w * 0.5, h * 0.5}, post.halfSize = {7 * s, h * 0.6};
        post.cell = 5 * s, post.colorA = {0.2, 0.8, 0.3, 1}, post.colorB = {0.1, 0.4, 0.15, 1};
        sc.layers = {bg, box, post};
        out.push_back({"pan", sc});
    }
    {
        // Two discs crossing at different depths, both moving, over a still floor.
        Scene sc{w, h, {}};
        SceneLayer floor;
        floor.depth = 25, floor.cell = 8 * s, floor.colorA = {0.4, 0.4, 0.4, 1}, floor.colorB = {0.6, 0.6, 0.6, 1};
        SceneLayer a;
        a.shape = SceneLayer::Shape::Disc, a.depth = 8, a.centre = {w * 0.42, h * 0.48}, a.halfSize = {24 * s, 0};
        a.colorA = {0.95, 0.6, 0.1, 1}, a.velocityPx = {8 * s, 0};
        SceneLayer b = a;
        b.depth = 12, b.centre = {w * 0.56, h * 0.55}, b.colorA = {0.2, 0.3, 0.95, 1}, b.cell = 6 * s, b.colorB = {0.9, 0.9, 1, 1};
        b.velocityPx = {-6 * s, -4 * s};
        sc.layers = {floor, b, a};
        out.push_back({"crossing", sc});
    }
    return out;
}

io::Image toImage(const ColorGrid& g) {
    io::Image img(g.width, g.height, 3);
    for (uint32_t y = 0; y < g.height; ++y)
        for (uint32_t x = 0; x < g.width; ++x)
            for (uint32_t c = 0; c < 3; ++c) img.at(x, y, c) = float(g.at(x, y)[c]);
    return img;
}

struct Errors {
    double rmse = 0, rmseSilhouette = 0;
};
Errors errorsOf(const ColorGrid& a, const ColorGrid& truth, const std::vector<bool>& mask) {
    double all = 0, sil = 0;
    size_t nSil = 0;
    for (size_t i = 0; i < a.values.size(); ++i) {
        double e = 0;
        for (int c = 0; c < 3; ++c) e += std::pow(a.values[i][c] - truth.values[i][c], 2);
        all += e;
        if (mask[i]) sil += e, ++nSil;
    }
    return {std::sqrt(all / (3.0 * a.values.size())), nSil ? std::sqrt(sil / (3.0 * nSil)) : 0.0};
}

struct Run {
    ColorGrid output;
    double medianMs = 0;
    TimingSource source = TimingSource::GpuTimestamps;
};

// Runs the effect `runs` times (after one warm-up) and reads the last output back.
Result<Run> runEffect(Device& device, Tier tier, const SceneFrame& f, const CameraProjection& cam, uint32_t runs) {
    const uint32_t w = f.color.width, h = f.color.height;
    const bool full = device.caps().renderableFormat[size_t(Format::RGBA32F)];
    if (!full) return Status{StatusCode::UnsupportedFormat, "bench needs RGBA32F render targets"};
    std::vector<float> c, z, v;
    for (const auto& px : f.color.values)
        for (double ch : px) c.push_back(float(ch));
    for (double d : f.depth.values) z.push_back(float(d));
    for (const auto& e : f.velocity.values) v.push_back(float(e[0])), v.push_back(float(e[1]));
    Result<TextureHandle> ct = device.createTexture({w, h, 1, Format::RGBA32F, kTextureSampled, "bench-color"});
    Result<TextureHandle> zt = device.createTexture({w, h, 1, Format::R32F, kTextureSampled, "bench-depth"});
    Result<TextureHandle> vt = device.createTexture({w, h, 1, Format::RG32F, kTextureSampled, "bench-velocity"});
    if (!ct) return ct.status();
    if (!zt) return zt.status();
    if (!vt) return vt.status();
    SFX_TRY(device.writeTexture(ct.value(), 0, c.data(), c.size() * 4));
    SFX_TRY(device.writeTexture(zt.value(), 0, z.data(), z.size() * 4));
    SFX_TRY(device.writeTexture(vt.value(), 0, v.data(), v.size() * 4));
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(device, {w, h, tier, Format::RGBA32F});
    if (!mb) return mb.status();
    Result<TimerHandle> timer = device.createTimer();
    if (!timer) return timer.status();
    MotionBlurInputs in;
    in.color = ct.value();
    in.depth = {zt.value(), DepthKind::Linear, cam};
    in.velocity = vt.value();
    std::vector<double> times;
    Run run;
    for (uint32_t i = 0; i <= runs; ++i) {
        SFX_TRY(device.beginTimer(timer.value()));
        SFX_TRY(mb.value()->dispatch(in));
        SFX_TRY(device.endTimer(timer.value()));
        SFX_TRY(device.flush());
        Result<TimerReading> r = device.readTimer(timer.value());
        if (!r) return r.status();
        run.source = r->source;
        if (i > 0) times.push_back(r->milliseconds);  // run 0 warms caches and compiles
    }
    std::sort(times.begin(), times.end());
    run.medianMs = times[times.size() / 2];
    std::vector<float> out(size_t(w) * h * 4);
    SFX_TRY(device.readTexture(mb.value()->output(), 0, out.data(), out.size() * 4));
    run.output = ColorGrid(w, h);
    for (size_t i = 0; i < run.output.values.size(); ++i)
        for (int ch = 0; ch < 4; ++ch) run.output.values[i][ch] = out[i * 4 + size_t(ch)];
    (void)device.destroyTimer(timer.value());
    mb.value().reset();
    for (TextureHandle t : {ct.value(), zt.value(), vt.value()}) (void)device.destroyTexture(t);
    return run;
}

Status writeInputs(const std::string& dir, uint32_t w, uint32_t h) {
    const Scene scene = makeScenes(w, h)[0].scene;
    const SceneFrame f = scene.render(0);
    io::Image color(w, h, 3), depth(w, h, 1), vel(w, h, 2), vel3(w, h, 3);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            for (uint32_t c = 0; c < 3; ++c) color.at(x, y, c) = float(f.color.at(x, y)[c]);
            depth.at(x, y) = float(f.depth.at(x, y));
            for (uint32_t c = 0; c < 2; ++c) vel.at(x, y, c) = vel3.at(x, y, c) = float(f.velocity.at(x, y)[c]);
        }
    SFX_TRY(io::writeImage(dir + "/colour.exr", color));
    SFX_TRY(io::writeImage(dir + "/colour.png", color));
    SFX_TRY(io::writeImage(dir + "/depth.pfm", depth));
    SFX_TRY(io::writeImage(dir + "/velocity.exr", vel));
    SFX_TRY(io::writeImage(dir + "/velocity.pfm", vel3));
    SFX_TRY(io::writeImage(dir + "/groundtruth.png", toImage(scene.groundTruth(32))));
    // Malformed: a velocity of the wrong size, one with a single channel, and a corrupt EXR.
    io::Image small(w / 2, h / 2, 2);
    SFX_TRY(io::writeImage(dir + "/velocity_small.exr", small));
    SFX_TRY(io::writeImage(dir + "/velocity_1ch.exr", depth));
    std::ofstream(dir + "/velocity_corrupt.exr") << "this is not an OpenEXR file\n";
    std::cout << "wrote " << w << "x" << h << " motion blur inputs to " << dir << "\n";
    return Status::ok();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"bench_motionblur: cost and error of motion blur per backend x tier against temporal supersampling"};
    uint32_t width = 320, height = 180, runs = 7, instants = 64;
    bool large = false;
    std::string csvPath = "bench_motionblur.csv", imagesDir, writeDir, backendsFlag = "all";
    app.add_option("--width", width, "picture width")->capture_default_str();
    app.add_option("--height", height, "picture height")->capture_default_str();
    app.add_flag("--large", large, "1280x720 instead of the default size (several minutes on 2 cores)");
    app.add_option("--runs", runs, "timed runs per configuration (median reported)")->capture_default_str();
    app.add_option("--instants", instants, "instants averaged for the ground truth")->capture_default_str();
    app.add_option("--backends", backendsFlag, "comma-separated backends, or all compiled ones")->capture_default_str();
    app.add_option("--csv", csvPath, "CSV output file")->capture_default_str();
    app.add_option("--images", imagesDir, "directory for before / after / ground-truth PNGs (none when empty)");
    app.add_option("--write-inputs", writeDir, "write CLI input files of the first scene to DIR and exit");
    CLI11_PARSE(app, argc, argv);
    if (large) width = 1280, height = 720;
    if (width == 0 || height == 0 || runs == 0 || instants == 0) {
        std::cerr << "bench_motionblur: --width, --height, --runs and --instants must be > 0\n";
        return 1;
    }
    if (!writeDir.empty()) {
        Status s = writeInputs(writeDir, width, height);
        if (!s) std::cerr << "bench_motionblur: " << s.toString() << "\n";
        return s ? 0 : 1;
    }

    std::vector<BackendConfig> configs;
    for (const BackendConfig& c : compiledBackends())
        if (c.backend != BackendKind::Null && (backendsFlag == "all" || ("," + backendsFlag + ",").find("," + toString(c) + ",") != std::string::npos))
            configs.push_back(c);

    std::ofstream csv(csvPath);
    csv << "scene,width,height,backend,tier,taps,radius_px,timing_source,median_ms,rmse,rmse_silhouette,input_rmse,input_rmse_silhouette,reference_rmse\n";
    PerspectiveDesc pd;
    pd.aspect = double(width) / height;
    const CameraProjection cam = makePerspective(pd).value();

    for (const NamedScene& ns : makeScenes(width, height)) {
        std::cout << "[" << ns.name << "] ground truth from " << instants << " instants at " << width << "x" << height << "...\n" << std::flush;
        const ColorGrid truth = ns.scene.groundTruth(instants);
        const SceneFrame frame = ns.scene.render(0);
        const std::vector<bool> mask = movingSilhouetteMask(frame, ns.scene, 4 + height / 60);
        const Errors input = errorsOf(frame.color, truth, mask);
        std::cout << "  input (no blur): rmse " << input.rmse << ", near moving silhouettes " << input.rmseSilhouette << "\n";
        if (!imagesDir.empty()) {
            (void)io::writePng(imagesDir + "/mb_" + ns.name + "_input.png", toImage(frame.color));
            (void)io::writePng(imagesDir + "/mb_" + ns.name + "_groundtruth.png", toImage(truth));
        }
        for (Tier tier : {Tier::Current, Tier::High}) {
            const MotionBlurParams p = resolveMotionBlur(tier, {}, height).value();
            const ColorGrid ref = motionBlur(frame.color, frame.depth, frame.velocity, p).color;
            const Errors refErr = errorsOf(ref, truth, mask);
            std::cout << "  reference " << toString(tier) << ": rmse " << refErr.rmse << ", silhouettes " << refErr.rmseSilhouette << "\n";
            if (!imagesDir.empty()) (void)io::writePng(imagesDir + "/mb_" + ns.name + "_" + toString(tier) + ".png", toImage(ref));
            for (const BackendConfig& config : configs) {
                DeviceOptions options;
                options.validation = false;
                options.ceiling = tier == Tier::Current ? CapabilityCeiling::GLES30 : CapabilityCeiling::None;
                Result<std::unique_ptr<Device>> device = openDevice(config, options);
                if (!device) {
                    std::cout << "  " << toString(config) << "/" << toString(tier) << ": skipped (" << device.status().toString() << ")\n";
                    continue;
                }
                Result<tiers::TierChoice> choice = tiers::choose(device.value()->caps(), tier);
                if (!choice) {
                    std::cout << "  " << toString(config) << "/" << toString(tier) << ": skipped (" << choice.status().toString() << ")\n";
                    continue;
                }
                Result<Run> run = runEffect(*device.value(), tier, frame, cam, runs);
                if (!run) {
                    std::cout << "  " << toString(config) << "/" << toString(tier) << ": FAILED " << run.status().toString() << "\n";
                    continue;
                }
                const Errors e = errorsOf(run->output, truth, mask);
                const Errors vsRef = errorsOf(run->output, ref, std::vector<bool>(mask.size(), false));
                const char* source = run->source == TimingSource::GpuTimestamps ? "gpu-timestamps" : "wall-clock-after-finish";
                std::printf("  %-10s %-7s %u taps r=%u px: %8.3f ms (%s), rmse %.4f, silhouettes %.4f, vs reference %.5f\n",
                            toString(config).c_str(), toString(tier), p.taps, p.radiusPx, run->medianMs, source, e.rmse,
                            e.rmseSilhouette, vsRef.rmse);
                std::fflush(stdout);
                csv << ns.name << "," << width << "," << height << "," << toString(config) << "," << toString(tier) << "," << p.taps << ","
                    << p.radiusPx << "," << source << "," << run->medianMs << "," << e.rmse << "," << e.rmseSilhouette << ","
                    << input.rmse << "," << input.rmseSilhouette << "," << vsRef.rmse << "\n";
            }
        }
    }
    std::cout << "wrote " << csvPath << "\n";
    return 0;
}
