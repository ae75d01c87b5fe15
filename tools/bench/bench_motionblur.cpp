// bench_motionblur: the cost and the error of motion blur reconstruction per backend x tier.
// Not a test. Two kinds of scene, each with a ground truth by temporal supersampling:
// - procedural 2.5D scenes (sfx::reference::MotionScene: textured layers with analytic motion): the
//   average of --instants exact instants; the effect gets the mid-shutter frame with its exact
//   linear depth and velocity;
// - the 3D sample scenes (tools/scenes/scene.hpp) given motion: "contact" with moving spheres,
//   "columns" with a panning camera (once with the G-buffer's velocity, once camera-only). Each
//   device rasterises --scene-instants instants across the shutter, shaded on the CPU and
//   averaged; the effect gets the t = 0 frame's colour, hardware depth and RG16F velocity.
// Reports, per case, backend and tier: median cost (Vulkan: GPU timestamps; GL: wall clock after
// glFinish, as TimerReading.source says), RMSE against the ground truth over the picture and
// near moving silhouettes, the same errors of the unblurred input for scale, and the distance
// to the CPU reference. CSV to --csv; PNGs to --images (the tier pictures are the GPU output of
// the first backend that ran). The default run (320x180) takes about 10 s on 2 cores;
// --large is 1280x720.
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
#include <limits>
#include <set>

#include "bench_device.hpp"
#include "mb_raster.hpp"
#include "motion_cases.hpp"
#include "scene.hpp"
#include "sfx/backends.hpp"
#include "sfx/image_io.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/reference/motion_blur_reference.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

io::Image toImage(const ColorGrid& g) {
    io::Image img(g.width, g.height, 3);
    for (uint32_t y = 0; y < g.height; ++y)
        for (uint32_t x = 0; x < g.width; ++x)
            for (uint32_t c = 0; c < 3; ++c) img.at(x, y, c) = float(g.at(x, y)[c]);
    return img;
}

// ---- The 3D sample scenes (tools/scenes/scene.hpp) -----------------------------------------
// Rasterised through the HAL at any instant of the shutter interval (tools/scenes/mb_raster.hpp),
// so their ground truth is the same temporal supersampling as the 2.5D scenes', with
// perspective, parallax, curved silhouettes and the rasteriser's own velocity buffer.

// One 3D case: a sample scene given motion, and where the effect's velocity comes from.
struct MovingSceneCase {
    std::string name;         // CSV and image name
    std::string scene;        // tools::makeScene name
    bool cameraOnly = false;  // velocity from depth and camera matrices, not the G-buffer's
};

std::vector<MovingSceneCase> movingSceneCases() {
    return {{"contact", "contact", false}, {"columns", "columns", false}, {"columns-camera", "columns", true}};
}

// Motion in world units per shutter interval, chosen so that at 180 rows the displacements
// are about 6-16 px, the range of the 2.5D scenes: some within the high tier's radius, the
// near floor of the pan well beyond both tiers'.
Result<tools::RasterScene> makeMovingScene(const std::string& name) {
    Result<tools::RasterScene> s = tools::makeScene(name);
    if (!s) return s;
    if (name == "contact") {
        // Objects moving over a still floor, seen by a still camera. makeScene's order: floor,
        // the large sphere, the small one on the right, the one on the left.
        if (s->meshes.size() != 4) return Status{StatusCode::InvalidArgument, "contact scene: expected floor + 3 spheres"};
        s->meshes[1].velocity = {0.2, 0.0, 0.0};
        s->meshes[2].velocity = {-0.12, 0.0, 0.12};
        s->meshes[3].velocity = {0.05, 0.15, 0.0};
    } else if (name == "columns") {
        // A camera pan across a still scene: sideways (x), nearly perpendicular to the view
        // direction, so each pixel's screen motion is nearly linear in time.
        s->eyeVelocity = {0.2, 0.0, 0.0};
    }
    return s;
}

