// The ScalableFX demo: picks the best backend and tier by the capability query, says what it
// chose and why, renders the sample scenes through the HAL, and writes what the effects see
// and produce as PNG files, with a short report of the plan and the cost.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "scene.hpp"
#include "sfx/ao.hpp"
#include "sfx/backends.hpp"
#include "sfx/budget.hpp"
#include "sfx/depth.hpp"
#include "sfx/image_io.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/scene_render.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared.h"

using namespace sfx;
namespace fs = std::filesystem;

namespace {

Result<io::Image> readR32F(Device& device, TextureHandle texture, uint32_t mip) {
    Result<TextureDesc> desc = device.textureDesc(texture);
    if (!desc) return desc.status();
    io::Image image(mipExtent(desc->width, mip), mipExtent(desc->height, mip), 1);
    SFX_TRY(device.readTexture(texture, mip, image.pixels.data(), image.pixels.size() * sizeof(float)));
    return image;
}

// View-space normals as a picture: n * 0.5 + 0.5.
io::Image normalsPicture(const tools::GBufferContents& g) {
    io::Image image(g.width, g.height, 3);
    for (size_t i = 0; i < g.normals.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i * 3 + c] = g.normals[i][c] * 0.5f + 0.5f;
    return image;
}

// Depth as a picture: near = white, far = black, sky = black, on a log scale so both the
// foreground and the background keep detail.
io::Image depthPicture(const io::Image& depth) {
    float lo = 1e30f, hi = 0.0f;
    for (float z : depth.pixels)
        if (z < shared::SFX_SKY_DEPTH * 0.5f) lo = std::min(lo, z), hi = std::max(hi, z);
    io::Image out(depth.width, depth.height, 1);
    const float llo = std::log(std::max(lo, 1e-6f)), lhi = std::log(std::max(hi, lo * 1.0001f));
    for (size_t i = 0; i < depth.pixels.size(); ++i) {
        const float z = depth.pixels[i];
        out.pixels[i] = z >= shared::SFX_SKY_DEPTH * 0.5f ? 0.0f : 1.0f - (std::log(z) - llo) / (lhi - llo + 1e-12f);
    }
    return out;
}

Result<std::vector<uint8_t>> readRGBA8(Device& device, TextureHandle texture, uint32_t w, uint32_t h) {
    std::vector<uint8_t> bytes(size_t(w) * h * 4);
    SFX_TRY(device.readTexture(texture, 0, bytes.data(), bytes.size()));
    return bytes;
}

// A lit composite on the CPU: albedo * (ambient * visibility + key light * n.l), the key light
// from the upper left, in view space.
io::Image composite(const tools::GBufferContents& g, const std::vector<uint8_t>* visibility) {
    io::Image out(g.width, g.height, 3);
    const glm::vec3 light(-0.45f, 0.75f, 0.48f);
    for (size_t i = 0; i < g.normals.size(); ++i) {
        if (!g.drawn(i)) {  // a sky colour
            out.pixels[i * 3 + 0] = 0.62f, out.pixels[i * 3 + 1] = 0.7f, out.pixels[i * 3 + 2] = 0.8f;
            continue;
        }
        const float direct = std::max(0.0f, glm::dot(g.normals[i], light));
        const float ao = visibility ? (*visibility)[i * 4] / 255.0f : 1.0f;
        for (int c = 0; c < 3; ++c) out.pixels[i * 3 + c] = g.albedo[i * 4 + c] / 255.0f * (0.55f * ao + 0.6f * direct);
    }
    return out;
}

// The composite as RGBA8 bytes, the colour input of motion blur.
std::vector<uint8_t> toRGBA8(const io::Image& rgb) {
    std::vector<uint8_t> bytes(size_t(rgb.width) * rgb.height * 4, 255);
    for (size_t i = 0; i < size_t(rgb.width) * rgb.height; ++i)
        for (int c = 0; c < 3; ++c) bytes[i * 4 + c] = uint8_t(std::lround(std::clamp(rgb.pixels[i * 3 + c], 0.0f, 1.0f) * 255.0f));
    return bytes;
}

io::Image fromRGBA8(const std::vector<uint8_t>& bytes, uint32_t w, uint32_t h) {
    io::Image out(w, h, 3);
    for (size_t i = 0; i < size_t(w) * h; ++i)
        for (int c = 0; c < 3; ++c) out.pixels[i * 3 + c] = bytes[i * 4 + c] / 255.0f;
    return out;
}

// Each cost is budget::timeMedian over kTimedRuns after one warm-up run (drivers compile
// pipelines on first use): one run is noise on a busy machine; the benchmarks go further.
constexpr uint32_t kTimedRuns = 5;

int fail(const Status& s) {
    std::cerr << "demo: error: " << s.toString() << "\n";
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"ScalableFX demo: renders the sample scenes through the SDK on the best device and writes PNGs"};
    std::string outDir = "out/demo", backendName = "auto", tierName = "auto";
    uint32_t width = 640, height = 360;
    std::vector<std::string> scenes = tools::sceneNames();
    app.add_option("--out", outDir, "output folder")->capture_default_str();
    app.add_option("--backend", backendName, "auto | vulkan | gles | gl-egl | gl-osmesa")->capture_default_str();
    app.add_option("--tier", tierName, "auto or a tier: " + tierNameList())->capture_default_str();
    app.add_option("--width", width, "width in pixels")->capture_default_str();
    app.add_option("--height", height, "height in pixels")->capture_default_str();
    app.add_option("--scenes", scenes, "scenes to render")->capture_default_str();
    std::string sceneFile = SFX_SCENE_FILES_DIR "/panes.json";
    app.add_option("--scene-file", sceneFile, "a scene file drawn through the scene renderer (sfx render); '' = none")->capture_default_str();
    CLI11_PARSE(app, argc, argv);

