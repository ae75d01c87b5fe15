// The two quality tiers of the SDK. Which tier a device gets, and what each tier's
// parameters are, is decided by the data and rules in tiers/ (see sfx/tiers.hpp).
#pragma once

#include <cstdint>
#include <string>

namespace sfx {

enum class Tier : uint32_t {
    Current = 0,  // GL ES 3.0-class: fragment passes only, no storage buffers or atomics
    High = 1,     // Vulkan / GL ES 3.1+ / GL 4.3+: storage buffers, atomics, compute
};
inline constexpr uint32_t kTierCount = 2;

const char* toString(Tier tier);  // "current" / "high"
bool parseTier(const std::string& text, Tier* out);

// The per-tier parameters effects read. Filled by sfx::tiers from its table; the values
// are the constants the shaders and CPU references share (shader_src/include/sfx_shared.h).
struct TierProfile {
    Tier tier = Tier::Current;
    // Ambient obscurance
    uint32_t aoScalableTaps = 0;       // 4 (mirrored) or 9 (spiral)
    bool aoScalableMirrored = false;   // current tier: each offset also used negated
    float aoScalableMaxRadiusPx = 0;   // screen-space clamp of the AO radius (0 = none)
    bool aoUsesDepthMip = false;       // high tier reads the depth MIP pyramid
    uint32_t aoDepthMipLevels = 0;     // levels of that pyramid (level 0 included)
    uint32_t aoAlchemySamples = 0;     // default Alchemy sample count
    uint32_t aoBlurRadiusPx = 0;       // bilateral blur half-width
    // With blur, where the blur finds each pixel's depth. true (current tier): the raw AO goes to
    // an RGBA8 target with a 16-bit depth key packed in b, a (one fetch per tap, 8-bit targets
    // only). false (high): an RG16F target, and the blur reads the linear depth texture. Must
    // match ao_blur.frag, whose high-tier variant (SFX_TIER_HIGH) declares that depth binding.
    bool aoPackedDepthTarget = false;
    // Motion blur
    uint32_t mbTaps = 0;               // reconstruction taps including the centre
    float mbMaxRadiusPx = 0;           // maximum blur radius at the reference resolution
    uint32_t mbJitterSize = 0;         // 2 (checkerboard) or 4 (4x4 randomised)
    // Order-independent transparency
    bool abufferOit = false;
};

}  // namespace sfx
