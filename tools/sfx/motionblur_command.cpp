// sfx motionblur: motion blur reconstruction on colour, depth and velocity files.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <optional>

#include "cli_common.hpp"
#include "commands.hpp"
#include "pass_profile.hpp"
#include "sfx/half.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/settings_ranges.hpp"

namespace sfx::cli {
namespace {

const char* kVelocityHelp =
    "velocity file in pixels: EXR with two channels (x, y; more are ignored) or PFM with three (the third "
    "ignored).\n"
    "x points toward the right edge of the picture, y toward the BOTTOM of the picture (the file's row "
    "order as its format defines it, row 0 = top). A velocity is the displacement across the shutter "
    "interval (exposure 1), for a frame rendered at mid-shutter: the blur reaches half of it either side.";

struct MotionBlurFlags {
    DeviceFlags device;
    CameraFlags camera;
    std::string colorPath, velocityPath, outPath;
    std::optional<float> maxRadius;  // unset: the tier's
    uint32_t referenceRows = 720;
    std::optional<uint32_t> samples;  // unset: the tier's
    float softDepth = 0.1f;
    float centreWeight = 1.0f;
    float exposure = 1.0f;
    uint32_t runs = 0;  // > 0: time the dispatch, median of runs after a warm-up
};

// Colour may travel as 16-bit floats (RGBA16F where RGBA32F is not renderable): finite colour
// is held at +-65504 here, the colour rule the effect applies on any format (sfx_shared.h), so
// both paths give the same picture instead of a half-float infinity.
constexpr float kLargestHalf = 65504.0f;

// "10 current, 18 high": one default-preset value per tier of the table, for help texts.
std::string perTier(std::string (*value)(const TierProfile&)) {
    std::string s;
    for (const tiers::TierRow& r : tiers::table()) s += (s.empty() ? "" : ", ") + value(r.presets.front().params) + " " + toString(r.tier);
    return s;
}

// The flags' ranges (the settings table's rows), named as flags, before any file is read.
Status checkFlags(const MotionBlurFlags& f) {
    if (f.maxRadius) SFX_TRY(checkSetting(Setting::MbMaxRadiusPx, *f.maxRadius, "--max-radius"));
    SFX_TRY(checkSetting(Setting::MbReferenceRows, f.referenceRows, "--reference-rows"));
    if (f.samples) SFX_TRY(checkSetting(Setting::MbSamples, *f.samples, "--samples"));
    SFX_TRY(checkSetting(Setting::MbSoftDepthExtent, f.softDepth, "--soft-depth"));
    SFX_TRY(checkSetting(Setting::MbCentreWeight, f.centreWeight, "--centre-weight"));
    if (f.runs > tools::kMaxTimedRuns)
        return invalidArgument("--runs", std::to_string(f.runs), "0 (not timed) to " + std::to_string(tools::kMaxTimedRuns));
    return checkSetting(Setting::MbExposure, f.exposure, "--exposure");
}

Status run(const MotionBlurFlags& f) {
    SFX_TRY(checkFlags(f));
    const std::string outExt = io::extensionOf(f.outPath);
    if (outExt != ".png" && outExt != ".pfm" && outExt != ".exr")
        return invalidArgument("--out", "'" + f.outPath + "'", "a .png, .pfm or .exr file name");
    const std::string velExt = io::extensionOf(f.velocityPath);
    if (velExt != ".exr" && velExt != ".pfm")
        return invalidArgument("--velocity", "'" + f.velocityPath + "'", "an .exr or .pfm file (signed pixels)");

    // Every file is read and checked before a device is opened: a malformed input is reported
    // as such, naming the file, on any machine.
    Result<LoadedDepth> depth = readDepth(f.camera);
    if (!depth) return depth.status();
    const uint32_t w = depth->image.width, h = depth->image.height;

    Result<io::Image> color = loadMatching(f.colorPath, w, h, "--color");
    if (!color) return color.status();
    SFX_TRY(refuseNaN(color.value(), color->channels, "--color", f.colorPath));
    Result<io::Image> velocity = loadMatching(f.velocityPath, w, h, "--velocity");
    if (!velocity) return velocity.status();
    const uint32_t needed = velExt == ".pfm" ? 3u : 2u;
    if (velocity->channels < needed)
        return {StatusCode::InvalidArgument,
                "--velocity " + f.velocityPath + " has " + std::to_string(velocity->channels) + " channel(s); a velocity " + velExt.substr(1) +
                    " needs " + std::to_string(needed) + (velExt == ".pfm" ? " (x, y, ignored)" : " (x, y)")};
    // Any velocity but NaN: the effect clamps infinite and huge ones to the radius (sfx_shared_mb.h).
    SFX_TRY(refuseNaN(velocity.value(), 2, "--velocity", f.velocityPath));

    Result<OpenedDevice> opened = openDevice(f.device);
    if (!opened) return opened.status();
    Device& device = *opened->device;
    const TierProfile& profile = opened->tier.profile;
    SFX_TRY(uploadDepth(device, depth.value()));

    // RGBA32F when the device renders it (exact), else RGBA16F (ES 3.0 with EXT_color_buffer_half_float).
    const bool full = device.caps().renderableFormat[size_t(Format::RGBA32F)];
    const Format colorFormat = full ? Format::RGBA32F : Format::RGBA16F;
    std::vector<float> rgba(size_t(w) * h * 4);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            float* px = &rgba[(size_t(y) * w + x) * 4];
            const uint32_t ch = color->channels;
            for (uint32_t c = 0; c < 3; ++c) px[c] = color->at(x, y, ch >= 3 ? c : 0);
            px[3] = ch == 4 || ch == 2 ? color->at(x, y, ch - 1) : 1.0f;
            for (uint32_t c = 0; c < 4; ++c)
                if (std::isfinite(px[c])) px[c] = std::clamp(px[c], -kLargestHalf, kLargestHalf);
        }
    Result<TextureHandle> colorTex = device.createTexture({w, h, 1, colorFormat, kTextureSampled, "sfx-cli-color"});
    if (!colorTex) return colorTex.status();
    if (full) {
        SFX_TRY(device.writeTexture(colorTex.value(), 0, rgba.data(), rgba.size() * 4));
    } else {
        std::vector<uint16_t> halves(rgba.size());
        for (size_t i = 0; i < rgba.size(); ++i) halves[i] = floatToHalf(rgba[i]);
        SFX_TRY(device.writeTexture(colorTex.value(), 0, halves.data(), halves.size() * 2));
    }
    std::vector<float> vel(size_t(w) * h * 2);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            // Files and textures both put row 0 at the top: y toward the bottom = increasing row.
            vel[(size_t(y) * w + x) * 2 + 0] = velocity->at(x, y, 0);
            vel[(size_t(y) * w + x) * 2 + 1] = velocity->at(x, y, 1);
        }
    Result<TextureHandle> velTex = device.createTexture({w, h, 1, Format::RG32F, kTextureSampled, "sfx-cli-velocity"});
    if (!velTex) return velTex.status();
    SFX_TRY(device.writeTexture(velTex.value(), 0, vel.data(), vel.size() * 4));

    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(device, {w, h, profile, colorFormat, depth->source.kind});
    if (!mb) return mb.status();
    MotionBlurSettings s;
    s.maxRadiusPx = f.maxRadius;
    s.referenceRows = f.referenceRows;
    s.samples = f.samples;
    s.softDepthExtent = f.softDepth;
    s.centreWeight = f.centreWeight;
    s.exposure = f.exposure;
    MotionBlurInputs inputs;
    inputs.color = colorTex.value();
    inputs.depth = depth->source;
    inputs.velocity = velTex.value();
    SFX_TRY(mb.value()->dispatch(inputs, s));
    SFX_TRY(device.flush());
    std::optional<tools::DispatchCost> cost;
    if (f.runs > 0) {
        // The timed dispatches write the same output again: profiling changes no pixel (conformance).
        Result<tools::DispatchCost> c = tools::profilePasses(
            device, *mb.value(), [&] { return mb.value()->dispatch(inputs, s); }, f.runs);
        if (!c) return c.status();
        cost = c.value();
    }

