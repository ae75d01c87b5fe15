// The AO techniques, named apart from the effect so that a tier preset (sfx/tier.hpp) can name
// the one it runs.
#pragma once

#include <cstdint>
#include <string>

namespace sfx {

enum class AoTechnique : uint32_t {
    Alchemy,   // McGuire et al. 2011: samples uniform in the projected world-space disk
    Scalable,  // Bukowski et al. 2012: few spiral taps with falloff, squared sum; depth MIP on high
    Crease,    // Fox & Compton 2007: 24 taps on the 11x11 stippled diamond, artist-tuned
    // Jimenez et al. 2016 (GTAO): per slice the two horizons, the cosine-weighted visible arc in
    // closed form; estimates the visibility itself rather than an obscurance with a falloff
    Horizon,
};
inline constexpr uint32_t kAoTechniqueCount = 4;
const char* toString(AoTechnique technique);  // "alchemy", "scalable", "crease", "horizon"
bool parseAoTechnique(const std::string& text, AoTechnique* out);

}  // namespace sfx