// Pixels within `radius` of an edge between surfaces in relative motion: 4-neighbours that
// differ in coverage or by more than 3% in linear depth, and whose velocities differ by more
// than 0.5 px. The 3D analogue of movingSilhouetteMask (which knows the 2.5D layers).
std::vector<bool> sceneSilhouetteMask(const tools::ShadedFrame& f, uint32_t radius) {
    const uint32_t w = f.color.width, h = f.color.height;
    std::vector<bool> edge(size_t(w) * h, false), mask(size_t(w) * h, false);
    auto differ = [&](size_t a, size_t b) {
        const bool surface = f.drawn[a] != f.drawn[b] ||
            std::fabs(f.linearDepth.values[a] - f.linearDepth.values[b]) > 0.03 * std::min(f.linearDepth.values[a], f.linearDepth.values[b]);
        const double dx = f.velocity.values[a][0] - f.velocity.values[b][0], dy = f.velocity.values[a][1] - f.velocity.values[b][1];
        return surface && dx * dx + dy * dy > 0.25;
    };
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (x + 1 < w && differ(i, i + 1)) edge[i] = edge[i + 1] = true;
            if (y + 1 < h && differ(i, i + w)) edge[i] = edge[i + w] = true;
        }
    const int r = int(radius);
    for (int y = 0; y < int(h); ++y)
        for (int x = 0; x < int(w); ++x) {
            if (!edge[size_t(y) * w + size_t(x)]) continue;
            for (int dy = -r; dy <= r; ++dy)
                for (int dx = -r; dx <= r; ++dx)
                    if (dx * dx + dy * dy <= r * r && x + dx >= 0 && x + dx < int(w) && y + dy >= 0 && y + dy < int(h))
                        mask[size_t(y + dy) * w + size_t(x + dx)] = true;
        }
    return mask;
}

// The effect on the G-buffer as a host would run it: its D32F hardware depth and RG16F
// velocity directly, or (camera) no velocity and the camera's matrices.
Result<tools::MotionBlurRun> runOnGBuffer(Device& device, Tier tier, const tools::GBuffer& g, const ColorGrid& color, const CameraMotion* camera,
                                          uint32_t runs) {
    Result<TextureHandle> ct = tools::uploadColor(device, color, "bench-scene-color");
    if (!ct) return ct.status();
    MotionBlurInputs in;
    in.color = ct.value();
    in.depth = {g.depth, DepthKind::Hardware, g.camera};
    if (camera)
        in.camera = *camera;
    else
        in.velocity = g.velocity;
    Result<tools::MotionBlurRun> run = tools::timeMotionBlur(device, tiers::profile(tier), {}, g.width, g.height, in, runs);
    (void)device.destroyTexture(ct.value());
    return run;
}

// What every case of the run shares.
struct BenchOptions {
    uint32_t width = 320, height = 180, runs = 7;
    uint32_t sceneInstants = 64;  // ground-truth instants for the 3D scenes
    std::string imagesDir;        // none written when empty
};

const char* timingLabel(TimingSource source) { return source == TimingSource::GpuTimestamps ? "gpu-timestamps" : "wall-clock-after-finish"; }

