// The search behind fit_ao: the look parameters of each AO technique, the looks a search starts
// from (the papers' and the tier table's), and the coarse-to-fine search that maximises a score
// of training cases. It sees only a scoring function, so the caller picks the training cases
// (the training families, or every family but one).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ao_scoring.hpp"
#include "sfx/ao.hpp"
#include "sfx/tiers.hpp"

namespace sfx::tools {

// A searched parameter: a field of AoSettings, its range and whether the search steps in log space.
struct LookParameter {
    const char* name;
    std::optional<float> AoSettings::*field = nullptr;              // a top-level field, or
    std::optional<float> AoCreaseSettings::*creaseField = nullptr;  // one of crease's
    double lo, hi;
    bool logScale;
    std::optional<float>& of(AoSettings& s) const { return field ? s.*field : s.crease.*creaseField; }
    // The searched settings are always set (startingSettings, tierSettings).
    float of(const AoSettings& s) const { return (field ? s.*field : s.crease.*creaseField).value(); }
    double toUnit(double v) const;
    double fromUnit(double u) const;
};

std::vector<LookParameter> lookParametersOf(AoTechnique t);

// The papers' look (every tier's default before the calibration), made explicit.
AoSettings paperLook(AoTechnique t);
// The tier table's look for t, as explicit settings (a refit that starts where the last one ended).
AoSettings tierLook(AoTechnique t, const TierProfile& profile);
// "intensity 0.39, contrast 1.78, bias 1e-07".
std::string describeLook(const AoSettings& s);

struct LookSearch {
    uint32_t refinements = 5;  // levels of the fine search (its step halves at each)
    // Mean signed error where the truth is occluded above which the objective pays
    // kBrightPenaltyDb per unit (negative: no limit): a look may not buy PSNR by leaving contacts
    // and creases too bright.
    double brightLimit = -1;
    // The objective is frameWeight x frame PSNR + the PSNR where occluded (1: both count alike;
    // 0: only where occluded, the quantity AO is for).
    double frameWeight = 1;
    double objective(const AoScore& s) const;
};
// dB of objective lost per unit of training signed error beyond the limit: 0.01 too bright costs 1 dB.
constexpr double kBrightPenaltyDb = 100.0;

using LookScorer = std::function<Result<AoScore>(const AoSettings&)>;

// Coarse to fine from `start`: each parameter over 5 points of its range, then `refinements`
// levels of a Hooke-Jeeves pattern search in the unit cube of the parameters. Prints each stage
// after `label`.
Result<AoSettings> searchLook(const LookScorer& score, const AoSettings& start, const LookSearch& search, const std::string& label);
// searchLook from each start in turn; the look with the highest objective wins (the first on a
// tie). A search ends on the ridge point nearest its start, so a fit that is to say where the
// best look lies tries more than one.
Result<AoSettings> searchLookFrom(const LookScorer& score, const std::vector<AoSettings>& starts, const LookSearch& search, const std::string& label);

}  // namespace sfx::tools
