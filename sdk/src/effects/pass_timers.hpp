// Per-pass HAL timers of an effect's profiling (setProfiling / passTimings), shared by every
// effect context in sdk/src/effects/ (not installed). One owner: the effect.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "sfx/hal.hpp"
#include "sfx/plan.hpp"

namespace sfx::detail {

class PassTimers {
public:
    explicit PassTimers(Device& device) : device_(device) {}
    ~PassTimers() { clear(); }
    PassTimers(const PassTimers&) = delete;
    PassTimers& operator=(const PassTimers&) = delete;

    // Makes timers until there are `count`, so a pass index below it records without creating
    // one mid-frame. On failure the timers made so far stay and the status says why.
    Status reserve(size_t count);
    void clear();
    bool empty() const { return timers_.empty(); }
    std::span<const TimerHandle> handles() const { return timers_; }

    // Records `record` bracketed by timer `index`, made first when there is none yet; the
    // last profiled frame's passes are those up to the highest index timed since clear().
    template <class Record>
    Status timed(size_t index, Record&& record) {
        SFX_TRY(reserve(index + 1));
        SFX_TRY(device_.beginTimer(timers_[index]));
        SFX_TRY(record());
        SFX_TRY(device_.endTimer(timers_[index]));
        if (index + 1 > timed_) timed_ = index + 1;
        return Status::ok();
    }
    // One entry per timed pass, named by `plan`'s passes in order; `who` ("MotionBlur") begins
    // each message. InvalidArgument when nothing was timed; a reading's failure names the pass.
    Result<std::vector<PassTiming>> read(const EffectPlan& plan, const std::string& who) const;

private:
    Device& device_;
    std::vector<TimerHandle> timers_;
    size_t timed_ = 0;
};

}  // namespace sfx::detail
