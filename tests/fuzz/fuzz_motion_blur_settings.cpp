// resolveMotionBlur on settings, profiles and heights from fuzzer bytes: a named
// InvalidArgument or parameters inside the documented ranges (odd taps in [3, 31], a radius
// in [1, 64] px, jitter 2 or 4, finite positive extents).
#include <cstdlib>

#include "fuzz_values.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx_shared_mb.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace sfx;
    FuzzedDataProvider in(data, size);
    const TierProfile profile = fuzz::hostileProfile(in);
    MotionBlurSettings s;
    s.maxRadiusPx = fuzz::hostileOptionalFloat(in);
    s.referenceRows = fuzz::hostileCount(in);
    s.samples = fuzz::hostileOptionalCount(in);
    s.softDepthExtent = fuzz::hostileFloat(in);
    s.centreWeight = fuzz::hostileFloat(in);
    s.exposure = fuzz::hostileFloat(in);
    const uint32_t height = in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(0, 8192) : in.ConsumeIntegral<uint32_t>();

    Result<MotionBlurParams> params = resolveMotionBlur(profile, s, height);
    if (!params) {
        if (!fuzz::namesField(params.status(), {"MotionBlurSettings.", "MotionBlurDesc.profile", "height"})) std::abort();
        return 0;
    }
    const MotionBlurParams& p = params.value();
    if (p.taps < 3 || p.taps > uint32_t(shared::SFX_MB_MAX_TAPS) || p.taps % 2 == 0 || p.pairs != (p.taps - 1) / 2) std::abort();
    if (p.radiusPx < 1 || p.radiusPx > uint32_t(shared::SFX_MB_MAX_RADIUS_LIMIT_PX)) std::abort();
    if (p.jitterSize != 2 && p.jitterSize != 4) std::abort();
    if (!(p.softDepthExtent > 0 && std::isfinite(p.softDepthExtent)) || !(p.centreWeight > 0 && std::isfinite(p.centreWeight)) ||
        !(p.exposure >= 0 && std::isfinite(p.exposure)))
        std::abort();
    return 0;
}
