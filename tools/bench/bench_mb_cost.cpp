// bench_mb_cost: motion blur configurations timed side by side on one device, for a cost
// comparison on a machine shared with other work. Each configuration (taps : radius at 720 rows,
// the rest the high tier's) is timed on the "pan" scene (as fit_mb and trade_presets time; --scene picks another) once
// per round, in an order that alternates between rounds, beside a copy pass of the same size as
// the load indicator; printed are the medians over the rounds. --exposure scales every velocity
// (a slower scene: the pair count follows the speed). A program, not a test; docs/motion_blur.md
// shows its figures.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

#include "bench_device.hpp"
#include "copy_pass.hpp"
#include "motion_cases.hpp"
#include "sfx/backends.hpp"
#include "sfx/settings_ranges.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Config {
    std::string label;
    TierProfile profile;
    std::vector<double> ms;
};

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"bench_mb_cost: motion blur configurations timed alternately on one backend", "bench_mb_cost"};
    std::vector<std::string> configs{"13:18", "9:18", "7:14"};
    std::string backend = "vulkan", sceneName = "pan";
    uint32_t width = 1280, height = 720, runs = 5, rounds = 7;
    float exposure = 1.0f;
    app.add_option("--configs", configs, "taps:radius, comma-separated")->delimiter(',')->capture_default_str();
    app.add_option("--backend", backend, "the backend timing them")->capture_default_str();
    app.add_option("--scene", sceneName, "the procedural scene timed: ball, pan or crossing")->capture_default_str();
    app.add_option("--width", width, "pixels of the timed runs")->capture_default_str();
    app.add_option("--height", height, "pixels of the timed runs")->capture_default_str();
    app.add_option("--runs", runs, "timed runs per configuration and round (median)")->capture_default_str();
    app.add_option("--rounds", rounds, "rounds, the configurations' order alternating")->capture_default_str();
    app.add_option("--exposure", exposure, "MotionBlurSettings::exposure: scales the scene's velocities (a slower scene), (0, 4]")
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    if (Status st = checkSetting(Setting::MbExposure, exposure, "--exposure"); !st) {
        std::cerr << "bench_mb_cost: " << st.toString() << "\n";
        return 1;
    }
    if (exposure == 0.0f) {
        std::cerr << "bench_mb_cost: --exposure 0 turns the blur off: nothing to time\n";
        return 1;
    }
    MotionBlurSettings settings;
    settings.exposure = exposure;

    const TierProfile high = tiers::profile(Tier::High);
    std::vector<Config> list;
    for (const std::string& c : configs) {
        std::istringstream in(c);
        uint32_t taps = 0;
        float radius = 0;
        char colon = 0;
        if (!(in >> taps >> colon >> radius) || colon != ':' || !in.eof()) {
            std::cerr << "bench_mb_cost: --configs " << c << ": expected taps:radius\n";
            return 1;
        }
        TierProfile p = high;
        p.mbTaps = taps, p.mbMaxRadiusPx = radius;
        list.push_back({c, p, {}});
    }
    Result<std::unique_ptr<Device>> opened = tools::openNamedForTier(backend, Tier::High);
    if (!opened) {
        std::cerr << "bench_mb_cost: --backend " << backend << ": " << opened.status().toString() << "\n";
        return 1;
    }
    std::unique_ptr<Device> device = std::move(opened.value());
    Result<std::unique_ptr<tools::CopyPass>> copy = tools::makeCopyPass(*device, Tier::High, width, height, Format::RGBA16F);
    if (!copy) {
        std::cerr << "bench_mb_cost: " << copy.status().toString() << "\n";
        return 1;
    }
    PerspectiveDesc pd;
    pd.aspect = double(width) / height;
    const CameraProjection cam = makePerspective(pd).value();
    std::optional<reference::SceneFrame> found;
    for (const tools::NamedMotionScene& named : tools::makeMotionScenes(width, height))
        if (named.name == sceneName) found = named.scene.render(0);
    if (!found) {
        std::cerr << "bench_mb_cost: --scene " << sceneName << ": allowed ball, pan, crossing\n";
        return 1;
    }
    const reference::SceneFrame& frame = *found;
    std::vector<double> copyMs;
    for (uint32_t round = 0; round < rounds; ++round) {
        for (size_t k = 0; k < list.size(); ++k) {
            Config& c = list[round % 2 == 0 ? k : list.size() - 1 - k];
            Result<tools::MotionBlurRun> run = tools::runMotionBlur(*device, c.profile, settings, frame, cam, runs);
            if (!run) {
                std::cerr << "bench_mb_cost: " << c.label << ": " << run.status().toString() << "\n";
                return 1;
            }
            c.ms.push_back(run->medianMs);
        }
        Result<double> ms = copy.value()->medianMs(runs);
        if (!ms) {
            std::cerr << "bench_mb_cost: copy pass: " << ms.status().toString() << "\n";
            return 1;
        }
        copyMs.push_back(ms.value());
        std::printf("round %u: copy pass %.2f ms;", round + 1, ms.value());
        for (const Config& c : list) std::printf(" %s %.2f ms;", c.label.c_str(), c.ms.back());
        std::printf("\n");
        std::fflush(stdout);
    }
    std::printf("%s at %ux%u, exposure %.2f, medians of %u rounds (each a median of %u runs); copy pass %.2f ms\n", backend.c_str(), width, height,
                exposure, rounds, runs, median(copyMs));
    for (const Config& c : list) std::printf("  %-10s %.2f ms (%.1f copy passes)\n", c.label.c_str(), median(c.ms), median(c.ms) / median(copyMs));
    return 0;
}
