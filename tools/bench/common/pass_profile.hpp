// Per-pass GPU cost of an effect, as the benchmarks and `sfx ao --runs` report it: the effect's
// own pass timers (Vulkan timestamps; GL wall clock around glFinish), one warm-up dispatch, then
// the median of each pass and of each dispatch's total over the timed runs.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "sfx/hal.hpp"
#include "sfx/plan.hpp"

namespace sfx::tools {

// Most timed runs a command line may ask for: enough for any median, short of an hour's run.
inline constexpr uint32_t kMaxTimedRuns = 1000;
// The --runs flag of the sfx commands that price a dispatch.
inline constexpr const char* kTimedRunsHelp =
    "time the dispatch: prints 'time: <median> ms' over N dispatches after a warm-up (GPU timestamps on Vulkan, "
    "glFinish on GL), per pass beside it; 0 = not timed";

struct PassCost {
    std::string name;
    double ms = 0;  // median over the timed runs
};

struct DispatchCost {
    std::vector<PassCost> passes;  // in the effect's plan() order
    double totalMs = 0;            // median of the per-run sums (not the sum of the medians)
    TimingSource source = TimingSource::GpuTimestamps;
    uint32_t runs = 0;
};

// Effect: anything with setProfiling(bool) and passTimings() (AmbientObscurance, MotionBlur,
// Transparency); dispatch: a callable recording one frame of it, returning Status.
template <class Effect, class Dispatch>
Result<DispatchCost> profilePasses(Device& dev, Effect& effect, Dispatch&& dispatch, uint32_t runs) {
    SFX_TRY(effect.setProfiling(true));
    DispatchCost cost;
    cost.runs = runs;
    std::vector<std::vector<double>> perPass;
    std::vector<double> totals;
    for (uint32_t i = 0; i < runs + 1; ++i) {
        SFX_TRY(dispatch());
        SFX_TRY(dev.flush());
        Result<std::vector<PassTiming>> timings = effect.passTimings();
        if (!timings) return timings.status();
        if (i == 0) {  // the warm-up: pipelines and caches settle, nothing is counted
            perPass.assign(timings->size(), {});
            for (const PassTiming& t : timings.value()) cost.passes.push_back({t.name, 0.0});
            continue;
        }
        double total = 0;
        for (size_t p = 0; p < timings->size() && p < perPass.size(); ++p) {
            perPass[p].push_back(timings.value()[p].reading.milliseconds);
            total += timings.value()[p].reading.milliseconds;
            cost.source = timings.value()[p].reading.source;
        }
        totals.push_back(total);
    }
    SFX_TRY(effect.setProfiling(false));
    for (size_t p = 0; p < perPass.size(); ++p) cost.passes[p].ms = median(perPass[p]);
    cost.totalMs = median(totals);
    return cost;
}

// "time: <median> ms" first, so a script reads the price of a configuration from one line.
inline void printCost(const DispatchCost& cost) {
    std::printf("time: %.3f ms\n", cost.totalMs);
    std::printf("  median of %u dispatches after a warm-up, %s; per pass:\n", cost.runs, toString(cost.source));
    for (const PassCost& p : cost.passes) std::printf("    %.3f ms  %s\n", p.ms, p.name.c_str());
}

}  // namespace sfx::tools