// The 3D cases on one device: per scene the ground truth and the t = 0 frame are rendered by
// this device's rasteriser, so the input, the truth and the effect agree on every edge.
// Pictures are written for the first device that gets to each (the first backend).
Status runSceneCases(Device& device, const std::string& backend, Tier tier, const BenchOptions& o, std::ostream& csv,
                     std::set<std::string>& imagesDone) {
    Result<std::unique_ptr<tools::SceneRenderer>> renderer = tools::SceneRenderer::create(device, tier);
    if (!renderer) return renderer.status();
    const MotionBlurParams p = resolveMotionBlur(tiers::profile(tier), {}, o.height).value();
    auto writeOnce = [&](const std::string& name, const ColorGrid& c) {
        if (o.imagesDir.empty() || !imagesDone.insert(name).second) return;
        (void)io::writePng(o.imagesDir + "/mb_" + name + ".png", toImage(c));
        std::cout << "    (image mb_" << name << ".png from " << backend << ")\n";
    };
    for (const std::string sceneName : {"contact", "columns"}) {
        Result<tools::RasterScene> scene = makeMovingScene(sceneName);
        if (!scene) return scene.status();
        // Meshes are per scene: load replaces the previous scene's buffers.
        SFX_TRY(renderer.value()->load(scene.value()));
        std::cout << "[" << sceneName << " 3D] " << backend << "/" << toString(tier) << ": ground truth from " << o.sceneInstants
                  << " rendered instants...\n"
                  << std::flush;
        Result<tools::SceneTruth> sceneTruth = tools::sceneGroundTruth(device, *renderer.value(), scene.value(), o.width, o.height, o.sceneInstants);
        if (!sceneTruth) return sceneTruth.status();
        const ColorGrid& truth = sceneTruth->color;
        std::cout << "  truth's residual noise: rmse " << sceneTruth->residualRmse << " between " << (o.sceneInstants + 1) / 2 << " and "
                  << o.sceneInstants << " instants\n";
        Result<tools::GBuffer> g = renderer.value()->render(scene.value(), o.width, o.height, 0.0);
        if (!g) return g.status();
        auto measure = [&]() -> Status {
            Result<tools::ShadedFrame> frame = tools::readFrame(device, g.value());
            if (!frame) return frame.status();
            const std::vector<bool> mask = sceneSilhouetteMask(frame.value(), 4 + o.height / 60);
            const tools::ColorErrors input = tools::colorErrors(frame->color, truth, mask);
            double maxSpeed = 0;
            for (const auto& v : frame->velocity.values) maxSpeed = std::max(maxSpeed, std::hypot(v[0], v[1]));
            std::cout << "  input (no blur): rmse " << input.rmse << ", near moving silhouettes " << input.rmseSilhouette << "; largest velocity "
                      << maxSpeed << " px across the shutter\n";
            writeOnce(sceneName + "_input", frame->color);
            writeOnce(sceneName + "_groundtruth", truth);
            for (const MovingSceneCase& c : movingSceneCases()) {
                if (c.scene != sceneName) continue;
                // CameraMotion wants the frame's own view-projection as current (each pixel's
                // depth is unprojected with it) and, as previous, the one a whole shutter interval
                // earlier, so that current - previous spans the interval as the velocity buffer's
                // does. The G-buffer's shutter open / close pair is centred on the frame: as
                // {previous, current} it would unproject this frame's depth with the closing
                // camera (the velocity of a point half a displacement away, wrong at depth edges);
                // {open, this frame's} would give half the displacement. The two spans differ
                // only by the curvature of each pixel's screen path, small for this pan.
                CameraMotion motion;
                motion.currentViewProjection = g->camera.projection * scene->view(0.0);
                motion.previousViewProjection = g->camera.projection * scene->view(-1.0);
                VelocityGrid v = frame->velocity;
                if (c.cameraOnly) {
                    v = cameraVelocity(frame->linearDepth, g->camera.projection, motion);
                    double diff = 0;
                    size_t n = 0;
                    for (size_t i = 0; i < v.values.size(); ++i)
                        if (frame->drawn[i])
                            diff += std::hypot(v.values[i][0] - frame->velocity.values[i][0], v.values[i][1] - frame->velocity.values[i][1]), ++n;
                    std::cout << "  camera-only velocity vs the G-buffer's: mean difference " << (n ? diff / n : 0.0) << " px\n";
                }
                Result<tools::MotionBlurRun> run = runOnGBuffer(device, tier, g.value(), frame->color, c.cameraOnly ? &motion : nullptr, o.runs);
                if (!run) {
                    std::cout << "  " << c.name << " " << backend << "/" << toString(tier) << ": FAILED " << run.status().toString() << "\n";
                    continue;
                }
                const ColorGrid ref = motionBlur(frame->color, frame->linearDepth, v, p).color;
                const tools::ColorErrors e = tools::colorErrors(run->output, truth, mask);
                const tools::ColorErrors vsRef = tools::colorErrors(run->output, ref, std::vector<bool>(mask.size(), false));
                const char* velocity = c.cameraOnly ? "camera" : "buffer";
                std::printf("  %-15s %-10s %-7s %u taps r=%u px: %8.3f ms (%s), rmse %.4f, silhouettes %.4f, vs reference %.5f\n", c.name.c_str(),
                            backend.c_str(), toString(tier), p.taps, p.radiusPx, run->medianMs, timingLabel(run->source), e.rmse, e.rmseSilhouette,
                            vsRef.rmse);
                std::fflush(stdout);
                writeOnce(c.name + "_" + toString(tier), run->output);
                csv << c.name << "," << o.width << "," << o.height << "," << backend << "," << toString(tier) << "," << p.taps << "," << p.radiusPx
                    << "," << timingLabel(run->source) << "," << run->medianMs << "," << e.rmse << "," << e.rmseSilhouette << "," << input.rmse << ","
                    << input.rmseSilhouette << "," << vsRef.rmse << "," << velocity << "\n";
            }
            return Status::ok();
        };
        Status s = measure();
        renderer.value()->destroy(g.value());
        SFX_TRY(s);
    }
    return Status::ok();
}

