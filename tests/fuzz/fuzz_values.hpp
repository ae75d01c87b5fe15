// Values for the settings fuzz targets: floats that are often hostile (NaN, infinities,
// denormals, the limits of the type) and tier profiles that are either the real table's or
// arbitrary, because a host may fill a TierProfile by hand.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>

#include "sfx/status.hpp"
#include "sfx/tier.hpp"
#include "sfx/tiers.hpp"

namespace sfx::fuzz {

inline float hostileFloat(FuzzedDataProvider& in) {
    switch (in.ConsumeIntegralInRange<int>(0, 3)) {
        case 0: {  // any bit pattern: NaNs, infinities, denormals
            const uint32_t bits = in.ConsumeIntegral<uint32_t>();
            float f;
            std::memcpy(&f, &bits, sizeof f);
            return f;
        }
        case 1: return in.ConsumeFloatingPointInRange<float>(-2.0f, 2.0f);
        case 2: return in.ConsumeFloatingPointInRange<float>(-2000.0f, 2000.0f);
        default: {
            static const float kEdges[] = {0.0f,
                                           -0.0f,
                                           1.0f,
                                           -1.0f,
                                           1e-8f,
                                           1e-6f,
                                           1e-4f,
                                           0.1f,
                                           10.0f,
                                           64.0f,
                                           100.0f,
                                           1000.0f,
                                           1e6f,
                                           std::numeric_limits<float>::denorm_min(),
                                           std::numeric_limits<float>::min(),
                                           std::numeric_limits<float>::max(),
                                           std::numeric_limits<float>::infinity(),
                                           -std::numeric_limits<float>::infinity(),
                                           std::numeric_limits<float>::quiet_NaN()};
            return kEdges[in.ConsumeIntegralInRange<size_t>(0, sizeof kEdges / sizeof kEdges[0] - 1)];
        }
    }
}

// Small counts most of the time (where the ranges' edges are), any 32-bit value otherwise.
inline uint32_t hostileCount(FuzzedDataProvider& in) {
    return in.ConsumeBool() ? in.ConsumeIntegralInRange<uint32_t>(0, 70) : in.ConsumeIntegral<uint32_t>();
}

// Unset (the tier's value) or a hostile value.
inline std::optional<float> hostileOptionalFloat(FuzzedDataProvider& in) {
    if (in.ConsumeBool()) return std::nullopt;
    return hostileFloat(in);
}
inline std::optional<uint32_t> hostileOptionalCount(FuzzedDataProvider& in) {
    if (in.ConsumeBool()) return std::nullopt;
    return hostileCount(in);
}

inline TierProfile hostileProfile(FuzzedDataProvider& in) {
    if (in.ConsumeBool()) return tiers::profile(in.ConsumeBool() ? Tier::High : Tier::Current);
    TierProfile p;
    p.tier = Tier(in.ConsumeIntegralInRange<uint32_t>(0, 3));
    p.aoScalableTaps = hostileCount(in);
    p.aoScalableMirrored = in.ConsumeBool();
    p.aoScalableMaxRadiusPx = hostileFloat(in);
    p.aoUsesDepthMip = in.ConsumeBool();
    p.aoDepthMipLevels = hostileCount(in);
    p.aoAlchemySamples = hostileCount(in);
    p.aoBlurRadiusPx = hostileCount(in);
    p.aoCreaseTaps = hostileCount(in);
    p.aoHorizonSlices = hostileCount(in);
    p.aoHorizonSteps = hostileCount(in);
    p.aoHorizonThickness = hostileFloat(in);
    p.aoHorizonFalloff = hostileFloat(in);
    p.aoPackedDepthTarget = in.ConsumeBool();
    p.mbTaps = hostileCount(in);
    p.mbMaxRadiusPx = hostileFloat(in);
    p.mbTilePx = hostileFloat(in);
    p.mbJitterSize = hostileCount(in);
    p.abufferOit = in.ConsumeBool();
    return p;
}

// A refusal must be InvalidArgument whose message names one of the fields it may name.
inline bool namesField(const Status& status, std::initializer_list<const char*> prefixes) {
    if (status.code() != StatusCode::InvalidArgument) return false;
    for (const char* prefix : prefixes)
        if (status.message().find(prefix) != std::string::npos) return true;
    return false;
}

}  // namespace sfx::fuzz
