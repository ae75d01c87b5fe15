// A reproducible stream of uniform numbers from a seed, for laying out scene families: the same
// on every compiler and library (mt19937 is specified bit for bit; the standard distributions are
// not, so the conversion is done here).
#pragma once

#include <cstdint>
#include <random>

namespace sfx::tools {

struct Draw {
    std::mt19937 gen;
    explicit Draw(uint32_t seed) : gen(seed) {}
    // Uniform in [lo, hi).
    double operator()(double lo, double hi) { return lo + (hi - lo) * (gen() / 4294967296.0); }
};

}  // namespace sfx::tools
