#include "cli_common.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

namespace sfx::cli {

void DeviceFlags::add(CLI::App& app) {
    app.add_option("--backend", backend, "auto | vulkan | gles | gl | gl-egl | gl-osmesa")->capture_default_str();
    app.add_option("--tier", tier, "auto, or a tier (" + tierNameList() + "; a lower tier runs under its capability ceiling)")->capture_default_str();
    app.add_option("--device", device,
                   "Vulkan: the physical device, by its index or part of its name (sfx info lists them); default the best by type");
    app.add_flag("--validate", validate, "API validation (Vulkan validation layer, GL error checks); messages go to stderr");
}

Result<OpenedDevice> openDevice(const DeviceFlags& flags) {
    std::optional<Tier> tier;
    if (flags.tier != "auto") {
        Tier t;
        if (!parseTier(flags.tier, &t)) return invalidArgument("--tier", "'" + flags.tier + "'", "auto or " + tierNameList());
        tier = t;
    }
    DeviceOptions options;
    options.validation = flags.validate;
    options.physicalDevice = flags.device;
    // The tool, not the library, prints: validation messages reach stderr through the log callback
    // when the device is destroyed.
    options.log = [](LogSeverity, std::string_view message) { std::cerr << "sfx: " << message << "\n"; };
    options.ceiling = tier ? tiers::row(*tier).ceiling : CapabilityCeiling::None;
    OpenedDevice out;
    if (flags.backend == "auto") {
        Result<DeviceSelection> sel = openBestDevice(options);
        if (!sel) return sel.status();
        out.device = std::move(sel->device);
        out.config = sel->config;
    } else {
        if (!parseBackendConfig(flags.backend, &out.config) || out.config.backend == BackendKind::Null)
            return invalidArgument("--backend", "'" + flags.backend + "'", "auto, vulkan, gles, gl, gl-egl or gl-osmesa");
        Result<std::unique_ptr<Device>> dev = sfx::openDevice(out.config, options);
        if (!dev) return dev.status();
        out.device = std::move(dev.value());
    }
    Result<tiers::TierChoice> choice = tiers::choose(out.device->caps(), tier);
    if (!choice) return choice.status();
    out.tier = choice.value();
    return out;
}

const char* const kInputValuesHelp =
    "Input values: a NaN anywhere in an input file is an error naming the file, pixel and channel. Every "
    "other value reaches the effect as it is and follows its rule (docs/robustness_extremes.md): depth that is "
    "infinite, not positive, or hardware depth outside [0, 1] is sky; a zero or infinite normal falls back to "
    "the one derived from depth; an infinite or huge velocity is clamped to the blur radius in its direction; "
    "colour beyond +-65504 is held at +-65504 and infinite colour is left out of the blur.";

Status refuseNaN(const io::Image& image, uint32_t channels, const std::string& flag, const std::string& path) {
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x)
            for (uint32_t c = 0; c < std::min(channels, image.channels); ++c)
                if (std::isnan(image.at(x, y, c)))
                    return {StatusCode::InvalidArgument,
                            flag + " " + path + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " + std::to_string(c) +
                                " is NaN; input files may hold any value but NaN"};
    return Status::ok();
}

void CameraFlags::add(CLI::App& app) {
    app.add_option("--depth", depthPath, "depth file (PFM, EXR or PNG; first channel; row order as the format defines)")->required();
    app.add_option("--depth-kind", depthKind,
                   "linear: positive eye-space distance along the view axis, in scene units;\n"
                   "hardware: the stored depth-buffer value in [0,1], mapped by the projection below")
        ->capture_default_str();
    app.add_option("--fov-y", fovYDegrees, "vertical field of view in degrees, (0, 180)")->capture_default_str();
    app.add_option("--near", nearPlane, "near plane distance, > 0")->capture_default_str();
    app.add_option("--far", farPlane, "far plane distance, > near; 'inf' for an infinite far plane")->capture_default_str();
    app.add_option("--clip-depth", clipDepth, "hardware depth convention: 0,1 (Vulkan/D3D) or -1,1 (GL default)")->capture_default_str();
    app.add_flag("--reversed-z", reversedZ, "hardware depth is reversed (near = 1, far = 0)");
}

