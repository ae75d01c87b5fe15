// fit_ao --leave-one-out: whether a calibration generalises, measured family by family. For
// each scene family F the look is fitted on the other families and, separately, on every family
// (both with the same search, from the same starting looks); F's score under the fit that saw it
// less its score under the fit that did not is F's generalisation gap. Every look is scored on
// every family, beside the tier table's, so a look that would meet the adoption rule (a higher
// training score, no held-out family lower) shows.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "ao_look_search.hpp"
#include "ao_scoring.hpp"
#include "scene_families.hpp"

namespace sfx::tools {

// A look and its score on each family and on the training families together.
struct ScoredLook {
    AoSettings settings;
    std::map<std::string, AoScore> families;
    AoScore training;
};

struct LeaveOneOut {
    std::string tier, technique;
    ScoredLook tierTable, allFamilies;
    std::map<std::string, ScoredLook> without;  // by the family left out of the fit
};

// Runs the fits of one tier x technique on `cases` (every family's; AoCase::view indexes
// `views`). Each fit searches from every look in `starts` and keeps the best on its own cases
// (searchLookFrom); starts[0] is the tier table's look, scored beside the fits.
Result<LeaveOneOut> leaveOneOut(AoEvaluator& ev, const std::vector<TradeView>& views, const std::vector<AoCase>& cases,
                                const std::vector<AoSettings>& starts, const LookSearch& search, const std::string& label);

// The page's section (docs/ao_families.md, between the fit_ao_loo markers) and the CSV (a row per
// tier x technique x look x family).
// `starts` says where each fit's search began ("the tier table's look").
std::string leaveOneOutMarkdown(const std::vector<LeaveOneOut>& runs, const std::map<std::string, AoScore>& none, const std::string& machine,
                                double seconds, const std::string& starts);
std::string leaveOneOutCsv(const std::vector<LeaveOneOut>& runs);

}  // namespace sfx::tools
