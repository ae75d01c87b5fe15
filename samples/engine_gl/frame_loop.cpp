#include "frame_loop.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

#include "sfx/image_io.hpp"

namespace engine_gl {

sfx::Result<FrameLoopResult> runFrames(Renderer& renderer, uint32_t warmup, uint32_t steady) {
    FrameLoopResult out;
    out.warmupFrames = warmup;
    out.steadyFrames = steady;
    auto takeMessages = [&] {
        for (const std::string& m : renderer.device().takeValidationMessages()) out.sdkMessages += m + "\n";
    };
    for (uint32_t f = 0; f < warmup; ++f) SFX_TRY(renderer.renderFrame(f));
    takeMessages();
    out.sdkAfterWarmup = renderer.device().stats();
    out.hostAfterWarmup = renderer.gl().counts();
    std::vector<double> ms, dispatchMs;
    ms.reserve(steady);  // before the steady frames: the loop itself allocates nothing either
    dispatchMs.reserve(steady);
    for (uint32_t f = warmup; f < warmup + steady; ++f) {
        const auto start = std::chrono::steady_clock::now();
        SFX_TRY(renderer.renderFrame(f));
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        dispatchMs.push_back(renderer.lastDispatchMs());
    }
    out.sdkAtEnd = renderer.device().stats();
    out.hostAtEnd = renderer.gl().counts();
    takeMessages();
    if (!ms.empty()) {
        std::sort(ms.begin(), ms.end());
        out.medianFrameMs = ms[ms.size() / 2];
        out.minFrameMs = ms.front();
        std::sort(dispatchMs.begin(), dispatchMs.end());
        out.medianDispatchMs = dispatchMs[dispatchMs.size() / 2];
    }
    return out;
}

sfx::Status writePresentedPng(Renderer& renderer, const std::string& path) {
    const std::vector<uint8_t> rgba = renderer.readPresented();
    sfx::io::Image image(renderer.width(), renderer.height(), 4);
    for (size_t i = 0; i < rgba.size(); ++i) image.pixels[i] = float(rgba[i]) / 255.0f;
    return sfx::io::writePng(path, image);
}

}  // namespace engine_gl
