// Scoring motion blur on the scene families (mb_families.hpp): PSNR over a mask, and the scored
// cases (held out or training, at the scored speeds) with their truth, masks and input frame, so
// every tool that ranks motion blur settings scores the same pictures the same way.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "mb_families.hpp"

namespace sfx::tools {

// PSNR (peak 1) of RGB over the masked pixels; an empty mask counts every pixel, a mask that
// selects none gives NaN; identical pictures give 99 dB.
double familyPsnr(const reference::ColorGrid& picture, const reference::ColorGrid& truth, const std::vector<bool>& mask);

struct ScoredFamilyCase {
    FamilyCase family;
    reference::ColorGrid truth;
    FamilyMasks masks;
    reference::SceneFrame frame;  // the mid-shutter input the effect gets
};

// Every family of the split (held out or training) at every speed, laid out from `seed` in a
// w x h frame, its truth averaged over `instants`. `progress` gets one line per family.
std::vector<ScoredFamilyCase> scoredFamilyCases(bool heldOut, const std::vector<double>& speedsPx, uint32_t instants, uint32_t seed, uint32_t w,
                                                uint32_t h, const std::function<void(const std::string&)>& progress);

// The speeds a family score averages over: from the still threshold's 2 px to beyond both
// tiers' radius (docs/motion_blur.md).
inline const std::vector<double> kScoredFamilySpeedsPx = {2, 6, 12, 24, 40};

}  // namespace sfx::tools
