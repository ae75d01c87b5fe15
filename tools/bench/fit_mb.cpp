// fit_mb: the measured front of motion blur's settings, from which each tier's presets are
// chosen. For every taps x maximum radius of a grid (the tile, jitter and everything else as
// the tiers have them, which both tiers share), the CPU reference's PSNR over the moving region
// on the TRAINING motion families (tools/scenes/mb_families.*) and, only to report, on the
// HELD-OUT ones, each the mean over the scored speeds (2-40 px at 240 rows, scaled; by default at
// 960x720, the rows the tiers' radii are given at, so the taps' spacing is the one they get at
// 720 rows); and the cost at --cost-size on one
// backend (median of HAL-timed runs on the "pan" scene, as trade_presets times presets). Prints
// the configurations no other beats on both training accuracy and cost, writes a CSV. A
// program, not a test; docs/motion_blur.md gives the rule the presets follow.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "bench_device.hpp"
#include "mb_family_scoring.hpp"
#include "motion_cases.hpp"
#include "sfx/backends.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/reference/motion_blur_reference.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;

namespace {

struct Point {
    uint32_t taps = 0;
    float radius = 0;
    double training = 0, heldOut = 0, ms = -1;
};

double meanPsnr(const std::vector<tools::ScoredFamilyCase>& cases, const TierProfile& profile) {
    double sum = 0;
    for (const tools::ScoredFamilyCase& c : cases) {
        const MotionBlurParams p = resolveMotionBlur(profile, {}, c.truth.height).value();
        sum += tools::familyPsnr(reference::motionBlur(c.frame.color, c.frame.depth, c.frame.velocity, p).color, c.truth, c.masks.moving);
    }
    return sum / double(cases.size());
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"fit_mb: motion blur's accuracy (training and held-out families) and cost per taps x maximum radius", "fit_mb"};
    std::vector<uint32_t> taps{3, 5, 7, 9, 11, 13, 15, 17};
    std::vector<float> radii{6, 8, 10, 12, 14, 18, 24};
    uint32_t instants = 256, width = 960, height = 720, costWidth = 1280, costHeight = 720, runs = 7;
    std::vector<double> speeds;
    std::string backend = "vulkan", csvPath = "mb_fit.csv";
    app.add_option("--taps", taps, "tap counts (centre included, odd)")->delimiter(',')->capture_default_str();
    app.add_option("--radii", radii, "maximum radii, pixels at 720 rows")->delimiter(',')->capture_default_str();
    app.add_option("--instants", instants, "instants averaged for the truth")->capture_default_str();
    app.add_option("--width", width, "family picture width")->capture_default_str();
    app.add_option("--height", height, "family picture height")->capture_default_str();
    app.add_option("--speeds", speeds, "displacements across the shutter, pixels (default: 2-40 px at 240 rows, scaled to the height)")
        ->delimiter(',');
    app.add_option("--backend", backend, "backend timing each configuration; none = accuracy only")->capture_default_str();
    app.add_option("--cost-width", costWidth, "pixels of the timed runs")->capture_default_str();
    app.add_option("--cost-height", costHeight, "pixels of the timed runs")->capture_default_str();
    app.add_option("--runs", runs, "timed runs per configuration (median)")->capture_default_str();
    app.add_option("--csv", csvPath, "CSV output file")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    const auto started = std::chrono::steady_clock::now();
    const auto progress = [&](const std::string& line) {
        std::printf("[%.1f s] %s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), line.c_str());
        std::fflush(stdout);
    };
    // The tiers differ in taps and radius only, which the grid sets: one profile stands for both.
    const TierProfile base = tiers::profile(Tier::High);
    if (base.mbJitterSize != tiers::profile(Tier::Current).mbJitterSize) {
        std::cerr << "fit_mb: the tiers' motion-blur jitter differs; the grid would need a run per tier\n";
        return 1;
    }
    // Opened before the truth is computed, so a wrong --backend fails at once.
    std::unique_ptr<Device> device;
    if (backend != "none") {
        Result<std::unique_ptr<Device>> d = tools::openNamedForTier(backend, Tier::High);
        if (!d) {
            std::cerr << "fit_mb: --backend " << backend << ": " << d.status().toString() << "\n";
            return 1;
        }
        device = std::move(d.value());
    }
    if (speeds.empty())
        for (double s : tools::kScoredFamilySpeedsPx) speeds.push_back(s * height / 240.0);
    const auto training = tools::scoredFamilyCases(false, speeds, instants, 1, width, height, progress);
    const auto heldOut = tools::scoredFamilyCases(true, speeds, instants, 1, width, height, progress);

    PerspectiveDesc pd;
    pd.aspect = double(costWidth) / costHeight;
    const CameraProjection cam = makePerspective(pd).value();
    const reference::SceneFrame costFrame = tools::makeMotionScenes(costWidth, costHeight)[1].scene.render(0);

    std::vector<Point> points;
    for (uint32_t t : taps)
        for (float r : radii) {
            TierProfile profile = base;
            profile.mbTaps = t, profile.mbMaxRadiusPx = r;
            if (!resolveMotionBlur(profile, {}, height)) continue;
            Point pt{t, r, meanPsnr(training, profile), meanPsnr(heldOut, profile)};
            if (device) {
                Result<tools::MotionBlurRun> run = tools::runMotionBlur(*device, profile, {}, costFrame, cam, runs);
                if (!run) {
                    std::cerr << "fit_mb: " << run.status().toString() << "\n";
                    return 1;
                }
                pt.ms = run->medianMs;
            }
            char line[160];
            std::snprintf(line, sizeof line, "%2u taps, radius %4.1f px: training %.2f dB, held-out %.2f dB, %.2f ms", t, r, pt.training, pt.heldOut,
                          pt.ms);
            progress(line);
            points.push_back(pt);
        }
    std::ofstream csv(csvPath);
    csv << "taps,max_radius_px,training_psnr_moving,heldout_psnr_moving,ms,backend,cost_width,cost_height,front\n";
    std::printf("front (no configuration both more accurate on training and cheaper):\n");
    for (const Point& p : points) {
        const bool dominated = std::any_of(points.begin(), points.end(), [&](const Point& q) {
            const bool cheaper = device ? q.ms <= p.ms : q.taps <= p.taps && q.radius <= p.radius;
            return &q != &p && q.training > p.training && cheaper;
        });
        csv << p.taps << "," << p.radius << "," << p.training << "," << p.heldOut << "," << p.ms << "," << backend << "," << costWidth << ","
            << costHeight << "," << (dominated ? 0 : 1) << "\n";
        if (!dominated)
            std::printf("  %2u taps, radius %4.1f: training %.2f, held-out %.2f dB, %.2f ms\n", p.taps, p.radius, p.training, p.heldOut, p.ms);
    }
    std::cout << "wrote " << csvPath << "\n";
    return 0;
}
