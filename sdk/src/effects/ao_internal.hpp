// Internal helpers of the AmbientObscurance passes (ao.cpp, ao_half_res.cpp); not installed.
#pragma once

#include <algorithm>

#include "sfx/ao.hpp"

namespace sfx::detail {

// TierProfile::aoPackedDepthTarget: depth packed into an RGBA8 AO target, or AO alone in RG16F
// with the blur reading full-precision linear depth.
inline Format aoTargetFormat(const TierProfile& profile) { return profile.aoPackedDepthTarget ? Format::RGBA8 : Format::RG16F; }

// At half resolution, whether depth MIP level 1 is the half-size depth: high-tier Scalable,
// whose pyramid exists anyway, on a target large enough for a second level. Otherwise the
// ao_half_depth pass makes the same rotated-grid sample into a texture of its own.
inline bool mipGivesHalfDepth(const AoConfig& config, const TierProfile& profile, uint32_t width, uint32_t height) {
    return config.halfResolution && config.technique == AoTechnique::Scalable && profile.aoUsesDepthMip &&
           std::min(profile.aoDepthMipLevels, maxMipLevels(width, height)) >= 2;
}

}  // namespace sfx::detail

namespace sfx {

template <class Record>
Status AmbientObscurance::timed(size_t passIndex, Record&& record) {
    if (passTimers_.empty()) return record();
    SFX_TRY(device_.beginTimer(passTimers_[passIndex]));
    SFX_TRY(record());
    return device_.endTimer(passTimers_[passIndex]);
}

}  // namespace sfx
