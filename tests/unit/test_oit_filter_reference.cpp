// The reference bilateral filter of the layer AO (sfx/reference/oit_ao_filter.hpp): radius 0 is
// the raw AO, a constant stays constant, a depth step is not crossed (neither by the front-depth
// key of the blended channel nor by the opaque key), sky keeps its value, and noise on one
// surface is smoothed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "sfx/reference/oit_ao_filter.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

constexpr uint32_t kW = 24, kH = 12;

// Opaque surfaces at depth 2 (left half) and 10 (right half), the top row sky; a fragment at
// depth 1.5 over the left half's bottom rows (the blended key there is the fragment's).
FragmentImage image() {
    PerspectiveDesc pd;
    pd.aspect = double(kW) / kH;
    pd.nearPlane = 0.1;
    pd.farPlane = 100.0;
    FragmentImage im(kW, kH, makeDepthReconstruction(makePerspective(pd).value(), kW, kH).value());
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            OpaqueSurface& o = im.opaque[im.index(x, y)];
            if (y > 0) o.depth = x < kW / 2 ? 2.0 : 10.0;
            if (y >= kH - 3 && x < kW / 2) {
                OitFragment f;
                f.depth = 1.5;
                f.alpha = 0.5;
                im.fragments[im.index(x, y)].push_back(f);
            }
        }
    return im;
}

OitAoResult rawAo(const std::function<double(uint32_t, uint32_t)>& blended, const std::function<double(uint32_t, uint32_t)>& opaque) {
    OitAoResult r;
    r.blended = Grid(kW, kH);
    r.opaque = Grid(kW, kH);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            r.blended.at(x, y) = blended(x, y);
            r.opaque.at(x, y) = opaque(x, y);
        }
    return r;
}

}  // namespace

TEST_CASE("oit AO filter reference: identity at radius 0, constants kept, depth steps not crossed", "[oit][reference]") {
    const FragmentImage im = image();
    // Each region its own value: sky row 1, left 0.2, right 0.9; the fragment rows 0.5 in blended.
    auto region = [](uint32_t x, uint32_t y) { return y == 0 ? 1.0 : x < kW / 2 ? 0.2 : 0.9; };
    auto blended = [&](uint32_t x, uint32_t y) { return (y >= kH - 3 && x < kW / 2) ? 0.5 : region(x, y); };
    const OitAoResult raw = rawAo(blended, region);
    CHECK(filterLayerAo(im, raw, 0).blended.values == raw.blended.values);
    for (uint32_t radius : {1u, 4u, 8u}) {
        const OitAoResult f = filterLayerAo(im, raw, radius);
        double worst = 0;
        for (size_t i = 0; i < raw.blended.values.size(); ++i)
            worst = std::max({worst, std::abs(f.blended.values[i] - raw.blended.values[i]), std::abs(f.opaque.values[i] - raw.opaque.values[i])});
        INFO("radius " << radius);
        CHECK(worst <= 1e-12);  // piecewise constant over keys 20% apart and more: nothing leaks
    }
}

TEST_CASE("oit AO filter reference: noise on one surface is smoothed", "[oit][reference]") {
    const FragmentImage im = image();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.3, 0.7);
    std::vector<double> noise(size_t(kW) * kH);
    for (double& v : noise) v = u(rng);
    auto noisy = [&](uint32_t x, uint32_t y) { return noise[size_t(y) * kW + x]; };
    const OitAoResult raw = rawAo(noisy, noisy);
    const OitAoResult f = filterLayerAo(im, raw, 3);
    // Spread over the right half's interior rows (one surface, one key).
    auto spread = [&](const Grid& g) {
        double lo = 1, hi = 0;
        for (uint32_t y = 1; y < kH; ++y)
            for (uint32_t x = kW / 2; x < kW; ++x) lo = std::min(lo, g.at(x, y)), hi = std::max(hi, g.at(x, y));
        return hi - lo;
    };
    CHECK(spread(f.opaque) < 0.5 * spread(raw.opaque));
    CHECK(spread(f.blended) < 0.5 * spread(raw.blended));
    for (uint32_t x = 0; x < kW; ++x) CHECK(f.opaque.at(x, 0) == raw.opaque.at(x, 0));  // sky keeps its value
}