    std::optional<Tier> forcedTier;
    if (tierName != "auto") {
        Tier t;
        if (!parseTier(tierName, &t)) return fail(invalidArgument("--tier", tierName, "auto or " + tierNameList()));
        forcedTier = t;
    }
    DeviceOptions options;
    options.validation = false;
    options.ceiling = forcedTier ? tiers::row(*forcedTier).ceiling : CapabilityCeiling::None;

    // 1. The device: best by capability score, or the one asked for.
    std::unique_ptr<Device> device;
    BackendConfig config;
    if (backendName == "auto") {
        Result<DeviceSelection> selection = openBestDevice(options);
        if (!selection) return fail(selection.status());
        std::cout << "chose " << selection->reason << "\n";
        for (const auto& r : selection->rejected) std::cout << "  not chosen: " << r << "\n";
        device = std::move(selection->device);
        config = selection->config;
    } else {
        if (!parseBackendConfig(backendName, &config))
            return fail(invalidArgument("--backend", backendName, "auto, vulkan, gles, gl-egl, gl-osmesa"));
        Result<std::unique_ptr<Device>> opened = openDevice(config, options);
        if (!opened) return fail(opened.status());
        device = std::move(opened.value());
        std::cout << "using " << toString(config) << " as asked: " << device->caps().summary() << "\n";
    }
    Result<tiers::TierChoice> tier = tiers::choose(device->caps(), forcedTier);
    if (!tier) return fail(tier.status());
    std::cout << "tier: " << tier->reason << "\n";

    fs::create_directories(outDir);
    Result<std::unique_ptr<tools::SceneRenderer>> renderer = tools::SceneRenderer::create(*device, tier->tier);
    if (!renderer) return fail(renderer.status());

    // 2. Ambient obscurance, every technique, at the tier's defaults. Each context owns only
    //    what it needs: the depth MIP pyramid exists only for the high tier's scalable AO.
    const AoTechnique techniques[] = {AoTechnique::Scalable, AoTechnique::Alchemy, AoTechnique::Crease, AoTechnique::Horizon};
    std::vector<std::unique_ptr<AmbientObscurance>> contexts;
    EffectPlan plan;
    for (AoTechnique technique : techniques) {
        AoDesc desc;
        desc.width = width;
        desc.height = height;
        desc.profile = tier->profile;
        desc.settings.technique = technique;
        desc.settings.normals = AoNormals::FromTexture;
        desc.settings.radius = 0.6f;
        // The papers' nominal intensity (sigma = 1) makes scalable AO (a squared sum) and crease
        // shading (a sum over 10) faint on these scenes; the demo turns them up so the effect shows.
        desc.settings.intensity = technique == AoTechnique::Scalable ? 3.0f : technique == AoTechnique::Crease ? 3.0f : 1.0f;
        std::cout << "ao " << toString(technique) << ": radius " << desc.settings.radius << ", intensity " << *desc.settings.intensity << "\n";
        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(*device, desc);
        if (!ao) return fail(ao.status());
        plan.append(ao.value()->plan());
        contexts.push_back(std::move(ao.value()));
    }
    std::cout << "plan (three AO contexts, each with its own linear depth):\n" << plan.describe();
    Result<TextureHandle> aoTarget = device->createTexture({width, height, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget, "demo-ao"});
    if (!aoTarget) return fail(aoTarget.status());