Status writeInputs(const std::string& dir, uint32_t w, uint32_t h) {
    const MotionScene scene = tools::makeMotionScenes(w, h)[0].scene;
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
    // Hostile values (PFM keeps 32-bit floats): huge and infinite velocities are clamped by the
    // effect; a NaN is a named error of the tool.
    io::Image huge = vel3, nan = vel3;
    huge.at(10, 10, 0) = 1.0e6f;
    huge.at(20, 12, 1) = -std::numeric_limits<float>::infinity();
    huge.at(30, 20, 0) = std::numeric_limits<float>::max();
    nan.at(5, 7, 1) = std::numeric_limits<float>::quiet_NaN();
    SFX_TRY(io::writeImage(dir + "/velocity_huge.pfm", huge));
    SFX_TRY(io::writeImage(dir + "/velocity_nan.pfm", nan));
    std::cout << "wrote " << w << "x" << h << " motion blur inputs to " << dir << "\n";
    return Status::ok();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"bench_motionblur: cost and error of motion blur per backend x tier against temporal supersampling"};
    uint32_t width = 320, height = 180, runs = 15, instants = 64, sceneInstants = 64;
    bool large = false, no3d = false;
    std::string csvPath = "bench_motionblur.csv", imagesDir, writeDir, backendsFlag = "all";
    app.add_option("--width", width, "picture width")->capture_default_str();
    app.add_option("--height", height, "picture height")->capture_default_str();
    app.add_flag("--large", large, "1280x720 instead of the default size (several minutes on 2 cores)");
    app.add_option("--runs", runs, "timed runs per configuration (median reported)")->capture_default_str();
    app.add_option("--instants", instants, "instants averaged for the ground truth")->capture_default_str();
    app.add_option("--scene-instants", sceneInstants, "rendered instants averaged for the 3D scenes' ground truth")->capture_default_str();
    app.add_flag("--no-3d", no3d, "skip the 3D sample scenes");
    app.add_option("--backends", backendsFlag, "comma-separated backends, or all compiled ones")->capture_default_str();
    app.add_option("--csv", csvPath, "CSV output file")->capture_default_str();
    app.add_option("--images", imagesDir, "directory for before / after / ground-truth PNGs (none when empty)");
    app.add_option("--write-inputs", writeDir, "write CLI input files of the first scene to DIR and exit");
    CLI11_PARSE(app, argc, argv);
    if (large) width = 1280, height = 720;
    if (width == 0 || height == 0 || runs == 0 || instants == 0 || sceneInstants == 0) {
        std::cerr << "bench_motionblur: --width, --height, --runs, --instants and --scene-instants must be > 0\n";
        return 1;
    }
    if (!writeDir.empty()) {
        Status s = writeInputs(writeDir, width, height);
        if (!s) std::cerr << "bench_motionblur: " << s.toString() << "\n";
        return s ? 0 : 1;
    }

    std::vector<BackendConfig> configs;
    for (const BackendConfig& c : compiledBackends())
        if (c.backend != BackendKind::Null &&
            (backendsFlag == "all" || ("," + backendsFlag + ",").find("," + toString(c) + ",") != std::string::npos))
            configs.push_back(c);

    std::ofstream csv(csvPath);
    csv << "scene,width,height,backend,tier,taps,radius_px,timing_source,median_ms,rmse,rmse_silhouette,input_rmse,input_rmse_silhouette,reference_"
           "rmse,velocity\n";
    PerspectiveDesc pd;
    pd.aspect = double(width) / height;
    const CameraProjection cam = makePerspective(pd).value();

    for (const tools::NamedMotionScene& ns : tools::makeMotionScenes(width, height)) {
        std::cout << "[" << ns.name << "] ground truth from " << instants << " instants at " << width << "x" << height << "...\n" << std::flush;
        const ColorGrid truth = ns.scene.groundTruth(instants);
        const SceneFrame frame = ns.scene.render(0);
        const std::vector<bool> mask = movingSilhouetteMask(frame, ns.scene, 4 + height / 60);
        const tools::ColorErrors input = tools::colorErrors(frame.color, truth, mask);
        std::cout << "  input (no blur): rmse " << input.rmse << ", near moving silhouettes " << input.rmseSilhouette << "\n";
        if (!imagesDir.empty()) {
            (void)io::writePng(imagesDir + "/mb_" + ns.name + "_input.png", toImage(frame.color));
            (void)io::writePng(imagesDir + "/mb_" + ns.name + "_groundtruth.png", toImage(truth));
        }
        for (Tier tier : {Tier::Current, Tier::High}) {
            const MotionBlurParams p = resolveMotionBlur(tiers::profile(tier), {}, height).value();
            const ColorGrid ref = motionBlur(frame.color, frame.depth, frame.velocity, p).color;
            const tools::ColorErrors refErr = tools::colorErrors(ref, truth, mask);
            std::cout << "  reference " << toString(tier) << ": rmse " << refErr.rmse << ", silhouettes " << refErr.rmseSilhouette << "\n";
            // The tier picture is the GPU output of the first backend that runs; the CPU
            // reference is written (named as such) only when none does.
            bool imageWritten = false;
            for (const BackendConfig& config : configs) {
                Result<std::unique_ptr<Device>> device = tools::openForTier(config, tier);
                if (!device) {
                    std::cout << "  " << toString(config) << "/" << toString(tier) << ": skipped (" << device.status().toString() << ")\n";
                    continue;
                }
                Result<tools::MotionBlurRun> run = tools::runMotionBlur(*device.value(), tiers::profile(tier), {}, frame, cam, runs);
                if (!run) {
                    std::cout << "  " << toString(config) << "/" << toString(tier) << ": FAILED " << run.status().toString() << "\n";
                    continue;
                }
                const tools::ColorErrors e = tools::colorErrors(run->output, truth, mask);
                const tools::ColorErrors vsRef = tools::colorErrors(run->output, ref, std::vector<bool>(mask.size(), false));
                const char* source = timingLabel(run->source);
                std::printf("  %-10s %-7s %u taps r=%u px: %8.3f ms (%s), rmse %.4f, silhouettes %.4f, vs reference %.5f\n", toString(config).c_str(),
                            toString(tier), p.taps, p.radiusPx, run->medianMs, source, e.rmse, e.rmseSilhouette, vsRef.rmse);
                std::fflush(stdout);
                if (!imagesDir.empty() && !imageWritten) {
                    (void)io::writePng(imagesDir + "/mb_" + ns.name + "_" + toString(tier) + ".png", toImage(run->output));
                    std::cout << "    (image mb_" << ns.name << "_" << toString(tier) << ".png from " << toString(config) << ")\n";
                    imageWritten = true;
                }
                csv << ns.name << "," << width << "," << height << "," << toString(config) << "," << toString(tier) << "," << p.taps << ","
                    << p.radiusPx << "," << source << "," << run->medianMs << "," << e.rmse << "," << e.rmseSilhouette << "," << input.rmse << ","
                    << input.rmseSilhouette << "," << vsRef.rmse << ",buffer\n";
            }
            if (!imagesDir.empty() && !imageWritten)
                (void)io::writePng(imagesDir + "/mb_" + ns.name + "_" + toString(tier) + "_reference.png", toImage(ref));
        }
    }
    if (!no3d) {
        const BenchOptions o{width, height, runs, sceneInstants, imagesDir};
        std::set<std::string> imagesDone;
        for (const BackendConfig& config : configs)
            for (Tier tier : {Tier::Current, Tier::High}) {
                Result<std::unique_ptr<Device>> device = tools::openForTier(config, tier);
                if (!device) {
                    std::cout << "[3D] " << toString(config) << "/" << toString(tier) << ": skipped (" << device.status().toString() << ")\n";
                    continue;
                }
                Status s = runSceneCases(*device.value(), toString(config), tier, o, csv, imagesDone);
                if (!s) std::cout << "[3D] " << toString(config) << "/" << toString(tier) << ": FAILED " << s.toString() << "\n";
            }
    }
    std::cout << "wrote " << csvPath << "\n";
    return 0;
}
