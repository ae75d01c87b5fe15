// engine_vulkan: a renderer on raw Vulkan that runs the SDK's AO and motion blur on its own
// G-buffer images inside its own command buffer (engine_renderer.hpp), for many frames, and
// writes the last one as a PNG.
//   engine_vulkan [--frames N] [--width W] [--height H] [--tier current|high] [--validate] [--out file.png]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "engine_renderer.hpp"
#include "sfx/image_io.hpp"

using namespace sfx;

int main(int argc, char** argv) {
    engine::EngineOptions options;
    uint32_t frames = 120;
    std::string out = "engine_vulkan.png";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--frames" && hasValue)
            frames = uint32_t(std::max(1, std::atoi(argv[++i])));
        else if (a == "--width" && hasValue)
            options.width = uint32_t(std::max(1, std::atoi(argv[++i])));
        else if (a == "--height" && hasValue)
            options.height = uint32_t(std::max(1, std::atoi(argv[++i])));
        else if (a == "--tier" && hasValue && parseTier(argv[i + 1], &options.tier))
            ++i;
        else if (a == "--validate")
            options.validation = true;
        else if (a == "--out" && hasValue)
            out = argv[++i];
        else {
            std::fprintf(stderr,
                         "usage: engine_vulkan [--frames N] [--width W] [--height H] [--tier current|high] "
                         "[--validate] [--out file.png]\n");
            return 2;
        }
    }
    Result<std::unique_ptr<engine::EngineRenderer>> renderer = engine::EngineRenderer::create(options);
    if (!renderer) {
        std::fprintf(stderr, "engine_vulkan: %s\n", renderer.status().toString().c_str());
        return renderer.status().code() == StatusCode::BackendUnavailable || renderer.status().code() == StatusCode::FileError ? 77 : 1;
    }
    engine::EngineRenderer& r = *renderer.value();
    // Frame time: start to start of consecutive frames (one frame in flight), after 4 warm-up frames.
    std::vector<double> ms;
    auto last = std::chrono::steady_clock::now();
    for (uint32_t f = 0; f < frames; ++f) {
        if (Status s = r.renderFrame(); !s) {
            std::fprintf(stderr, "engine_vulkan: frame %u: %s\n", f, s.toString().c_str());
            return 1;
        }
        const auto now = std::chrono::steady_clock::now();
        if (f >= 4) ms.push_back(std::chrono::duration<double, std::milli>(now - last).count());
        last = now;
    }
    if (Status s = r.finish(); !s) {
        std::fprintf(stderr, "engine_vulkan: %s\n", s.toString().c_str());
        return 1;
    }
    Result<std::vector<uint8_t>> texels = r.readImage(engine::HostImageKind::Final);
    if (!texels) {
        std::fprintf(stderr, "engine_vulkan: %s\n", texels.status().toString().c_str());
        return 1;
    }
    io::Image picture(r.width(), r.height(), 4);
    for (size_t i = 0; i < picture.pixels.size(); ++i) picture.pixels[i] = float(texels.value()[i]) / 255.0f;
    if (Status s = io::writePng(out, picture); !s) {
        std::fprintf(stderr, "engine_vulkan: %s\n", s.toString().c_str());
        return 1;
    }
    const std::vector<std::string> messages = r.takeValidationMessages();
    for (const std::string& m : messages) std::fprintf(stderr, "engine_vulkan: validation: %s\n", m.c_str());
    std::sort(ms.begin(), ms.end());
    const double median = ms.empty() ? 0.0 : ms[ms.size() / 2];
    std::printf("engine_vulkan: %u frames at %ux%u (%s tier%s), median frame %.2f ms -> %s\n", frames, r.width(), r.height(), toString(options.tier),
                options.validation ? ", validation on" : "", median, out.c_str());
    return messages.empty() ? 0 : 1;
}
