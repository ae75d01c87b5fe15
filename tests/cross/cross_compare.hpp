// What every cross-backend comparison shares: the backends opened at a tier (the Vulkan backend
// once per physical device the loader lists), and the pairwise worst-difference check whose
// measured worst is printed beside its bound.
#pragma once

#include <catch2/catch.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "edge_bands.hpp"
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
// where it is, and how many values differ by more than `bound`; with a bound per value
// (`bounds`, as long as the outputs, each above 0), also the worst difference / bound and
// where it is.
struct Worst {
    double value = 0;
    size_t at = 0;
    size_t beyond = 0;
    double ratio = 0;
    size_t ratioAt = 0;
};
Worst worstDifference(const std::vector<double>& a, const std::vector<double>& b, double bound);
Worst worstDifference(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& bounds);

// Every pair of backends' outputs (one value per channel and pixel): the worst difference is
// within `bound`; the measured worst is printed so the bound stays honest. With `tieFraction`
// > 0, up to that fraction of the values may exceed it instead (where the effect has a step a
// rounding can cross: a tie); how many did is printed.
void requirePairsWithin(const std::map<std::string, std::vector<double>>& results, double bound, const std::string& what, double tieFraction = 0.0);

// requirePairsWithin with a bound per value (`bounds`, one per value of every output): each
// pair's worst difference / bound is at most 1; that ratio and the worst absolute difference
// are printed.
void requirePairsWithinEach(const std::map<std::string, std::vector<double>>& results, const std::vector<double>& bounds, const std::string& what);

// requirePairsWithin for a rasterised picture, `channels` values per pixel. Pairs whose
// rasterisers snap vertices to the same sub-pixel grid (DeviceLimits::subPixelPrecisionBits)
// are held to `bound` everywhere. On different grids a pixel centre near an edge may be covered
// by one and not the other (both specifications allow a grid as coarse as 1/16 pixel):
// `excluded(bits)` gives those pixels for the coarser grid of 2^-bits pixels; how many is
// printed, and more than kMaxExcludedFraction of the picture fails. Outside them the pair is
// held to `bound` (Checked) or its worst difference printed (Printed): where the picture
// depends on depth beyond coverage, as AO does, the snap moves every triangle's depth plane too
// (depth is interpolated from the snapped vertices), by up to the depth's slope times the
// snap, which AO turns into more than rounding far from any edge (docs/conformance.md,
// "Cross-backend agreement").
inline constexpr double kMaxExcludedFraction = 0.05;
enum class OutsideBand { Checked, Printed };
void requireRasterPairsWithin(const std::vector<Opened>& devices, const std::map<std::string, std::vector<double>>& results, size_t channels,
                              double bound, const std::string& what, const std::function<PixelMask(uint32_t bits)>& excluded, OutsideBand outside);

// So that agreement means something: the output spans more than `minSpan` somewhere.
void requireSpan(const std::vector<double>& values, double minSpan, const std::string& what);

}  // namespace sfx::test

// The backends at `tier`, or a skip when fewer than two opened: there is nothing to compare.
// clang-format off
#define SFX_OPEN_AT_LEAST_TWO(devices, tier)                                                             \
    std::vector<::sfx::test::Opened> devices = ::sfx::test::openAll(tier);                               \
    if (devices.size() < 2) SFX_SKIP("fewer than two backends at tier " << toString(tier) << ": nothing to compare")
// clang-format on