    io::Image out(w, h, 4);
    if (full) {
        SFX_TRY(device.readTexture(mb.value()->output(), 0, out.pixels.data(), out.pixels.size() * 4));
    } else {
        std::vector<uint16_t> halves(out.pixels.size());
        SFX_TRY(device.readTexture(mb.value()->output(), 0, halves.data(), halves.size() * 2));
        for (size_t i = 0; i < halves.size(); ++i) out.pixels[i] = halfToFloat(halves[i]);
    }
    // Keep the input's channel layout: grey stays grey, RGB stays RGB.
    io::Image written(w, h, color->channels);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const uint32_t ch = color->channels;
            if (ch >= 3)
                for (uint32_t c = 0; c < ch; ++c) written.at(x, y, c) = out.at(x, y, c);
            else {
                written.at(x, y, 0) = out.at(x, y, 0);
                if (ch == 2) written.at(x, y, 1) = out.at(x, y, 3);
            }
        }
    SFX_TRY(io::writeImage(f.outPath, written));
    const MotionBlurParams p = resolveMotionBlur(profile, s, h).value();
    std::cout << "sfx motionblur: " << toString(opened->config) << " " << toString(profile.tier) << " tier, " << p.taps << " taps, radius "
              << p.radiusPx << " px, " << w << "x" << h << " -> " << f.outPath << "\n";
    std::cout.flush();
    if (cost) tools::printCost(*cost);
    (void)device.destroyTexture(colorTex.value());
    (void)device.destroyTexture(velTex.value());
    (void)device.destroyTexture(depth->source.texture);
    return Status::ok();
}

}  // namespace

