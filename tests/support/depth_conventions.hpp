// The depth conventions the depth tests sweep: every clip range × reversed-Z × finite/infinite
// far plane a host may render with.
#pragma once

#include <limits>

#include "sfx/hal.hpp"

namespace sfx::test {

struct DepthConvention {
    const char* name;
    ClipDepthRange clip;
    bool reversed;
    double farPlane;  // +infinity: infinite far plane
};

inline constexpr double kInfiniteFar = std::numeric_limits<double>::infinity();

inline constexpr DepthConvention kDepthConventions[] = {
    {"[0,1] standard", ClipDepthRange::ZeroToOne, false, 100.0},
    {"[0,1] reversed", ClipDepthRange::ZeroToOne, true, 100.0},
    {"[0,1] standard infinite", ClipDepthRange::ZeroToOne, false, kInfiniteFar},
    {"[0,1] reversed infinite", ClipDepthRange::ZeroToOne, true, kInfiniteFar},
    {"[-1,1] standard", ClipDepthRange::MinusOneToOne, false, 100.0},
    {"[-1,1] standard infinite", ClipDepthRange::MinusOneToOne, false, kInfiniteFar},
    {"[-1,1] reversed", ClipDepthRange::MinusOneToOne, true, 100.0},
};

}  // namespace sfx::test
