#include <cmath>
#include <limits>
#include <string>

#include "sfx/truth_metrics.hpp"

namespace sfx::truth {
namespace {
double psnrOf(double squaredErrorSum, size_t count) {
    if (count == 0 || squaredErrorSum == 0.0) return std::numeric_limits<double>::infinity();
    return -10.0 * std::log10(squaredErrorSum / double(count));
}
}  // namespace

Result<Comparison> compare(const Image& truth, const std::vector<double>& estimate) {
    const size_t n = size_t(truth.width) * truth.height;
    if (estimate.size() != n)
        return invalidArgument("estimate", std::to_string(estimate.size()) + " pixels",
                               std::to_string(truth.width) + "x" + std::to_string(truth.height) + " = " + std::to_string(n) + " (the truth's size)");
    Comparison c;
    double sq = 0, sqOccluded = 0, signedSum = 0, signedOccluded = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(estimate[i]))
            return invalidArgument("estimate[" + std::to_string(i) + "]", std::to_string(estimate[i]), "a finite visibility");
        const double e = estimate[i] - double(truth.visibility[i]);
        sq += e * e;
        signedSum += e;
        if (std::abs(e) > c.worstError) {
            c.worstError = std::abs(e);
            c.worstX = uint32_t(i % truth.width);
            c.worstY = uint32_t(i / truth.width);
        }
        if (truth.isSurface(i) && truth.visibility[i] < kOccludedBelow) {
            sqOccluded += e * e;
            signedOccluded += e;
            ++c.occludedPixels;
        }
    }
    c.psnr = psnrOf(sq, n);
    c.psnrOccluded = psnrOf(sqOccluded, c.occludedPixels);
    c.meanSignedError = n ? signedSum / double(n) : 0.0;
    c.meanSignedErrorOccluded = c.occludedPixels ? signedOccluded / double(c.occludedPixels) : 0.0;
    return c;
}

}  // namespace sfx::truth
