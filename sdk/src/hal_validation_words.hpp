// How the shared validation prints the values its messages name (internal to sfx_core).
#pragma once

#include <string>
#include <vector>

#include "sfx/hal.hpp"

namespace sfx::validation {

inline std::string str(uint64_t v) { return std::to_string(v); }
inline bool knownFormat(Format f) { return uint32_t(f) < uint32_t(Format::Count); }
// The format's name, or its number for a value outside Format.
inline std::string formatName(Format f) { return knownFormat(f) ? toString(f) : str(uint32_t(f)); }
// "R8, RGBA8 or R32F": the formats (Undefined excluded) for which `keep` holds.
template <class Keep>
std::string formatList(Keep keep) {
    std::vector<std::string> names;
    for (uint32_t f = 1; f < uint32_t(Format::Count); ++f)
        if (keep(Format(f))) names.push_back(toString(Format(f)));
    return orList(names);
}
// " under its capability ceiling (GLES30)" when the device has one, else "".
inline std::string underCeiling(const DeviceCaps& caps) {
    return caps.ceiling == CapabilityCeiling::None ? "" : std::string(" under its capability ceiling (") + toString(caps.ceiling) + ")";
}

}  // namespace sfx::validation
