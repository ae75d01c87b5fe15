#include "pass_timers.hpp"

namespace sfx::detail {

Status PassTimers::reserve(size_t count) {
    while (timers_.size() < count) {
        Result<TimerHandle> timer = device_.createTimer();
        if (!timer) return timer.status();
        timers_.push_back(timer.value());
    }
    return Status::ok();
}

void PassTimers::clear() {
    for (TimerHandle t : timers_) (void)device_.destroyTimer(t);
    timers_.clear();
    timed_ = 0;
}

Result<std::vector<PassTiming>> PassTimers::read(const EffectPlan& plan, const std::string& who) const {
    if (timed_ == 0)
        return Status{StatusCode::InvalidArgument, who + "::passTimings: nothing timed (call setProfiling(true), then record a frame and flush)"};
    std::vector<PassTiming> out;
    out.reserve(timed_);
    for (size_t i = 0; i < timed_ && i < plan.passes.size(); ++i) {
        Result<TimerReading> reading = device_.readTimer(timers_[i]);
        if (!reading)
            return Status{reading.status().code(),
                          who + "::passTimings: pass '" + plan.passes[i].name + "' (dispatch, then flush, first): " + reading.status().message()};
        out.push_back({plan.passes[i].effect, plan.passes[i].name, reading.value()});
    }
    return out;
}

}  // namespace sfx::detail
