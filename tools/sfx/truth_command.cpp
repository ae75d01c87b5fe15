// sfx truth: ray-traced AO ground truth (Embree) for a sample scene, as the effects' error is
// measured against (docs/trade.md). Writes visibility and a surface mask to --out.
#include <chrono>
#include <iostream>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sfx/truth_file.hpp"
#include "truth_scenes.hpp"

namespace sfx::cli {
namespace {

struct TruthFlags {
    std::string scene, outPath;
    uint32_t width = 320, height = 180, samples = 256, seed = 0, threads = 0;
    double radius = 0.5;
};

std::string sceneList() {
    std::string known;
    for (const std::string& n : tools::truthSceneNames()) known += (known.empty() ? "" : ", ") + n;
    return known;
}

int runTruth(const TruthFlags& f) {
    const std::string cmd = "truth";
    const std::string ext = io::extensionOf(f.outPath);
    if (ext != ".pfm" && ext != ".exr") return fail(cmd, invalidArgument("--out", "'" + f.outPath + "'", "a .pfm or .exr file"));
    if (f.width == 0 || f.height == 0 || f.width > 16384 || f.height > 16384)
        return fail(cmd, invalidArgument("--width/--height", std::to_string(f.width) + "x" + std::to_string(f.height), "1 to 16384 each"));
    truth::Settings s;
    s.radius = f.radius;
    s.samples = f.samples;
    s.seed = f.seed;
    s.threads = f.threads;
    if (Status st = truth::validate(s, "--radius", "--samples"); !st) return fail(cmd, st);
    Result<tools::TruthScene> scene = tools::makeTruthScene(f.scene, f.width, f.height);
    if (!scene) return fail(cmd, scene.status());
    const auto start = std::chrono::steady_clock::now();
    Result<std::unique_ptr<truth::Tracer>> tracer = truth::Tracer::create(scene->geometry);
    if (!tracer) return fail(cmd, tracer.status());
    Result<truth::Image> image = tracer.value()->trace(scene->camera, s);
    if (!image) return fail(cmd, image.status());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (Status st = truth::writeImageFile(f.outPath, image.value()); !st) return fail(cmd, st);
    io::Image preview(f.width, f.height, 1);
    for (size_t i = 0; i < preview.pixels.size(); ++i) preview.pixels[i] = image->visibility[i];
    Result<std::string> png = writePngBeside(f.outPath, preview);
    if (!png) return fail(cmd, png.status());
    std::cout << "sfx truth: " << f.scene << " " << f.width << "x" << f.height << ", radius " << f.radius << ", " << f.samples
              << " directions per pixel, seed " << f.seed << ": " << seconds << " s; mean standard-error bound "
              << truth::meanStdErrorBound(image.value()) << " -> " << f.outPath << " (visibility, surface mask) and " << png.value() << "\n";
    return 0;
}

}  // namespace

Command addTruthCommand(CLI::App& app) {
    auto flags = std::make_shared<TruthFlags>();
    Command c;
    c.app = app.add_subcommand("truth", "Ray-traced AO ground truth (Embree) of a sample scene: visibility in [0,1] and a surface mask");
    c.app->footer("Input values: reads no input files (the scene is one of the built-in ones), so no NaN can reach it.");
    c.app->add_option("--scene", flags->scene, "one of: " + sceneList())->required();
    c.app->add_option("--width", flags->width, "pixels, 1 to 16384")->capture_default_str();
    c.app->add_option("--height", flags->height, "pixels, 1 to 16384")->capture_default_str();
    c.app->add_option("--radius", flags->radius, "world-space AO radius, > 0")->capture_default_str();
    c.app->add_option("--samples", flags->samples, "cosine-weighted directions per pixel, a square >= 256")->capture_default_str();
    c.app->add_option("--seed", flags->seed, "selects the per-pixel stratified pattern (output is deterministic per seed)")->capture_default_str();
    c.app->add_option("--threads", flags->threads, "0 = all hardware threads (does not change the result)")->capture_default_str();
    c.app
        ->add_option("--out", flags->outPath,
                     "output .pfm or .exr: channel 0 visibility (1 on sky), channel 1 surface mask (a .png preview is written beside it)")
        ->required();
    c.run = [flags] { return runTruth(*flags); };
    return c;
}

}  // namespace sfx::cli
