// fit_mb: the measured front of motion blur's settings, from which each tier's presets are
// chosen. For every taps x maximum radius of a grid (the tile, jitter and everything else as
// the tiers have them, which both tiers share), and for each tier's default at every tile edge
// of --tiles, the CPU reference's PSNR over the moving region
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
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "bench_device.hpp"
#include "markdown_section.hpp"
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
    float radius = 0, tile = 0;
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

// The points of a CSV this program wrote (--doc-only).
Result<std::vector<Point>> readPoints(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    if (!in || !std::getline(in, line)) return Status{StatusCode::FileError, path + ": cannot read"};
    if (line.rfind("taps,max_radius_px,tile_px,training_psnr_moving,heldout_psnr_moving,ms,", 0) != 0)
        return Status{StatusCode::InvalidArgument, path + ": not a fit_mb CSV (header " + line + ")"};
    std::vector<Point> points;
    while (std::getline(in, line)) {
        Point p;
        if (std::sscanf(line.c_str(), "%u,%f,%f,%lf,%lf,%lf", &p.taps, &p.radius, &p.tile, &p.training, &p.heldOut, &p.ms) == 6) points.push_back(p);
    }
    return points;
}

// The page's section "fit_mb": the grid (training PSNR, held-out in brackets, per taps x radius;
// the cost's range per taps) and each tier's presets placed on it, ordered by training PSNR.
std::string docSection(const std::vector<Point>& all, const std::string& backend, uint32_t w, uint32_t h, uint32_t costW, uint32_t costH,
                       uint32_t instants) {
    const float gridTile = tiers::profile(Tier::High).mbTilePx;
    std::vector<Point> points;
    std::copy_if(all.begin(), all.end(), std::back_inserter(points), [&](const Point& p) { return p.tile == gridTile; });
    std::vector<float> radii;
    std::vector<uint32_t> taps;
    for (const Point& p : points) {
        if (std::find(radii.begin(), radii.end(), p.radius) == radii.end()) radii.push_back(p.radius);
        if (std::find(taps.begin(), taps.end(), p.taps) == taps.end()) taps.push_back(p.taps);
    }
    std::sort(radii.begin(), radii.end());
    std::sort(taps.begin(), taps.end());
    auto find = [&](uint32_t t, float r) -> const Point* {
        for (const Point& p : points)
            if (p.taps == t && p.radius == r) return &p;
        return nullptr;
    };
    const auto px = tools::compactNumber;
    std::ostringstream md;
    md << "Measured by `fit_mb` at " << w << " × " << h << " (truth of " << instants << " instants), cost at " << costW << " × " << costH << " on "
       << backend << ", the tiers' tile edge (" << px(gridTile) << " px at 720 rows). Training PSNR (held-out in brackets), dB:\n\n| taps |";
    for (float r : radii) md << " " << px(r) << " px |";
    md << " cost (ms, the radii's range) |\n| --- |";
    for (size_t i = 0; i <= radii.size(); ++i) md << " --- |";
    md << "\n";
    for (uint32_t t : taps) {
        md << "| " << t << " |";
        double lo = INFINITY, hi = -INFINITY;
        for (float r : radii) {
            const Point* p = find(t, r);
            md << " " << (p ? tools::fixed(p->training, 2) + " (" + tools::fixed(p->heldOut, 2) + ")" : std::string("-")) << " |";
            if (p && p->ms >= 0) lo = std::min(lo, p->ms), hi = std::max(hi, p->ms);
        }
        md << " " << (std::isfinite(lo) ? px(std::round(lo)) + "-" + px(std::round(hi)) : std::string("-")) << " |\n";
    }
    md << "\nEach tier's presets on the grid (taps / radius at 720 rows: training PSNR), in the order of their training PSNR, and the "
          "gain of each step:\n\n| tier | presets | steps (dB) |\n| --- | --- | --- |\n";
    for (const tiers::TierRow& row : tiers::table()) {
        std::vector<std::pair<double, std::string>> placed;
        for (const Preset& preset : row.presets) {
            const Point* p = find(preset.params.mbTaps, preset.params.mbMaxRadiusPx);
            placed.push_back({p ? p->training : NAN,
                              preset.name + " " + std::to_string(preset.params.mbTaps) + " / " + px(preset.params.mbMaxRadiusPx) +
                                  " px: " + (p ? tools::fixed(p->training, 2) : "not in the grid")});
        }
        std::sort(placed.begin(), placed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        md << "| " << toString(row.tier) << " |";
        std::string steps;
        for (size_t i = 0; i < placed.size(); ++i) {
            md << (i ? ", " : " ") << placed[i].second;
            if (i) steps += (i > 1 ? ", " : "") + tools::fixedOrDash(placed[i].first - placed[i - 1].first, 2);
        }
        md << " | " << steps << " |\n";
    }
    return md.str();
}

// The page's section "fit_mb_tiles": each tier's default at every tile edge measured.
std::string tileSection(const std::vector<Point>& points, const std::string& backend) {
    std::vector<float> tiles;
    for (const Point& p : points)
        if (std::find(tiles.begin(), tiles.end(), p.tile) == tiles.end()) tiles.push_back(p.tile);
    std::sort(tiles.begin(), tiles.end());
    const auto px = tools::compactNumber;
    std::ostringstream md;
    md << "Each tier's default at each tile edge (px at 720 rows; a tile is never larger than the radius, so the current tier's 18 px "
          "tile is 14 px): training PSNR (held-out in brackets), dB, and the cost on "
       << backend << ", ms:\n\n| tier default |";
    for (float t : tiles) md << " " << px(t) << " px |";
    md << "\n| --- |";
    for (size_t i = 0; i < tiles.size(); ++i) md << " --- |";
    md << "\n";
    for (const tiers::TierRow& row : tiers::table()) {
        const TierProfile& d = tiers::profile(row.tier);  // the tier's default
        md << "| " << toString(row.tier) << ", " << d.mbTaps << " taps / " << px(d.mbMaxRadiusPx) << " px |";
        for (float t : tiles) {
            auto it = std::find_if(points.begin(), points.end(),
                                   [&](const Point& p) { return p.taps == d.mbTaps && p.radius == d.mbMaxRadiusPx && p.tile == t; });
            md << " "
               << (it == points.end() ? std::string("-")
                                      : tools::fixed(it->training, 2) + " (" + tools::fixed(it->heldOut, 2) + ")" +
                           (it->ms >= 0 ? ", " + tools::fixed(it->ms, 1) : std::string()))
               << " |";
        }
        md << "\n";
    }
    return md.str();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"fit_mb: motion blur's accuracy (training and held-out families) and cost per taps x maximum radius", "fit_mb"};
    std::vector<uint32_t> taps{3, 5, 7, 9, 11, 13, 15, 17};
    std::vector<float> radii{6, 8, 10, 12, 14, 18, 24};
    std::vector<float> tiles{5, 7, 10, 14, 18};
    uint32_t instants = 256, width = 960, height = 720, costWidth = 1280, costHeight = 720, runs = 7;
    std::vector<double> speeds;
    std::string backend = "vulkan", csvPath = "mb_fit.csv", docPath;
    app.add_option("--taps", taps, "tap counts (centre included, odd)")->delimiter(',')->capture_default_str();
    app.add_option("--radii", radii, "maximum radii, pixels at 720 rows")->delimiter(',')->capture_default_str();
    app.add_option("--tiles", tiles, "tile edges for each tier's default, pixels at 720 rows, [1, 64]")->delimiter(',')->capture_default_str();
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
    app.add_option("--doc", docPath, "write the grid and the presets on it into this page's section fit_mb");
    bool docOnly = false;
    app.add_flag("--doc-only", docOnly, "with --doc: write the section from --csv as it is, without running anything");
    CLI11_PARSE(app, argc, argv);
    for (float t : tiles)
        if (!(t >= 1.0f && t <= 64.0f)) {
            std::cerr << "fit_mb: --tiles " << t << " is outside [1, 64] px\n";
            return 1;
        }
    auto writeDoc = [&](const std::vector<Point>& points) -> int {
        for (const auto& [name, text] : {std::pair{"fit_mb", docSection(points, backend, width, height, costWidth, costHeight, instants)},
                                         {"fit_mb_tiles", tileSection(points, backend)}}) {
            if (Status st = tools::replaceMarkdownSection(docPath, name, text); !st) {
                std::cerr << "fit_mb: " << st.toString() << "\n";
                return 1;
            }
            std::cout << "wrote the section " << name << " of " << docPath << "\n";
        }
        return 0;
    };
    if (docOnly) {
        if (docPath.empty()) {
            std::cerr << "fit_mb: --doc-only needs --doc\n";
            return 1;
        }
        Result<std::vector<Point>> points = readPoints(csvPath);
        if (!points) {
            std::cerr << "fit_mb: " << points.status().toString() << "\n";
            return 1;
        }
        return writeDoc(points.value());
    }
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

    // One configuration measured and added: accuracy on both family sets, and the cost where a
    // backend times it; false (after saying why) when the backend could not run it.
    std::vector<Point> points;
    auto measure = [&](const TierProfile& profile) -> bool {
        Point pt{profile.mbTaps, profile.mbMaxRadiusPx, profile.mbTilePx, meanPsnr(training, profile), meanPsnr(heldOut, profile)};
        if (device) {
            Result<tools::MotionBlurRun> run = tools::runMotionBlur(*device, profile, {}, costFrame, cam, runs);
            if (!run) {
                std::cerr << "fit_mb: " << run.status().toString() << "\n";
                return false;
            }
            pt.ms = run->medianMs;
        }
        char line[192];
        std::snprintf(line, sizeof line, "%2u taps, radius %4.1f px, tile %4.1f px: training %.2f dB, held-out %.2f dB, %.2f ms", pt.taps, pt.radius,
                      pt.tile, pt.training, pt.heldOut, pt.ms);
        progress(line);
        points.push_back(pt);
        return true;
    };
    for (uint32_t t : taps)
        for (float r : radii) {
            TierProfile profile = base;
            profile.mbTaps = t, profile.mbMaxRadiusPx = r;
            if (resolveMotionBlur(profile, {}, height) && !measure(profile)) return 1;
        }
    // The tile edge at each tier's default (the grid above has the tiers' own tile).
    const size_t gridPoints = points.size();
    for (const tiers::TierRow& row : tiers::table()) {
        const TierProfile& d = tiers::profile(row.tier);
        for (float tile : tiles) {
            const bool measured = std::any_of(points.begin(), points.end(),
                                              [&](const Point& p) { return p.taps == d.mbTaps && p.radius == d.mbMaxRadiusPx && p.tile == tile; });
            if (measured) continue;
            TierProfile profile = base;
            profile.mbTaps = d.mbTaps, profile.mbMaxRadiusPx = d.mbMaxRadiusPx, profile.mbTilePx = tile;
            if (!measure(profile)) return 1;
        }
    }
    std::ofstream csv(csvPath);
    csv << "taps,max_radius_px,tile_px,training_psnr_moving,heldout_psnr_moving,ms,backend,cost_width,cost_height,front\n";
    std::printf("front (no configuration both more accurate on training and cheaper; the grid at the tiers' tile):\n");
    for (size_t i = 0; i < points.size(); ++i) {
        const Point& p = points[i];
        // The front is the grid's; a tile row is not on the grid ("-").
        const bool onGrid = i < gridPoints;
        const bool dominated = std::any_of(points.begin(), points.begin() + long(gridPoints), [&](const Point& q) {
            const bool cheaper = device ? q.ms <= p.ms : q.taps <= p.taps && q.radius <= p.radius;
            return &q != &p && q.training > p.training && cheaper;
        });
        csv << p.taps << "," << p.radius << "," << p.tile << "," << p.training << "," << p.heldOut << "," << p.ms << "," << backend << ","
            << costWidth << "," << costHeight << ","
            << (!onGrid         ? "-"
                    : dominated ? "0"
                                : "1")
            << "\n";
        if (onGrid && !dominated)
            std::printf("  %2u taps, radius %4.1f: training %.2f, held-out %.2f dB, %.2f ms\n", p.taps, p.radius, p.training, p.heldOut, p.ms);
    }
    csv.close();
    std::cout << "wrote " << csvPath << "\n";
    if (docPath.empty()) return 0;
    // From the CSV as written, so the section is what --doc-only gives from it.
    Result<std::vector<Point>> written = readPoints(csvPath);
    if (!written) {
        std::cerr << "fit_mb: " << written.status().toString() << "\n";
        return 1;
    }
    return writeDoc(written.value());
}
