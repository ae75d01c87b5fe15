// engine_gl: a renderer on its own EGL context and GL textures, with ScalableFX's AO and motion
// blur run on those textures in place (no copy, nothing allocated per frame). Renders the
// glmark2 bunny for --frames frames and writes the last one as a PNG.
//   engine_gl [--api gles|gl] [--width W] [--height H] [--frames N] [--out file.png] [--debug]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include "frame_loop.hpp"

namespace {

int usage(const std::string& why) {
    std::cerr << "engine_gl: " << why << "\n"
              << "usage: engine_gl [--api gles|gl] [--width W] [--height H] [--frames N] [--out file.png] [--debug]\n";
    return 2;
}

bool parseCount(const char* text, uint32_t lo, uint32_t hi, uint32_t* out) {
    char* end = nullptr;
    const unsigned long v = std::strtoul(text, &end, 10);
    if (!end || *end != '\0' || v < lo || v > hi) return false;
    *out = uint32_t(v);
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    engine_gl::ContextApi api = engine_gl::ContextApi::GLES;
    engine_gl::RendererOptions options;
    uint32_t frames = 120;
    std::string out = "engine_gl.png";
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
        if (arg == "--debug") {
            options.debug = true;
        } else if (!value) {
            return usage(arg + " needs a value");
        } else if (arg == "--api") {
            if (std::strcmp(value, "gles") == 0)
                api = engine_gl::ContextApi::GLES;
            else if (std::strcmp(value, "gl") == 0)
                api = engine_gl::ContextApi::DesktopGL;
            else
                return usage(std::string("--api is '") + value + "'; allowed gles or gl");
            ++i;
        } else if (arg == "--width" || arg == "--height") {
            if (!parseCount(value, 1, 8192, arg == "--width" ? &options.width : &options.height))
                return usage(arg + " is '" + value + "'; allowed 1 to 8192");
            ++i;
        } else if (arg == "--frames") {
            if (!parseCount(value, 2, 100000, &frames)) return usage(std::string("--frames is '") + value + "'; allowed 2 to 100000");
            ++i;
        } else if (arg == "--out") {
            out = value;
            ++i;
        } else {
            return usage("unknown argument " + arg);
        }
    }
    options.log = [](sfx::LogSeverity, std::string_view message) { std::cerr << "sfx: " << message << "\n"; };

    sfx::Result<std::unique_ptr<engine_gl::EglContext>> context = engine_gl::EglContext::open(api);
    if (!context) {
        std::cerr << context.status().toString() << "\n";
        return 1;
    }
    sfx::Result<std::unique_ptr<engine_gl::Renderer>> renderer = engine_gl::Renderer::create(*context.value(), options);
    if (!renderer) {
        std::cerr << renderer.status().toString() << "\n";
        return 1;
    }
    std::cout << "engine_gl: " << engine_gl::toString(api) << " " << options.width << "x" << options.height << ", " << renderer.value()->tier().reason
              << "\n";
    const uint32_t warmup = frames < 10 ? 1 : 5;
    sfx::Result<engine_gl::FrameLoopResult> loop = engine_gl::runFrames(*renderer.value(), warmup, frames - warmup);
    if (!loop) {
        std::cerr << loop.status().toString() << "\n";
        return 1;
    }
    if (sfx::Status s = engine_gl::writePresentedPng(*renderer.value(), out); !s) {
        std::cerr << s.toString() << "\n";
        return 1;
    }
    const bool steady = loop->sdkAfterWarmup == loop->sdkAtEnd && loop->hostAfterWarmup == loop->hostAtEnd;
    std::printf(
        "engine_gl: %u frames, median %.2f ms (min %.2f) per steady frame, %.3f ms of it in the two dispatch() calls; "
        "steady frames made %s -> %s\n",
        frames, loop->medianFrameMs, loop->minFrameMs, loop->medianDispatchMs, steady ? "nothing" : "OBJECTS", out.c_str());
    if (!loop->sdkMessages.empty()) std::cerr << loop->sdkMessages;
    return steady && loop->sdkMessages.empty() ? 0 : 1;
}
