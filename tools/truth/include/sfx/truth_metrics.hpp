// How far an AO estimate is from the ray-traced truth (sfx/truth.hpp): the numbers of the
// trade table in docs/trade.md.
#pragma once

#include <cstdint>
#include <vector>

#include "sfx/status.hpp"
#include "sfx/truth.hpp"

namespace sfx::truth {

// Pixels where the truth is below this are "occluded": the region AO exists to darken.
inline constexpr double kOccludedBelow = 0.95;

struct Comparison {
    double psnr = 0;          // dB, peak 1, over every pixel (sky included); +inf when exact
    double psnrOccluded = 0;  // dB over surface pixels with truth < kOccludedBelow; +inf when exact or none
    size_t occludedPixels = 0;
    double meanSignedError = 0;  // mean of estimate - truth over the frame: > 0 too bright, < 0 too dark
    double meanSignedErrorOccluded = 0;
    double worstError = 0;  // largest |estimate - truth|
    uint32_t worstX = 0, worstY = 0;
};

// `estimate`: visibility per pixel, row 0 = top, width x height of the truth. InvalidArgument
// naming estimate when the size differs or a value is not finite.
Result<Comparison> compare(const Image& truth, const std::vector<double>& estimate);

}  // namespace sfx::truth