Command addMotionBlurCommand(CLI::App& app) {
    auto flags = std::make_shared<MotionBlurFlags>();
    Command c;
    c.app = app.add_subcommand("motionblur", "Motion blur reconstruction on colour, depth and velocity files");
    CLI::App* sub = c.app;
    sub->footer(kInputValuesHelp);
    sub->add_option("--color", flags->colorPath, "colour file (PNG, PFM or EXR; grey, RGB or RGBA)")->required();
    flags->camera.add(*sub);
    sub->add_option("--velocity", flags->velocityPath, kVelocityHelp)->required();
    sub->add_option("--out", flags->outPath, "output file (.png, .pfm or .exr), the colour's channel layout")->required();
    flags->device.add(*sub);
    sub->add_option("--max-radius", flags->maxRadius,
                    settingHelp(Setting::MbMaxRadiusPx) + "; not given: the tier's (" +
                        perTier([](const TierProfile& p) { return std::to_string(int(p.mbMaxRadiusPx)); }) + ")");
    sub->add_option("--reference-rows", flags->referenceRows, settingHelp(Setting::MbReferenceRows))->capture_default_str();
    sub->add_option(
        "--samples", flags->samples,
        settingHelp(Setting::MbSamples) + "; not given: the tier's (" + perTier([](const TierProfile& p) { return std::to_string(p.mbTaps); }) + ")");
    sub->add_option("--soft-depth", flags->softDepth, settingHelp(Setting::MbSoftDepthExtent))->capture_default_str();
    sub->add_option("--centre-weight", flags->centreWeight, settingHelp(Setting::MbCentreWeight))->capture_default_str();
    sub->add_option("--exposure", flags->exposure, settingHelp(Setting::MbExposure))->capture_default_str();
    sub->add_option("--runs", flags->runs, tools::kTimedRunsHelp);
    c.run = [flags] {
        Status s = run(*flags);
        return s.isOk() ? 0 : fail("motionblur", s);
    };
    return c;
}

}  // namespace sfx::cli
