// Internal helpers of the AmbientObscurance passes (ao.cpp, ao_half_res.cpp); not installed.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "pass_timers.hpp"
#include "sfx/ao.hpp"
#include "sfx_shared_ao.h"

namespace sfx::detail {

// TierProfile::aoPackedDepthTarget: the depth key packed into an RGBA8 AO target (ES 3.0 need
// not render to float). Otherwise a float target that carries the linear depth too (RG32F; RGBA32F for crease, whose g
// holds the moderate blur), so the blur and the upsample read one texel per tap, not two.
inline Format aoTargetFormat(const TierProfile& profile, AoTechnique technique) {
    if (profile.aoPackedDepthTarget) return Format::RGBA8;
    return technique == AoTechnique::Crease ? Format::RGBA32F : Format::RG32F;
}

// The bent normals' intermediate targets (AoSettings.bentNormals): RGBA8 holding xyz * 0.5 + 0.5
// where the AO target is RGBA8 (ES 3.0 need not render to float), else RGBA16F.
inline Format aoBentTargetFormat(const TierProfile& profile) { return profile.aoPackedDepthTarget ? Format::RGBA8 : Format::RGBA16F; }

// The host's bent normal target's check (AoInputs.bentNormals with AoSettings.bentNormals on):
// InvalidArgument naming it, else its format.
Result<Format> checkBentNormalsInput(Device& device, TextureHandle texture, uint32_t width, uint32_t height);

// At half resolution, whether depth MIP level 1 is the half-size depth: high-tier Scalable or Horizon,
// whose pyramid exists anyway, on a target large enough for a second level. Otherwise the
// ao_half_depth pass makes the same rotated-grid sample into a texture of its own.
// Where the obscurance pass writes the depth its readers need (SFX_AO_DEPTH_IN_*, sfx_shared_ao.h):
// nowhere when it writes the host's output, else by the target's layout.
inline int aoDepthInTarget(const TierProfile& profile, AoTechnique technique, bool blur, bool half) {
    if (!blur && !half) return SFX_AO_DEPTH_IN_NONE;
    if (profile.aoPackedDepthTarget) return SFX_AO_DEPTH_IN_KEY_BA;
    return technique == AoTechnique::Crease ? SFX_AO_DEPTH_IN_FLOAT_B : SFX_AO_DEPTH_IN_FLOAT_G;
}

inline bool mipGivesHalfDepth(const AoConfig& config, const TierProfile& profile, uint32_t width, uint32_t height) {
    return config.halfResolution && (config.technique == AoTechnique::Scalable || config.technique == AoTechnique::Horizon) &&
        profile.aoUsesDepthMip && std::min(profile.aoDepthMipLevels, maxMipLevels(width, height)) >= 2;
}

// Multilayer AO (ao_multilayer.cpp): named errors for AoInputs.depthLayers the config needs,
// and the obscurance pass's layer bindings where the tier's programs declare them.
Status checkDepthLayers(Device& device, const AoInputs& in, const AoConfig& config, uint32_t width, uint32_t height);
void appendDepthLayerBindings(std::vector<TextureBinding>& bindings, const AoInputs& in, const AoConfig& config, const TierProfile& profile,
                              const TextureBinding& passDepth);

}  // namespace sfx::detail

namespace sfx {

template <class Record>
Status AmbientObscurance::timed(size_t passIndex, Record&& record) {
    if (passTimers_->empty()) return record();
    return passTimers_->timed(passIndex, std::forward<Record>(record));
}

}  // namespace sfx
