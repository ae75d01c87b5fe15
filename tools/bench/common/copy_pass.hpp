// The cost unit of the benchmarks: one full-screen pass copying a texture of the AO output's
// format, timed on the same device at the same size, so costs read as "copy passes" and compare
// across backends and machines.
#pragma once

#include <functional>
#include <memory>

#include "sfx/hal.hpp"

namespace sfx::tools {

struct CopyPass {
    explicit CopyPass(Device& device) : dev(device) {}
    CopyPass(const CopyPass&) = delete;
    CopyPass& operator=(const CopyPass&) = delete;
    Device& dev;
    TextureHandle src, dst;
    ProgramHandle program;
    PipelineHandle pipeline;
    Status record();  // one copy, recorded (flush to run it)
    // The cost unit: the median over `runs` timed runs of kCopiesPerRun copies recorded back to
    // back, divided by kCopiesPerRun. One copy alone is a few milliseconds on a CPU rasteriser and
    // its median swung by 2x between runs of the same benchmark; a run of eight averages the
    // per-pass jitter, and the timer's fixed cost is spread over eight passes.
    static constexpr uint32_t kCopiesPerRun = 8;
    Result<double> medianMs(uint32_t runs);
    // An effect's cost in copy passes, timed interleaved with the unit: run i times `record` and
    // one run of copies back to back (their order alternating, so neither always runs on the
    // other's warm caches), and the cost is the median of the per-run ratios. On lavapipe the
    // copy's time moves by up to 2x within one process over seconds (one copy pass, timed three
    // times in a row: 1.57, 2.06, 2.07 ms); a ratio of two medians taken seconds apart moved with
    // it, while each pair here is timed within a few tens of milliseconds.
    struct Interleaved {
        double effectMs = 0;  // median of the effect's runs
        double copyMs = 0;    // median of the copy's runs (one pass)
        double ratio = 0;     // median of effect / copy, pair by pair
    };
    Result<Interleaved> timeAgainst(uint32_t runs, const std::function<Status()>& record);
    ~CopyPass();
};

Result<std::unique_ptr<CopyPass>> makeCopyPass(Device& dev, Tier tier, uint32_t w, uint32_t h, Format format);

}  // namespace sfx::tools
