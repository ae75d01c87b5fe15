#include "ao_look_search.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

#include "markdown_section.hpp"

namespace sfx::tools {

double LookParameter::toUnit(double v) const { return logScale ? std::log(v / lo) / std::log(hi / lo) : (v - lo) / (hi - lo); }

double LookParameter::fromUnit(double u) const {
    u = std::clamp(u, 0.0, 1.0);
    return logScale ? lo * std::pow(hi / lo, u) : lo + u * (hi - lo);
}

std::vector<LookParameter> lookParametersOf(AoTechnique t) {
    // Horizon estimates the visibility itself: its one look parameter is a power p on it (the
    // contrast k, intensity staying 1), which leaves an open surface's 1 and a hidden one's 0 as they are.
    if (t == AoTechnique::Horizon) return {{"power", &AoSettings::contrast, nullptr, 0.5, 4.0, true}};
    std::vector<LookParameter> p{{"intensity", &AoSettings::intensity, nullptr, 0.05, 20.0, true},
                                 {"contrast", &AoSettings::contrast, nullptr, 0.1, 10.0, true}};
    if (t == AoTechnique::Alchemy) p.push_back({"bias", &AoSettings::bias, nullptr, 1e-7, 0.3, true});
    if (t == AoTechnique::Scalable) {
        p.push_back({"bias", &AoSettings::bias, nullptr, 0.0, 0.5, false});
        p.push_back({"sumExponent", &AoSettings::sumExponent, nullptr, 0.5, 4.0, true});
    }
    if (t == AoTechnique::Crease) {
        // crease.averager divides what intensity multiplies: searching both would be searching one.
        p.push_back({"crease.range", nullptr, &AoCreaseSettings::range, 0.05, 10.0, true});
        p.push_back({"crease.bias", nullptr, &AoCreaseSettings::bias, 0.02, 10.0, true});
    }
    return p;
}

AoSettings paperLook(AoTechnique t) {
    AoSettings s;
    s.technique = t;
    s.normals = AoNormals::FromTexture;  // the G-buffer's normals, as a deferred renderer would
    s.intensity = 1.0f, s.contrast = 1.0f;
    s.bias = t == AoTechnique::Alchemy ? kAoAlchemyDefaultBias : t == AoTechnique::Scalable ? kAoScalableDefaultBias : 0.0f;
    // The article's range of 1 world unit at the default radius (0.5), in units of the radius.
    s.crease.range = 2.0f, s.crease.bias = 0.25f;
    if (t == AoTechnique::Scalable) s.sumExponent = kAoScalableCourseSumExponent;
    s.radiusExponent = 0.0f;  // one intensity at every radius
    return s;
}

AoSettings tierLook(AoTechnique t, const TierProfile& profile) {
    AoSettings s = paperLook(t);
    const AoLook& look = profile.aoLook[uint32_t(t)];
    s.intensity = look.intensity, s.contrast = look.contrast;
    if (t != AoTechnique::Crease) s.bias = look.bias;
    if (t == AoTechnique::Scalable) s.sumExponent = look.sumExponent;
    s.crease.range = look.creaseRange, s.crease.bias = look.creaseBias;
    s.radiusExponent = look.radiusExponent;
    return s;
}

std::string describeLook(const AoSettings& s) {
    std::ostringstream o;
    for (const LookParameter& p : lookParametersOf(s.technique.value())) o << (o.tellp() ? ", " : "") << p.name << " " << p.of(s);
    if (s.radiusExponent.value_or(0.0f) != 0.0f) o << ", radius exponent " << *s.radiusExponent;
    return o.str();
}

double LookSearch::objective(const AoScore& s) const {
    const double excess = brightLimit < 0 ? 0.0 : std::max(0.0, s.signedOccluded - brightLimit);
    return frameWeight * s.psnr + s.psnrOccluded - kBrightPenaltyDb * excess;
}

namespace {

struct FittedLook {
    AoSettings settings;
    AoScore score;  // the search's own evaluation of it: a caller comparing fits need not score it again
};

// The step halves from 1/8 of the range each level; after the moves along each axis a jump
// along the move just made follows (the intensity-contrast ridge is diagonal).
Result<FittedLook> fitLook(const LookScorer& score, const AoSettings& start, const LookSearch& search, const std::string& label) {
    const std::vector<LookParameter> params = lookParametersOf(start.technique.value());
    auto settingsAt = [&](const std::vector<double>& u) {
        AoSettings s = start;
        for (size_t i = 0; i < params.size(); ++i) params[i].of(s) = float(params[i].fromUnit(u[i]));
        return s;
    };
    std::vector<double> best;
    for (const LookParameter& p : params) best.push_back(p.toUnit(p.of(start)));
    Result<AoScore> first = score(start);
    if (!first) return first.status();
    size_t evaluations = 1;
    AoScore bestScore = first.value();
    // Scores the point u (clamped to the cube); keeps it when better. *improved says so.
    auto tryPoint = [&](std::vector<double> u, bool* improved) -> Status {
        for (double& x : u) x = std::clamp(x, 0.0, 1.0);
        *improved = false;
        if (u == best) return Status::ok();  // at a bound: nothing new
        Result<AoScore> r = score(settingsAt(u));
        if (!r) return r.status();
        ++evaluations;
        if (search.objective(r.value()) > search.objective(bestScore) + 1e-6) bestScore = r.value(), best = u, *improved = true;
        return Status::ok();
    };
    auto progress = [&](const std::string& stage) {
        std::cout << "  " << label << " " << stage << ": " << describeLook(settingsAt(best)) << " -> training objective "
                  << fixed(search.objective(bestScore), 2) << " dB, signed error occluded " << fixed(bestScore.signedOccluded, 3) << " ("
                  << evaluations << " evaluations)" << std::endl;
    };
    progress("start");
    bool improved = false;
    for (size_t i = 0; i < params.size(); ++i)
        for (int k = 0; k <= 4; ++k) {
            std::vector<double> u = best;
            u[i] = k / 4.0;
            SFX_TRY(tryPoint(u, &improved));
        }
    progress("coarse");
    double step = 1.0 / 8.0;
    for (uint32_t level = 0; level < search.refinements; ++level, step *= 0.5) {
        for (int round = 0; round < 4; ++round) {
            const std::vector<double> base = best;
            for (size_t i = 0; i < params.size(); ++i)
                for (double direction : {1.0, -1.0}) {
                    std::vector<double> u = best;
                    u[i] += direction * step;
                    SFX_TRY(tryPoint(u, &improved));
                    if (improved) break;  // the other direction goes back
                }
            if (best == base) break;
            std::vector<double> jump = best;
            for (size_t i = 0; i < jump.size(); ++i) jump[i] += best[i] - base[i];
            SFX_TRY(tryPoint(jump, &improved));
        }
        progress("fine, step " + fixed(step, 4));
    }
    return FittedLook{settingsAt(best), bestScore};
}

}  // namespace

Result<AoSettings> searchLook(const LookScorer& score, const AoSettings& start, const LookSearch& search, const std::string& label) {
    Result<FittedLook> fitted = fitLook(score, start, search, label);
    if (!fitted) return fitted.status();
    return fitted->settings;
}

Result<AoSettings> searchLookFrom(const LookScorer& score, const std::vector<AoSettings>& starts, const LookSearch& search,
                                  const std::string& label) {
    if (starts.empty()) return invalidArgument("searchLookFrom starts", "empty", "at least one look");
    std::optional<FittedLook> best;
    for (size_t i = 0; i < starts.size(); ++i) {
        const std::string from = starts.size() > 1 ? label + " (start " + std::to_string(i + 1) + " of " + std::to_string(starts.size()) + ")"
                                                   : label;
        Result<FittedLook> fitted = fitLook(score, starts[i], search, from);
        if (!fitted) return fitted.status();
        if (!best || search.objective(fitted->score) > search.objective(best->score) + 1e-6) best = fitted.value();
    }
    return best->settings;
}

}  // namespace sfx::tools
