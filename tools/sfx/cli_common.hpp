// Pieces every `sfx` subcommand shares: opening the device a user asked for, reading the
// G-buffer files into textures, building the camera from --fov-y/--near/--far.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>

#include "sfx/backends.hpp"
#include "sfx/camera.hpp"
#include "sfx/depth.hpp"
#include "sfx/image_io.hpp"
#include "sfx/tiers.hpp"

namespace sfx::cli {

// --backend auto|vulkan|gles|gl|gl-egl|gl-osmesa, --device, --tier auto|current|high and --validate.
struct DeviceFlags {
    std::string backend = "auto";
    std::string tier = "auto";
    bool validate = false;  // API validation; its messages are printed on stderr
    std::string device;     // Vulkan: the physical device, by index or part of its name
    void add(CLI::App& app);
};

struct OpenedDevice {
    std::unique_ptr<Device> device;
    BackendConfig config;
    tiers::TierChoice tier;
};
// Forcing "current" opens the device under the GL ES 3.0 ceiling, as a phone would run it.
Result<OpenedDevice> openDevice(const DeviceFlags& flags);

// --depth FILE --depth-kind linear|hardware --fov-y --near --far [--clip-depth 0,1|-1,1] [--reversed-z]
struct CameraFlags {
    std::string depthPath;
    std::string depthKind = "linear";
    double fovYDegrees = 60.0;
    double nearPlane = 0.1;
    double farPlane = 100.0;  // "inf" accepted
    std::string clipDepth = "0,1";
    bool reversedZ = false;
    void add(CLI::App& app);
};

struct LoadedDepth {
    io::Image image;     // as read, one channel, row 0 = top
    DepthSource source;  // kind and camera; the texture once uploadDepth has run (R32F)
};
// Reads the depth file (PFM/EXR/PNG; first channel) once, validates flags and values (no NaN:
// refuseNaN; any other value goes to the effect, whose depth rule makes it sky where it is out
// of range) and builds the camera. No device is needed, so a
// bad file is named before one is opened.
Result<LoadedDepth> readDepth(const CameraFlags& flags);
// Uploads depth.image to a new R32F texture on `device` into depth.source.texture.
Status uploadDepth(Device& device, LoadedDepth& depth);

// Reads an image and checks it matches width x height; `what` names the flag in errors.
Result<io::Image> loadMatching(const std::string& path, uint32_t width, uint32_t height, const char* what);

// Writes `image` as a PNG preview beside outPath (same name, extension .png); returns its path.
Result<std::string> writePngBeside(const std::string& outPath, const io::Image& image);

// The one rule of every tool for hostile values in input files (each --help says it):
// a NaN is an error naming the flag, file, pixel and channel; every other value (an infinity,
// a huge or out-of-range value) goes to the effect, which follows its documented rule.
extern const char* const kInputValuesHelp;
// InvalidArgument "<flag> <path>: pixel (x, y) channel c is NaN; ..." for the first NaN among
// the first `channels` channels of `image`, else ok.
Status refuseNaN(const io::Image& image, uint32_t channels, const std::string& flag, const std::string& path);

// Prints "sfx <command>: error: <message>" to stderr and returns the process exit code 1.
int fail(const std::string& command, const Status& status);

}  // namespace sfx::cli