Result<io::Image> loadMatching(const std::string& path, uint32_t width, uint32_t height, const char* what) {
    Result<io::Image> image = io::readImage(path);
    if (!image) return image.status();
    if (image->width != width || image->height != height)
        return Status{StatusCode::InvalidArgument,
                      std::string(what) + " " + path + " is " + std::to_string(image->width) + "x" + std::to_string(image->height) +
                          "; the depth is " + std::to_string(width) + "x" + std::to_string(height)};
    return image;
}

Result<LoadedDepth> readDepth(const CameraFlags& f) {
    if (f.depthKind != "linear" && f.depthKind != "hardware") return invalidArgument("--depth-kind", "'" + f.depthKind + "'", "linear or hardware");
    if (!(f.fovYDegrees > 0 && f.fovYDegrees < 180)) return invalidArgument("--fov-y", std::to_string(f.fovYDegrees), "(0, 180) degrees");
    if (!(f.nearPlane > 0) || !std::isfinite(f.nearPlane)) return invalidArgument("--near", std::to_string(f.nearPlane), "a finite distance > 0");
    if (!(f.farPlane > f.nearPlane))
        return invalidArgument("--far", std::to_string(f.farPlane), "> --near (" + std::to_string(f.nearPlane) + "), or inf");
    if (f.clipDepth != "0,1" && f.clipDepth != "-1,1") return invalidArgument("--clip-depth", "'" + f.clipDepth + "'", "0,1 or -1,1");

    LoadedDepth out;
    Result<io::Image> image = io::readImage(f.depthPath);
    if (!image) return Status{image.status().code(), "--depth: " + image.status().message()};
    out.image = io::Image(image->width, image->height, 1);
    SFX_TRY(refuseNaN(image.value(), 1, "--depth", f.depthPath));
    for (uint32_t y = 0; y < image->height; ++y)
        for (uint32_t x = 0; x < image->width; ++x) out.image.at(x, y) = image->at(x, y, 0);
    PerspectiveDesc p;
    p.fovYRadians = f.fovYDegrees * 3.14159265358979323846 / 180.0;
    p.aspect = double(image->width) / double(image->height);
    p.nearPlane = f.nearPlane;
    p.farPlane = f.farPlane;
    p.reversedZ = f.reversedZ;
    p.clipDepth = f.clipDepth == "0,1" ? ClipDepthRange::ZeroToOne : ClipDepthRange::MinusOneToOne;
    p.rowZeroIsTop = true;  // image files put row 0 at the top; so does the upload below
    Result<CameraProjection> camera = makePerspective(p);
    if (!camera) return camera.status();

    out.source.kind = f.depthKind == "hardware" ? DepthKind::Hardware : DepthKind::Linear;
    out.source.camera = camera.value();
    return out;
}

Status uploadDepth(Device& device, LoadedDepth& depth) {
    TextureDesc desc{depth.image.width, depth.image.height, 1, Format::R32F, kTextureSampled, "sfx-cli-depth"};
    Result<TextureHandle> tex = device.createTexture(desc);
    if (!tex) return tex.status();
    SFX_TRY(device.writeTexture(tex.value(), 0, depth.image.pixels.data(), depth.image.pixels.size() * sizeof(float)));
    depth.source.texture = tex.value();
    return Status::ok();
}

Result<std::string> writePngBeside(const std::string& outPath, const io::Image& image) {
    const std::string png = std::filesystem::path(outPath).replace_extension(".png").string();
    SFX_TRY(io::writePng(png, image));
    return png;
}

int fail(const std::string& command, const Status& status) {
    std::cerr << "sfx " << command << ": error: " << status.toString() << "\n";
    return 1;
}

}  // namespace sfx::cli