    for (const std::string& name : scenes) {
        Result<tools::RasterScene> scene = tools::makeScene(name);
        if (!scene) return fail(scene.status());
        if (Status s = renderer.value()->load(scene.value()); !s) return fail(s);
        std::cout << "[" << name << "] rendering " << width << "x" << height << "\n";
        Result<tools::GBuffer> g = renderer.value()->render(scene.value(), width, height);
        if (!g) return fail(g.status());
        const std::string base = outDir + "/" + name;
        Result<tools::GBufferContents> contents = tools::readBack(*device, g.value());
        if (!contents) return fail(contents.status());
        if (Status s = io::writePng(base + "_normals.png", normalsPicture(contents.value())); !s) return fail(s);
        if (Status s = io::writePng(base + "_lit_no_ao.png", composite(contents.value(), nullptr)); !s) return fail(s);

        for (size_t t = 0; t < contexts.size(); ++t) {
            AmbientObscurance& ao = *contexts[t];
            const std::string technique = toString(techniques[t]);
            Result<TimerReading> cost = budget::timeMedian(*device, kTimedRuns, [&] {
                return ao.dispatch({{g->depth, DepthKind::Hardware, g->camera}, g->normals, aoTarget.value()});
            });
            if (!cost) return fail(cost.status());
            Result<std::vector<uint8_t>> visibility = readRGBA8(*device, aoTarget.value(), width, height);
            if (!visibility) return fail(visibility.status());
            io::Image aoImage(width, height, 1);
            for (size_t i = 0; i < aoImage.pixels.size(); ++i) aoImage.pixels[i] = visibility.value()[i * 4] / 255.0f;
            if (Status s = io::writePng(base + "_ao_" + technique + ".png", aoImage); !s) return fail(s);
            if (Status s = io::writePng(base + "_lit_" + technique + ".png", composite(contents.value(), &visibility.value())); !s) return fail(s);
            std::cout << "[" << name << "] ao " << technique << ": " << cost->milliseconds << " ms (" << toString(cost->source) << ", median of "
                      << kTimedRuns << " after a warm-up), " << ao.plan().passes.size() << " passes\n";
        }
        // The linear depth the scalable context computed, and its pyramid where the tier has one.
        const LinearDepth& linear = contexts[0]->linearDepth();
        for (uint32_t level = 0; level < linear.desc().mipLevels; ++level) {
            Result<io::Image> depth = readR32F(*device, linear.texture(), level);
            if (!depth) return fail(depth.status());
            if (Status s = io::writePng(base + "_linear_depth_mip" + std::to_string(level) + ".png", depthPicture(depth.value())); !s) return fail(s);
        }
        std::cout << "[" << name << "] wrote " << base << "_{normals,ao_*,lit_*,linear_depth_mip*}.png\n";
        renderer.value()->destroy(g.value());
    }
    (void)device->destroyTexture(aoTarget.value());

