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
#include "sfx/backends.hpp"
#include "sfx/depth.hpp"
#include "sfx/image_io.hpp"
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

// Half floats back to float, for the RGBA16F normal buffer.
float halfToFloat(uint16_t h) {
    const uint32_t sign = (h >> 15) & 1, exponent = (h >> 10) & 31, mantissa = h & 1023;
    float v;
    if (exponent == 0) v = std::ldexp(float(mantissa), -24);
    else if (exponent == 31) v = mantissa ? NAN : INFINITY;
    else v = std::ldexp(float(mantissa | 1024), int(exponent) - 25);
    return sign ? -v : v;
}

Result<io::Image> readNormals(Device& device, TextureHandle texture, uint32_t w, uint32_t h) {
    std::vector<uint16_t> halves(size_t(w) * h * 4);
    SFX_TRY(device.readTexture(texture, 0, halves.data(), halves.size() * 2));
    io::Image image(w, h, 3);
    for (size_t i = 0; i < size_t(w) * h; ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i * 3 + c] = halfToFloat(halves[i * 4 + c]) * 0.5f + 0.5f;
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

int fail(const Status& s) {
    std::cerr << "demo: error: " << s.toString() << "\n";
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"ScalableFX demo: renders the sample scenes through the SDK on the best device and writes PNGs"};
    std::string outDir = "out/demo", backendName = "auto", tierName = "auto";
    uint32_t width = 640, height = 360;
    std::vector<std::string> scenes = samples::sceneNames();
    app.add_option("--out", outDir, "output folder")->capture_default_str();
    app.add_option("--backend", backendName, "auto | vulkan | gles | gl-egl | gl-osmesa")->capture_default_str();
    app.add_option("--tier", tierName, "auto | current | high")->capture_default_str();
    app.add_option("--width", width, "width in pixels")->capture_default_str();
    app.add_option("--height", height, "height in pixels")->capture_default_str();
    app.add_option("--scenes", scenes, "scenes to render")->capture_default_str();
    CLI11_PARSE(app, argc, argv);

    std::optional<Tier> forcedTier;
    if (tierName != "auto") {
        Tier t;
        if (!parseTier(tierName, &t)) return fail(invalidArgument("--tier", tierName, "auto, current or high"));
        forcedTier = t;
    }
    DeviceOptions options;
    options.validation = false;
    options.ceiling = forcedTier == Tier::Current ? CapabilityCeiling::GLES30 : CapabilityCeiling::None;

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
    Result<std::unique_ptr<samples::SceneRenderer>> renderer = samples::SceneRenderer::create(*device, tier->tier);
    if (!renderer) return fail(renderer.status());

    // 2. Only what the scene needs: the depth pyramid exists only on the high tier, where the
    //    scalable AO reads it.
    LinearDepthDesc ld{width, height, tier->tier, tier->profile.aoUsesDepthMip ? tier->profile.aoDepthMipLevels : 1u};
    Result<std::unique_ptr<LinearDepth>> linear = LinearDepth::create(*device, ld);
    if (!linear) return fail(linear.status());
    std::cout << "plan:\n" << linear.value()->plan().describe();

    Result<TimerHandle> timer = device->createTimer();
    if (!timer) return fail(timer.status());

    for (const std::string& name : scenes) {
        Result<samples::Scene> scene = samples::makeScene(name);
        if (!scene) return fail(scene.status());
        if (Status s = renderer.value()->load(scene.value()); !s) return fail(s);
        std::cout << "[" << name << "] rendering " << width << "x" << height << "\n";
        Result<samples::GBuffer> g = renderer.value()->render(scene.value(), width, height);
        if (!g) return fail(g.status());
        if (Status s = device->beginTimer(timer.value()); !s) return fail(s);
        if (Status s = linear.value()->dispatch({g->depth, DepthKind::Hardware, g->camera}); !s) return fail(s);
        if (Status s = device->endTimer(timer.value()); !s) return fail(s);
        if (Status s = device->flush(); !s) return fail(s);
        Result<TimerReading> t = device->readTimer(timer.value());
        if (!t) return fail(t.status());
        std::cout << "[" << name << "] depth passes: " << t->milliseconds << " ms (" << toString(t->source) << ")\n";

        Result<io::Image> normals = readNormals(*device, g->normals, width, height);
        if (!normals) return fail(normals.status());
        const std::string base = outDir + "/" + name;
        if (Status s = io::writePng(base + "_normals.png", normals.value()); !s) return fail(s);
        for (uint32_t level = 0; level < ld.mipLevels; ++level) {
            Result<io::Image> depth = readR32F(*device, linear.value()->texture(), level);
            if (!depth) return fail(depth.status());
            const std::string file = base + "_linear_depth_mip" + std::to_string(level) + ".png";
            if (Status s = io::writePng(file, depthPicture(depth.value())); !s) return fail(s);
        }
        std::cout << "[" << name << "] wrote " << base << "_normals.png and " << ld.mipLevels << " linear depth level(s)\n";
        renderer.value()->destroy(g.value());
    }
    (void)device->destroyTimer(timer.value());
    std::cout << "done: " << outDir << "\n";
    return 0;
}
