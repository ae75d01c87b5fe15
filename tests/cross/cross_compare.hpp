// What every cross-backend comparison shares: the backends opened at a tier (the Vulkan backend
// once per physical device the loader lists), and the pairwise worst-difference check whose
// measured worst is printed beside its bound.
#pragma once

#include <catch2/catch.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sfx/backends.hpp"
#include "sfx/tier.hpp"
#include "skips.hpp"

namespace sfx::test {

struct Opened {
    std::string name;
    BackendKind backend = BackendKind::Null;
    std::unique_ptr<Device> device;
};

// Every compiled backend at `tier` (current: under the GL ES 3.0 ceiling), and the Vulkan
// backend once on each physical device the loader lists (given lavapipe and SwiftShader, two
// independent compilers compared in one run). An absent backend is reported; with
// SFX_REQUIRE_ALL_BACKENDS set it fails the test.
std::vector<Opened> openAll(Tier tier);

// Every device's validation messages: any one fails.
void requireNoValidation(std::vector<Opened>& devices);

// The worst absolute difference of two equally long outputs (each value finite: a REQUIRE),
// where it is, and how many values differ by more than `bound`.
struct Worst {
    double value = 0;
    size_t at = 0;
    size_t beyond = 0;
};
Worst worstDifference(const std::vector<double>& a, const std::vector<double>& b, double bound);

// Every pair of backends' outputs (one value per channel and pixel): the worst difference is
// within `bound`; the measured worst is printed so the bound stays honest. With `tieFraction`
// > 0, up to that fraction of the values may exceed it instead (where the effect has a step a
// rounding can cross: a tie); how many did is printed.
void requirePairsWithin(const std::map<std::string, std::vector<double>>& results, double bound, const std::string& what, double tieFraction = 0.0);

// requirePairsWithin for a rasterised picture: only pairs whose rasterisers snap vertices to the
// same sub-pixel grid (DeviceLimits::subPixelPrecisionBits) are held to `bound`. On different
// grids a pixel centre within half a grid step of a silhouette may be covered by one and not
// the other (both specifications allow a grid as coarse as 1/16 pixel), which moves that pixel
// and the AO of every pixel that taps it by far more than rounding; such a pair is printed
// with its worst difference and how many values exceed the bound, not checked.
void requireRasterPairsWithin(const std::vector<Opened>& devices, const std::map<std::string, std::vector<double>>& results, double bound,
                              const std::string& what, double tieFraction = 0.0);

// So that agreement means something: the output spans more than `minSpan` somewhere.
void requireSpan(const std::vector<double>& values, double minSpan, const std::string& what);

}  // namespace sfx::test

// The backends at `tier`, or a skip when fewer than two opened: there is nothing to compare.
// clang-format off
#define SFX_OPEN_AT_LEAST_TWO(devices, tier)                                                             \
    std::vector<::sfx::test::Opened> devices = ::sfx::test::openAll(tier);                               \
    if (devices.size() < 2) SFX_SKIP("fewer than two backends at tier " << toString(tier) << ": nothing to compare")
// clang-format on
