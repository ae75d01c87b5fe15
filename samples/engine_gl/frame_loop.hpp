// The sample's frame loop, shared by main.cpp and tests/engine/test_engine_gl.cpp: warm-up
// frames (the SDK compiles its pipelines at the first dispatch), then steady frames, with what
// the SDK and the host made in between and the frame times.
#pragma once

#include <string>

#include "renderer.hpp"

namespace engine_gl {

struct FrameLoopResult {
    uint32_t warmupFrames = 0, steadyFrames = 0;
    double medianFrameMs = 0, minFrameMs = 0;   // steady frames, wall time including the flush
    double medianDispatchMs = 0;                // CPU time in the AO and motion-blur dispatch() calls
    sfx::DeviceStats sdkAfterWarmup, sdkAtEnd;  // Device::stats() of the wrapped device
    HostGlCounts hostAfterWarmup, hostAtEnd;
    std::string sdkMessages;  // validation messages taken during the loop
};

// Frames [0, warmup) then [warmup, warmup + steady).
sfx::Result<FrameLoopResult> runFrames(Renderer& renderer, uint32_t warmup, uint32_t steady);

// The presented picture as a PNG (row 0 = top); reads back once, after the loop.
sfx::Status writePresentedPng(Renderer& renderer, const std::string& path);

}  // namespace engine_gl
