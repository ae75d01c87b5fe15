// sfx render: draws a scene file (docs/scene_files.md) through the SDK on any backend and tier:
// opaque objects into the G-buffer, ambient obscurance, the composite, translucent objects through
// sfx::Transparency; writes the picture (.pfm/.exr linear RGB, .png sRGB) and optionally the AO
// buffer, the plan and the statistics (always the transparency counts when that step ran).
#include <iostream>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sfx/scene_render.hpp"
#include "sfx/settings_ranges.hpp"

namespace sfx::cli {
namespace {

struct RenderFlags {
    DeviceFlags device;
    std::string scenePath, outPath, aoOutPath;
    uint32_t width = 0, height = 0;
    std::string ao = "scalable";
    float aoRadius = 0.5f;
    uint32_t aoLayers = 1;
    std::string oit = "auto";
    uint32_t maxLayers = 16, nodes = 4;
    bool showPlan = false, showStats = false;
};

// Flags into options; every bad value is named before a file is read or a device opened.
Result<render::RenderOptions> parseOptions(const RenderFlags& f) {
    render::RenderOptions o;
    o.width = f.width;
    o.height = f.height;
    if (f.ao == "off") {
        o.ao.reset();
    } else {
        AoTechnique t;
        if (!parseAoTechnique(f.ao, &t)) return invalidArgument("--ao", "'" + f.ao + "'", "off, alchemy, scalable, crease or horizon");
        o.ao = t;
    }
    o.aoRadius = f.aoRadius;
    o.aoLayers = f.aoLayers;
    if (f.oit != "auto" && f.oit != "off") return invalidArgument("--oit", "'" + f.oit + "'", "auto or off");
    o.oit = f.oit == "auto";
    o.maxLayers = f.maxLayers;
    o.nodes = f.nodes;
    SFX_TRY(render::validateOptions(o));
    for (const auto& [flag, path] : {std::pair<const char*, const std::string*>{"--out", &f.outPath}, {"--ao-out", &f.aoOutPath}}) {
        if (path->empty()) continue;
        const std::string ext = io::extensionOf(*path);
        if (ext != ".pfm" && ext != ".exr" && ext != ".png")
            return invalidArgument(flag, "'" + *path + "'", "a .pfm, .exr (linear) or .png (sRGB) file");
    }
    if (!f.aoOutPath.empty() && !o.ao)
        return invalidArgument("--ao-out", "'" + f.aoOutPath + "' with --ao off", "--ao alchemy, scalable, crease or horizon");
    return o;
}

int runRender(const RenderFlags& f) {
    const std::string cmd = "render";
    Result<render::RenderOptions> options = parseOptions(f);
    if (!options) return fail(cmd, options.status());
    Result<scene::Scene> scene = scene::loadSceneFile(f.scenePath);
    if (!scene) return fail(cmd, scene.status());
    Result<OpenedDevice> opened = openDevice(f.device);
    if (!opened) return fail(cmd, opened.status());
    Device& dev = *opened->device;
    Result<std::unique_ptr<render::SceneRender>> renderer = render::SceneRender::create(dev, opened->tier, scene.value(), options.value());
    if (!renderer) return fail(cmd, renderer.status());
    if (f.showPlan) std::cout << "plan:\n" << renderer.value()->plan().describe();
    Result<render::RenderResult> result = renderer.value()->render();
    if (!result) return fail(cmd, result.status());
    if (Status st = render::writeRendered(f.outPath, result->color, "--out"); !st) return fail(cmd, st);
    if (!f.aoOutPath.empty())
        // Visibility is data, not a picture: stored as is in every format (PNG: 8 bits, linear).
        if (Status st = io::writeImage(f.aoOutPath, *result->ao); !st) return fail(cmd, st);
    for (const std::string& w : result->warnings) std::cerr << "sfx render: warning: " << w << "\n";
    std::cout << "sfx render: " << f.scenePath << " on " << dev.caps().summary() << ", tier " << toString(opened->tier.tier) << ", "
              << renderer.value()->width() << "x" << renderer.value()->height() << ", ao " << f.ao << " -> " << f.outPath
              << (f.aoOutPath.empty() ? "" : " and " + f.aoOutPath) << "\n";
    // The transparency counts (fragments, stored, dropped, pool) are printed whenever that step ran.
    if (f.showStats || result->stats.transparencyRan) std::cout << "stats:\n" << result->stats.describe();
    return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
    auto flags = std::make_shared<RenderFlags>();
    Command c;
    c.app = app.add_subcommand("render", "Render a scene file: opaque objects, ambient obscurance, composite, OIT");
    c.app->add_option("--scene", flags->scenePath, "scene file (JSON, docs/scene_files.md)")->required();
    c.app->add_option("--out", flags->outPath, "picture: .pfm or .exr (linear RGB) or .png (sRGB)")->required();
    flags->device.add(*c.app);
    c.app->add_option("--width", flags->width, "width in pixels; 0 = the scene's")->capture_default_str();
    c.app->add_option("--height", flags->height, "height in pixels; 0 = the scene's")->capture_default_str();
    c.app->add_option("--ao", flags->ao, "off | alchemy | scalable | crease | horizon")->capture_default_str();
    c.app->add_option("--ao-radius", flags->aoRadius, "AO " + settingHelp(Setting::AoRadius))->capture_default_str();
    c.app->add_option("--ao-out", flags->aoOutPath, "also write the AO visibility buffer (.pfm, .exr or .png; values as they are, no sRGB)");
    c.app->add_option("--ao-layers", flags->aoLayers, settingHelp(Setting::AoDepthLayers) + "; above 1 by depth peeling")->capture_default_str();
    c.app->add_option("--oit", flags->oit, "auto (transparent objects through OIT) | off (not drawn)")->capture_default_str();
    c.app->add_option("--max-layers", flags->maxLayers, "K: transparent fragments the A-buffer resolve keeps exact per pixel, 16 or 32")
        ->capture_default_str();
    c.app->add_option("--nodes", flags->nodes, settingHelp(Setting::OitCompressedNodes) + "; at least 1 here (AO through transparency)")
        ->capture_default_str();
    c.app->add_flag("--plan", flags->showPlan, "print the passes, resources and bytes, and why each is there");
    c.app->add_flag("--stats", flags->showStats, "print objects, triangles, transparent fragments, stored, dropped, pool nodes and bytes");
    c.run = [flags] { return runRender(*flags); };
    return c;
}

}  // namespace sfx::cli