    // 3. Motion blur on the chosen tier: objects moving over a still floor (the renderer's
    //    velocity buffer), and a panning camera (camera-only velocity from depth).
    struct MotionCase {
        const char* label;
        const char* scene;
        bool cameraOnly;
    };
    const MotionCase motionCases[] = {{"moving_objects", "contact", false}, {"moving_camera", "columns", true}};
    Result<std::unique_ptr<MotionBlur>> blur = MotionBlur::create(*device, {width, height, tier->profile, Format::RGBA8});
    if (!blur) return fail(blur.status());
    std::cout << "motion blur plan:\n" << blur.value()->plan().describe();
    Result<TextureHandle> colour = device->createTexture({width, height, 1, Format::RGBA8, kTextureSampled, "demo-motion-colour"});
    if (!colour) return fail(colour.status());
    for (const MotionCase& mc : motionCases) {
        Result<tools::RasterScene> scene = tools::makeScene(mc.scene);
        if (!scene) return fail(scene.status());
        if (mc.cameraOnly) {
            scene->eyeVelocity = {0.25, 0.0, 0.0};  // world units per shutter interval
        } else {
            const glm::dvec3 velocities[] = {{0, 0, 0}, {0.3, 0, 0}, {-0.25, 0, 0.1}, {0, 0.2, 0}};
            for (size_t m = 0; m < scene->meshes.size() && m < std::size(velocities); ++m)
                scene->meshes[m].velocity = velocities[m];  // mesh 0 is the floor: still
        }
        if (Status s = renderer.value()->load(scene.value()); !s) return fail(s);
        Result<tools::GBuffer> g = renderer.value()->render(scene.value(), width, height, 0.0);
        if (!g) return fail(g.status());
        Result<tools::GBufferContents> contents = tools::readBack(*device, g.value());
        if (!contents) return fail(contents.status());
        const io::Image sharp = composite(contents.value(), nullptr);
        const std::vector<uint8_t> sharpBytes = toRGBA8(sharp);
        if (Status s = device->writeTexture(colour.value(), 0, sharpBytes.data(), sharpBytes.size()); !s) return fail(s);

        MotionBlurInputs in;
        in.color = colour.value();
        in.depth = {g->depth, DepthKind::Hardware, g->camera};
        if (mc.cameraOnly) {
            // Camera-only velocity: where each pixel's surface was one shutter interval earlier.
            in.camera.previousViewProjection = g->camera.projection * scene->view(-1.0);
            in.camera.currentViewProjection = g->camera.projection * scene->view(0.0);
        } else {
            in.velocity = g->velocity;
        }
        Result<TimerReading> cost = budget::timeMedian(*device, kTimedRuns, [&] { return blur.value()->dispatch(in); });
        if (!cost) return fail(cost.status());
        Result<std::vector<uint8_t>> blurred = readRGBA8(*device, blur.value()->output(), width, height);
        if (!blurred) return fail(blurred.status());
        const std::string base = outDir + "/motion_" + mc.label;
        if (Status s = io::writePng(base + "_before.png", sharp); !s) return fail(s);
        if (Status s = io::writePng(base + "_after.png", fromRGBA8(blurred.value(), width, height)); !s) return fail(s);
        std::cout << "[" << mc.label << "] motion blur (" << (mc.cameraOnly ? "camera-only velocity" : "velocity buffer")
                  << "): " << cost->milliseconds << " ms (" << toString(cost->source) << ", median of " << kTimedRuns << " after a warm-up); wrote "
                  << base << "_{before,after}.png\n";
        renderer.value()->destroy(g.value());
    }
    (void)device->destroyTexture(colour.value());

    // 4. A scene file through the scene renderer, as `sfx render` draws it: its plan (what the
    //    scene needs and nothing more), AO on the opaque objects, the translucent ones through
    //    sfx::Transparency on the chosen tier (A-buffer or weighted blended), and the picture.
    if (!sceneFile.empty()) {
        Result<scene::Scene> file = scene::loadSceneFile(sceneFile);
        if (!file) return fail(file.status());
        render::RenderOptions ro;
        ro.width = width;
        ro.height = height;
        Result<std::unique_ptr<render::SceneRender>> sr = render::SceneRender::create(*device, tier.value(), file.value(), ro);
        if (!sr) return fail(sr.status());
        std::cout << "[" << sceneFile << "] scene renderer plan:\n" << sr.value()->plan().describe();
        Result<render::RenderResult> picture = sr.value()->render();
        if (!picture) return fail(picture.status());
        for (const std::string& w : picture->warnings) std::cout << "[" << sceneFile << "] warning: " << w << "\n";
        std::cout << "[" << sceneFile << "] " << picture->stats.describe();
        const std::string path = outDir + "/scene_" + fs::path(sceneFile).stem().string() + ".png";
        if (Status s = render::writeRendered(path, picture->color, "--scene-file output"); !s) return fail(s);
        std::cout << "[" << sceneFile << "] wrote " << path << "\n";
    }
    std::cout << "done: " << outDir << "\n";
    return 0;
}
