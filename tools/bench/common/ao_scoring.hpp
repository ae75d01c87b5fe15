// Scoring AO settings against the ray-traced truth on a set of views (tools/scenes/
// trade_views.*): the truth of every view x radius (cached), and an evaluator that renders the
// SDK's AO of each view's inputs on one device and compares it with the truth. fit_ao and
// trade_presets share it.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sfx/ao.hpp"
#include "sfx/truth_metrics.hpp"
#include "trade_views.hpp"

namespace sfx::tools {

// One view at one radius, with its truth.
struct AoCase {
    size_t view;  // index into the view list the evaluator was prepared with
    double radius;
    truth::Image truth;
};

struct TruthSettings {
    uint32_t width = 320, height = 180, samples = 256;
    std::string cacheDir = "build/truth-cache";
};

// The cases of views[first, last) at every radius (none: each view's own), truth from the cache
// or traced; progress gets one line per truth.
Result<std::vector<AoCase>> loadCases(const std::vector<TradeView>& views, size_t first, size_t last, const std::vector<double>& radii,
                                      const TruthSettings& settings, const std::function<void(const std::string&)>& progress);

// Mean scores over a set of cases (PSNR averaged in dB; non-finite values, which only an exact
// answer gives, are left out of the mean).
struct AoScore {
    double psnr = 0, psnrOccluded = 0, signedOccluded = 0;
    double worstPsnr = 1e9, worstPsnrOccluded = 1e9;  // the worst single case
    size_t cases = 0;
    double objective() const { return psnr + psnrOccluded; }
};
AoScore summarise(const std::vector<truth::Comparison>& errors);
// The score of "no AO" (visibility 1 everywhere).
AoScore noAoScore(const std::vector<AoCase>& cases);
// Every technique the SDK names (AoTechnique's values in order), so that a benchmark scores a
// technique the moment it exists.
std::vector<AoTechnique> allAoTechniques();

// Renders and scores settings on one tier's device (a preset's profile, default the tier's),
// every case of a set.
class AoEvaluator {
public:
    AoEvaluator(Device& device, Tier tier, uint32_t width, uint32_t height) : dev_(device), tier_(tier), width_(width), height_(height) {}
    ~AoEvaluator();
    AoEvaluator(const AoEvaluator&) = delete;
    AoEvaluator& operator=(const AoEvaluator&) = delete;
    Status prepare(const std::vector<TradeView>& views);
    void setProfile(const TierProfile& profile) { profile_ = profile; }
    // Each case with settings.radius = the case's radius; visibilities, when given, receives each
    // case's output.
    Result<std::vector<truth::Comparison>> run(AoSettings settings, const std::vector<AoCase>& cases,
                                               std::vector<reference::Grid>* visibilities = nullptr);
    Result<AoScore> score(const AoSettings& settings, const std::vector<AoCase>& cases);
    size_t evaluations() const { return evaluations_; }
    Device& device() const { return dev_; }
    const ViewInputs& inputs(size_t view) const { return *inputs_[view]; }

private:
    Device& dev_;
    Tier tier_;
    uint32_t width_, height_;
    TierProfile profile_;
    Format format_ = Format::Undefined;
    TextureHandle out_;
    std::vector<std::unique_ptr<ViewInputs>> inputs_;
    size_t evaluations_ = 0;
};

}  // namespace sfx::tools
