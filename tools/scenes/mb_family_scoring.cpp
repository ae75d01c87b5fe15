#include "mb_family_scoring.hpp"

#include <cmath>

namespace sfx::tools {

double familyPsnr(const reference::ColorGrid& picture, const reference::ColorGrid& truth, const std::vector<bool>& mask) {
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < picture.values.size(); ++i) {
        if (!mask.empty() && !mask[i]) continue;
        for (int c = 0; c < 3; ++c) sum += std::pow(picture.values[i][c] - truth.values[i][c], 2);
        n += 3;
    }
    if (n == 0) return NAN;
    return sum == 0 ? 99.0 : 10.0 * std::log10(double(n) / sum);
}

std::vector<ScoredFamilyCase> scoredFamilyCases(bool heldOut, const std::vector<double>& speedsPx, uint32_t instants, uint32_t seed, uint32_t w,
                                                uint32_t h, const std::function<void(const std::string&)>& progress) {
    std::vector<ScoredFamilyCase> out;
    for (const std::string& name : familyNames()) {
        if (familyHeldOut(name) != heldOut) continue;
        for (double speed : speedsPx) {
            ScoredFamilyCase c;
            c.family = makeFamilyCase(name, speed, seed, w, h);
            c.truth = c.family.scene.truth(instants);
            c.masks = familyMasks(c.family.scene, 64);
            c.frame = c.family.scene.render(0);
            out.push_back(std::move(c));
        }
        if (progress) progress("motion blur family " + name + ": truth of " + std::to_string(speedsPx.size()) + " speeds");
    }
    return out;
}

}  // namespace sfx::tools
