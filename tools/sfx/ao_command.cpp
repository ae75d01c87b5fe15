// sfx ao: ambient obscurance on G-buffer files, with any technique, tier and backend.
// Writes visibility in [0, 1] (1 = unoccluded) to --out (.pfm or .exr) and a PNG beside it, and
// with --bent-normals the horizon technique's bent normals (signed view-space xyz);
// --preset picks one of the tier's presets, --runs prices the dispatch.
#include <iostream>
#include <optional>

#include "bench_device.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "pass_profile.hpp"
#include "sfx/ao.hpp"
#include "sfx/settings_ranges.hpp"

namespace sfx::cli {
namespace {

struct AoFlags {
    DeviceFlags device;
    CameraFlags camera;
    std::string technique;  // empty: the preset's
    std::string resolution = "tier";
    std::string normalsPath;
    std::string outPath;
    std::string bentPath;                 // not empty: AoSettings.bentNormals, written there
    std::string preset = kDefaultPreset;  // one of the tier's presets (sfx info --rules)
    uint32_t runs = 0;                    // > 0: time the dispatch, median of runs after a warm-up
    float radius = 0.5f;
    float metresPerUnit = 1.0f;
    std::optional<float> intensity, contrast, bias, sumExponent, radiusExponent;  // unset: the tier's calibrated look
    std::optional<uint32_t> samples, blurRadius;                                  // unset: the tier's
    std::optional<uint32_t> slices, steps;                                        // horizon; unset: the tier's
    std::optional<float> thickness, falloff;                                      // horizon; unset: the tier's
    bool noBlur = false;
    bool showPlan = false;
};

// The flags' ranges (the settings table's rows), named as flags, before any file is read.
Status checkFlags(const AoFlags& f) {
    SFX_TRY(checkSetting(Setting::AoRadius, f.radius, "--radius"));
    SFX_TRY(checkSetting(Setting::AoMetresPerUnit, f.metresPerUnit, "--metres-per-unit"));
    if (f.intensity) SFX_TRY(checkSetting(Setting::AoIntensity, *f.intensity, "--intensity"));
    if (f.radiusExponent) SFX_TRY(checkSetting(Setting::AoRadiusExponent, *f.radiusExponent, "--radius-exponent"));
    if (f.contrast) SFX_TRY(checkSetting(Setting::AoContrast, *f.contrast, "--contrast"));
    if (f.bias) SFX_TRY(checkSetting(Setting::AoBias, *f.bias, "--bias"));
    if (f.sumExponent) SFX_TRY(checkSetting(Setting::AoSumExponent, *f.sumExponent, "--sum-exponent"));
    if (f.blurRadius) SFX_TRY(checkSetting(Setting::AoBlurRadius, *f.blurRadius, "--blur-radius"));
    if (f.slices) SFX_TRY(checkSetting(Setting::AoHorizonSlices, *f.slices, "--slices"));
    if (f.steps) SFX_TRY(checkSetting(Setting::AoHorizonSteps, *f.steps, "--steps"));
    if (f.thickness) SFX_TRY(checkSetting(Setting::AoHorizonThickness, *f.thickness, "--thickness"));
    if (f.falloff) SFX_TRY(checkSetting(Setting::AoHorizonFalloff, *f.falloff, "--falloff"));
    if (f.runs > tools::kMaxTimedRuns)
        return invalidArgument("--runs", std::to_string(f.runs), "0 (not timed) to " + std::to_string(tools::kMaxTimedRuns));
    return Status::ok();
}

// The tier's preset of that name; InvalidArgument listing the tier's presets otherwise.
Result<TierProfile> presetProfile(Tier tier, const std::string& name) {
    std::string names;
    for (const Preset& p : tiers::row(tier).presets) {
        if (p.name == name) return p.params;
        names += (names.empty() ? "" : ", ") + p.name;
    }
    return invalidArgument("--preset", "'" + name + "'", std::string("a preset of the ") + toString(tier) + " tier: " + names);
}

// The bent normals read back as signed xyz (RGBA8 holds xyz * 0.5 + 0.5), written to `path`.
Status writeBentNormals(Device& dev, TextureHandle texture, Format format, uint32_t w, uint32_t h, const std::string& path) {
    Result<std::vector<glm::dvec3>> bent = tools::readBentNormals(dev, texture, format, w, h);
    if (!bent) return bent.status();
    io::Image image(w, h, 3);
    for (size_t i = 0; i < bent->size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i * 3 + c] = float(bent.value()[i][c]);
    return io::writeImage(path, image);
}

int runAo(const AoFlags& f) {
    const std::string cmd = "ao";
    const std::string ext = io::extensionOf(f.outPath);
    if (ext != ".pfm" && ext != ".exr") return fail(cmd, invalidArgument("--out", "'" + f.outPath + "'", "a .pfm or .exr file"));
    if (!f.bentPath.empty() && io::extensionOf(f.bentPath) != ".pfm" && io::extensionOf(f.bentPath) != ".exr")
        return fail(cmd, invalidArgument("--bent-normals", "'" + f.bentPath + "'", "a .pfm or .exr file"));
    if (Status st = checkFlags(f); !st) return fail(cmd, st);
    AoSettings s;
    if (!f.technique.empty()) {
        AoTechnique technique;
        if (!parseAoTechnique(f.technique, &technique))
            return fail(cmd, invalidArgument("--technique", "'" + f.technique + "'", "alchemy, scalable, crease or horizon"));
        s.technique = technique;
    }
    if (!parseAoResolution(f.resolution, &s.resolution))
        return fail(cmd, invalidArgument("--resolution", "'" + f.resolution + "'", "tier, full or half"));
    s.radius = f.radius;
    s.metresPerUnit = f.metresPerUnit;
    s.intensity = f.intensity;
    s.radiusExponent = f.radiusExponent;
    s.contrast = f.contrast;
    s.bias = f.bias;
    s.sumExponent = f.sumExponent;
    s.samples = f.samples;
    s.blur = !f.noBlur;
    s.blurRadius = f.blurRadius;
    s.horizon = {f.slices, f.steps, f.thickness, f.falloff};
    s.normals = f.normalsPath.empty() ? AoNormals::FromDepth : AoNormals::FromTexture;
    s.bentNormals = !f.bentPath.empty();

    // Files first, each read once: a malformed or mismatched file is named before any device is opened.
    Result<LoadedDepth> depth = readDepth(f.camera);
    if (!depth) return fail(cmd, depth.status());
    const uint32_t w = depth->image.width, h = depth->image.height;
    std::optional<io::Image> normalImage;
    if (!f.normalsPath.empty()) {
        Result<io::Image> n = loadMatching(f.normalsPath, w, h, "--normals");
        if (!n) return fail(cmd, n.status());
        normalImage = std::move(n.value());
    }
    Result<OpenedDevice> opened = openDevice(f.device);
    if (!opened) return fail(cmd, opened.status());
    Device& dev = *opened->device;
    if (Status st = uploadDepth(dev, depth.value()); !st) return fail(cmd, st);

    TextureHandle normals;
    if (normalImage) {
        const io::Image& n = *normalImage;
        if (n.channels < 3)
            return fail(cmd,
                        Status{StatusCode::FileError,
                               "--normals " + f.normalsPath + " has " + std::to_string(n.channels) + " channel(s); view-space normals need x, y, z"});
        if (Status st = refuseNaN(n, 3, "--normals", f.normalsPath); !st) return fail(cmd, st);
        std::vector<float> px(size_t(w) * h * 4, 0.0f);
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                for (uint32_t c = 0; c < 3; ++c) px[(size_t(y) * w + x) * 4 + c] = n.at(x, y, c);
        Result<TextureHandle> t = dev.createTexture({w, h, 1, Format::RGBA32F, kTextureSampled, "sfx-cli-normals"});
        if (!t) return fail(cmd, t.status());
        normals = t.value();
        if (Status st = dev.writeTexture(normals, 0, px.data(), px.size() * sizeof(float)); !st) return fail(cmd, st);
    }

    Result<TierProfile> profile = presetProfile(opened->tier.tier, f.preset);
    if (!profile) return fail(cmd, profile.status());
    Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(dev, {w, h, profile.value(), s, depth->source.kind});
    if (!ao) return fail(cmd, ao.status());
    const bool r32 = dev.caps().renderableFormat[size_t(Format::R32F)];
    const Format outFormat = r32 ? Format::R32F : Format::RGBA8;
    Result<TextureHandle> out = dev.createTexture({w, h, 1, outFormat, kTextureSampled | kTextureRenderTarget, "sfx-cli-ao"});
    if (!out) return fail(cmd, out.status());
    AoInputs in;
    in.depth = depth->source;
    in.normals = normals;
    in.output = out.value();
    // Bent normals in the widest float format the device renders (signed xyz), else RGBA8.
    Format bentFormat = Format::RGBA8;
    for (Format candidate : {Format::RGBA32F, Format::RGBA16F})
        if (bentFormat == Format::RGBA8 && dev.caps().renderableFormat[size_t(candidate)]) bentFormat = candidate;
    if (s.bentNormals) {
        Result<TextureHandle> b = dev.createTexture({w, h, 1, bentFormat, kTextureSampled | kTextureRenderTarget, "sfx-cli-bent-normals"});
        if (!b) return fail(cmd, b.status());
        in.bentNormals = b.value();
    }
    if (Status st = ao.value()->dispatch(in); !st) return fail(cmd, st);
    if (Status st = dev.flush(); !st) return fail(cmd, st);
    std::optional<tools::DispatchCost> cost;
    if (f.runs > 0) {
        // The timed dispatches write the same output again: profiling changes no pixel (conformance).
        Result<tools::DispatchCost> c = tools::profilePasses(
            dev, *ao.value(), [&] { return ao.value()->dispatch(in); }, f.runs);
        if (!c) return fail(cmd, c.status());
        cost = c.value();
    }

    io::Image image(w, h, 1);
    if (r32) {
        if (Status st = dev.readTexture(out.value(), 0, image.pixels.data(), image.pixels.size() * sizeof(float)); !st) return fail(cmd, st);
    } else {
        std::vector<uint8_t> px(size_t(w) * h * 4);
        if (Status st = dev.readTexture(out.value(), 0, px.data(), px.size()); !st) return fail(cmd, st);
        for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = px[i * 4] / 255.0f;
    }
    // Texture rows are image rows (row 0 = top, as uploadDepth uploaded them).
    if (Status st = io::writeImage(f.outPath, image); !st) return fail(cmd, st);
    Result<std::string> png = writePngBeside(f.outPath, image);
    if (!png) return fail(cmd, png.status());
    if (s.bentNormals) {
        if (Status st = writeBentNormals(dev, in.bentNormals, bentFormat, w, h, f.bentPath); !st) return fail(cmd, st);
    }
    std::cout << "sfx ao: " << toString(ao.value()->config().technique) << " on " << dev.caps().summary() << ", tier " << toString(opened->tier.tier)
              << " preset " << f.preset << ", " << w << "x" << h << ", AO at " << (ao.value()->config().halfResolution ? "half" : "full")
              << " resolution -> " << f.outPath << " and " << png.value() << (s.bentNormals ? ", bent normals -> " + f.bentPath : "") << "\n";
    if (f.showPlan) std::cout << ao.value()->plan().describe();
    std::cout.flush();
    if (cost) tools::printCost(*cost);
    return 0;
}

}  // namespace

Command addAoCommand(CLI::App& app) {
    auto flags = std::make_shared<AoFlags>();
    Command c;
    c.app = app.add_subcommand("ao", "Ambient obscurance on G-buffer files: visibility in [0,1] (1 = unoccluded)");
    c.app->footer(kInputValuesHelp);
    flags->device.add(*c.app);
    flags->camera.add(*c.app);
    c.app->add_option("--technique", flags->technique, "alchemy | scalable | crease | horizon; not given: the preset's (sfx info --rules)");
    c.app
        ->add_option("--resolution", flags->resolution,
                     "tier | full | half: where obscurance and blur run; half = half size, then a depth-aware upsample; "
                     "tier = the tier preset's")
        ->capture_default_str();
    c.app->add_option("--normals", flags->normalsPath,
                      "view-space normals file (x right, y up, camera looking down -z; signed float xyz in PFM/EXR)");
    const std::string tier = "; not given: the tier's calibrated value";
    c.app->add_option("--radius", flags->radius, settingHelp(Setting::AoRadius))->capture_default_str();
    c.app->add_option("--metres-per-unit", flags->metresPerUnit, settingHelp(Setting::AoMetresPerUnit))->capture_default_str();
    c.app->add_option("--intensity", flags->intensity, settingHelp(Setting::AoIntensity) + tier);
    c.app->add_option("--radius-exponent", flags->radiusExponent, settingHelp(Setting::AoRadiusExponent) + tier);
    c.app->add_option("--contrast", flags->contrast, settingHelp(Setting::AoContrast) + tier);
    c.app->add_option("--bias", flags->bias, settingHelp(Setting::AoBias) + tier);
    c.app->add_option("--sum-exponent", flags->sumExponent, settingHelp(Setting::AoSumExponent) + tier);
    c.app->add_option("--samples", flags->samples, settingHelp(Setting::AoSamples) + "; not given: the tier's");
    c.app->add_option("--blur-radius", flags->blurRadius, settingHelp(Setting::AoBlurRadius) + "; not given: the tier's");
    c.app->add_option("--slices", flags->slices, settingHelp(Setting::AoHorizonSlices) + "; not given: the tier's");
    c.app->add_option("--steps", flags->steps, settingHelp(Setting::AoHorizonSteps) + "; not given: the tier's");
    c.app->add_option("--thickness", flags->thickness, settingHelp(Setting::AoHorizonThickness) + "; not given: the tier's");
    c.app->add_option("--falloff", flags->falloff, settingHelp(Setting::AoHorizonFalloff) + "; not given: the tier's");
    c.app->add_flag("--no-blur", flags->noBlur, "skip the bilateral blur");
    c.app->add_option("--preset", flags->preset, "one of the tier's presets (sfx info --rules lists them); explicit flags override it")
        ->capture_default_str();
    c.app->add_option("--runs", flags->runs, tools::kTimedRunsHelp);
    c.app->add_flag("--plan", flags->showPlan, "print the passes and memory");
    c.app->add_option("--out", flags->outPath, "output visibility, .pfm or .exr (a .png is written beside it)")->required();
    c.app->add_option("--bent-normals", flags->bentPath,
                      "horizon only: also write the bent normals (mean unoccluded direction, view space, signed xyz; sky (0, 0, 1)) "
                      "to this .pfm or .exr");
    c.run = [flags] { return runAo(*flags); };
    return c;
}

}  // namespace sfx::cli
