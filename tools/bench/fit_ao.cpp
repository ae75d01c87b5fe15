// fit_ao: calibrates the AO techniques' default settings against ray-traced ground truth.
// For each tier x technique it searches intensity and contrast (and Alchemy's and
// Scalable's bias and sum exponent, crease's range and bias; horizon's one parameter, a power on
// its visibility) coarse to fine, maximising the mean PSNR over the
// frame (weighed by --frame-weight) plus the mean PSNR where the truth is below 0.95, less a penalty where the mean signed
// error there passes --bright-limit (too bright in contacts), on the views of the TRAINING scene
// families (tools/scenes/scene_families.*) at each view's radius with the blur on (the
// default); then it scores the fitted settings and today's defaults on the HELD-OUT families,
// whose kind of geometry the search never saw, each family on its own as well. Writes
// <out-dir>/ao_fit.csv and the tables into <out-dir>/trade.md between its markers. With
// --leave-one-out it measures instead how the fit generalises, one family left out at a time
// (ao_leave_one_out.hpp): <out-dir>/ao_loo.csv and its section of <out-dir>/ao_families.md. The
// search is tools/bench/common/ao_look_search.*. --epsilon holds AoSettings::epsilon (Alchemy's
// falloff guard) at a value through the fit (docs/ao_families.md measures it as a look
// parameter); --radius-exponent holds AoSettings::radiusExponent (A) for every start. --diagnose
// --solid-sheet scores the held-out thin views with a solid block in place of the sheet on legs,
// to tell what the sheet costs from the rest. The truth comes from the same cache as
// bench_trade. A program, not a test.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "ao_leave_one_out.hpp"
#include "ao_look_search.hpp"
#include "ao_scoring.hpp"
#include "bench_device.hpp"
#include "markdown_section.hpp"
#include "scene_families.hpp"
#include "sfx/ao.hpp"
#include "sfx/tiers.hpp"
#include "sfx/truth_metrics.hpp"
#include "trade_views.hpp"

using namespace sfx;

namespace {

using tools::fixed;

struct Options {
    uint32_t width = 320, height = 180, samples = 256;
    std::vector<double> trainingRadii, heldOutRadii;  // none: each view's own
    std::string backend = "vulkan";
    std::vector<std::string> techniques{"alchemy", "scalable", "crease"};
    std::string cacheDir = "build/truth-cache", outDir = "docs";
    std::vector<std::string> tiers{"high", "current"};
    bool diagnose = false;        // score the tier defaults' variants instead of fitting
    bool solidSheet = false;      // --diagnose: the held-out thin views with a solid block for the sheet
    std::string start = "paper";  // where the search starts: the papers' look, the tier table's, or both (the better fit)
    tools::LookSearch search;
    bool leaveOneOut = false;             // fit on every family and on every family but one, score each
    std::vector<std::string> variants;    // --diagnose: only the variants whose names contain one of these (none: all)
    std::optional<float> epsilon;         // AoSettings::epsilon for the fit (unset: the settings' default)
    std::optional<float> radiusExponent;  // AoSettings::radiusExponent of every start; unset: the tier table's look's
};

// Each family's score from a run's comparisons (one per case; AoCase::view indexes `views`).
std::map<std::string, tools::AoScore> byFamily(const std::vector<truth::Comparison>& errors, const std::vector<tools::AoCase>& cases,
                                               const std::vector<tools::TradeView>& views) {
    std::map<std::string, std::vector<truth::Comparison>> split;
    for (size_t i = 0; i < cases.size(); ++i) split[views[cases[i].view].family].push_back(errors[i]);
    std::map<std::string, tools::AoScore> scores;
    for (const auto& [family, e] : split) scores[family] = tools::summarise(e);
    return scores;
}

// The fitted settings' score on each held-out family's cases.
Result<std::map<std::string, tools::AoScore>> scoreByFamily(tools::AoEvaluator& ev, const AoSettings& settings,
                                                            const std::vector<tools::AoCase>& cases, const std::vector<tools::TradeView>& views) {
    Result<std::vector<truth::Comparison>> errors = ev.run(settings, cases);
    if (!errors) return errors.status();
    return byFamily(errors.value(), cases, views);
}

// Where a technique's error at the tier's defaults comes from: the held-out score of the default
// and of variants that each change one thing (no blur: how much noise the blur hides; 4x the
// taps: the noise left; full resolution: what half resolution costs; no screen-radius clamp),
// each held-out view's score after its families'.
Status diagnose(tools::AoEvaluator& ev, Tier tier, AoTechnique technique, const std::vector<tools::AoCase>& training,
                const std::vector<tools::AoCase>& heldOut, const std::vector<tools::TradeView>& views, const std::vector<std::string>& only) {
    const TierProfile base = tiers::choose(ev.device().caps(), tier)->profile;
    const tools::AoScore none = tools::noAoScore(heldOut);  // the baseline of the 4 dB accuracy goal
    struct Variant {
        std::string name;
        std::function<void(AoSettings&, TierProfile&)> apply;
    };
    std::vector<Variant> variants{
        {"default", [](AoSettings&, TierProfile&) {}},
        // The looks the leave-one-out run fitted on all five families (docs/ao_loo.csv), darker
        // than the table's where the truth is occluded and turned down by the adoption rule.
        {"every-family look",
         [tier](AoSettings&, TierProfile& p) {
             const bool high = tier == Tier::High;
             // alchemy, with the intensity it was fitted beside and one intensity at every radius
             p.aoLook[0] = {.intensity = high ? 0.392128f : 0.472871f, .contrast = high ? 2.05353f : 1.59634f, .bias = high ? 1e-7f : 1.59371e-7f};
             p.aoLook[1].intensity = high ? 0.223607f : 0.0789174f;  // scalable
             if (high) p.aoLook[1].bias = 0.0625002f;
         }},
        {"blur off", [](AoSettings& s, TierProfile&) { s.blur = false; }},
        {"4x taps",
         [&](AoSettings& s, TierProfile& p) {
             if (technique == AoTechnique::Horizon) {
                 s.horizon.slices = 2 * p.aoHorizonSlices, s.horizon.steps = 2 * p.aoHorizonSteps;
             } else if (technique != AoTechnique::Crease) {
                 s.samples = std::min(64u, 4 * (technique == AoTechnique::Alchemy ? p.aoAlchemySamples : p.aoScalableTaps));
             }
         }},
        {"horizon slices +1", [](AoSettings&, TierProfile& p) { p.aoHorizonSlices += 1; }},
        {"horizon steps x2", [](AoSettings&, TierProfile& p) { p.aoHorizonSteps *= 2; }},
        {"horizon thickness 0.8", [](AoSettings&, TierProfile& p) { p.aoHorizonThickness = 0.8f; }},
        {"horizon falloff 0.1", [](AoSettings&, TierProfile& p) { p.aoHorizonFalloff = 0.1f; }},
        {"horizon falloff 0.4", [](AoSettings&, TierProfile& p) { p.aoHorizonFalloff = 0.4f; }},
        {"full resolution", [](AoSettings& s, TierProfile&) { s.resolution = AoResolution::Full; }},
        {"no radius clamp", [](AoSettings&, TierProfile& p) { p.aoScalableMaxRadiusPx = 0; }},
        {"radius clamp doubled", [](AoSettings&, TierProfile& p) { p.aoScalableMaxRadiusPx *= 2; }},
    };
    // Horizon's counts and falloff as a grid, the same on both tiers: its defaults are chosen on
    // the training score (docs/ao_families.md states the rule).
    if (technique == AoTechnique::Horizon)
        for (uint32_t slices : {2u, 3u, 4u})
            for (uint32_t steps : {4u, 6u, 8u, 12u})
                for (float falloff : {0.2f, 0.1f, 0.05f, 0.02f}) {
                    variants.push_back(
                        {"grid " + std::to_string(slices) + "x" + std::to_string(steps) + " falloff " + fixed(falloff, 2),
                         [=](AoSettings&, TierProfile& p) { p.aoHorizonSlices = slices, p.aoHorizonSteps = steps, p.aoHorizonFalloff = falloff; }});
                }
    // Horizon with a power p on its visibility (the look's contrast; intensity stays 1), and
    // without the depth MIP (every step at the pass's size), the tier's other defaults.
    if (technique == AoTechnique::Horizon) {
        for (float k : {1.1f, 1.2f, 1.3f, 1.4f, 1.5f})
            variants.push_back({"horizon power " + fixed(k, 2), [=](AoSettings&, TierProfile& p) { p.aoLook[3].contrast = k; }});
        variants.push_back({"horizon no depth MIP", [](AoSettings&, TierProfile& p) { p.aoDepthMipLevels = 1; }});
    }
    for (const Variant& v : variants) {
        if (!only.empty() && std::none_of(only.begin(), only.end(), [&](const std::string& o) { return v.name.find(o) != std::string::npos; }))
            continue;
        AoSettings s;
        s.technique = technique;
        s.normals = AoNormals::FromTexture;
        TierProfile p = base;
        v.apply(s, p);
        ev.setProfile(p);
        // One run of each set: its mean and each family's.
        Result<std::vector<truth::Comparison>> te = ev.run(s, training);
        if (!te) return te.status();
        Result<std::vector<truth::Comparison>> re = ev.run(s, heldOut);
        if (!re) return re.status();
        const tools::AoScore t = tools::summarise(te.value()), r = tools::summarise(re.value());
        std::map<std::string, tools::AoScore> families = byFamily(te.value(), training, views);
        families.merge(byFamily(re.value(), heldOut, views));
        std::cout << "  diagnose " << toString(tier) << "/" << toString(technique) << " " << v.name << ": training " << fixed(t.psnr, 2) << " / "
                  << fixed(t.psnrOccluded, 2) << " dB, held out " << fixed(r.psnr, 2) << " / " << fixed(r.psnrOccluded, 2)
                  << " dB, signed error occluded " << fixed(r.signedOccluded, 3) << ", gain over no AO occluded "
                  << fixed(r.psnrOccluded - none.psnrOccluded, 2) << " dB, training signed error occluded " << fixed(t.signedOccluded, 3) << ";";
        for (const auto& [family, f] : families)
            std::cout << " " << family << " " << fixed(f.psnr, 2) << " / " << fixed(f.psnrOccluded, 2) << " / " << fixed(f.signedOccluded, 3) << ";";
        std::cout << std::endl;
        for (size_t i = 0; i < heldOut.size(); ++i) {
            const tools::AoScore one = tools::summarise({re.value()[i]});
            std::cout << "    " << views[heldOut[i].view].name() << ": " << fixed(one.psnr, 2) << " / " << fixed(one.psnrOccluded, 2) << " / "
                      << fixed(one.signedOccluded, 3) << std::endl;
        }
    }
    ev.setProfile(base);
    return Status::ok();
}

struct FitRow {
    std::string tier, technique, fitted;
    AoSettings settings;
    tools::AoScore before, trainingScore, heldOut;
    std::map<std::string, tools::AoScore> heldOutFamilies;  // the fitted settings on each held-out family
};

std::string markdown(const Options& o, const std::vector<FitRow>& rows, const std::map<std::string, tools::AoScore>& none,
                     const std::vector<tools::TradeView>& training, const std::vector<tools::TradeView>& heldOut, const std::string& machine) {
    std::ostringstream md;
    auto list = [](const std::vector<tools::TradeView>& views) {
        std::string s;
        for (const tools::TradeView& v : views) s += (s.empty() ? "`" : ", `") + v.name() + "`";
        return s;
    };
    md << "Fitted by `build/tools/bench/fit_ao` on " << machine << "; " << o.width << "x" << o.height << ", blur on, G-buffer normals, truth "
       << o.samples << " directions per pixel.\n\nTraining views (radii";
    for (double r : o.trainingRadii) md << " " << r;
    if (o.trainingRadii.empty()) md << " of each view, docs/ao_families.md";
    md << "): " << list(training) << ".\n\nHeld-out views (radii";
    for (double r : o.heldOutRadii) md << " " << r;
    if (o.heldOutRadii.empty()) md << " of each view";
    md << "): " << list(heldOut) << ".\n\n";
    md << "| tier | technique | fitted defaults | training PSNR / occluded | held-out PSNR / occluded (before the fit) | held-out worst case "
          "PSNR / occluded | held-out signed error occluded | gain over no AO, occluded | per held-out family PSNR / occluded |\n| --- | --- | --- | "
          "--- | --- | --- | --- | --- | --- |\n";
    for (const FitRow& r : rows) {
        md << "| " << r.tier << " | " << r.technique << " | " << r.fitted << " | " << fixed(r.trainingScore.psnr, 2) << " / "
           << fixed(r.trainingScore.psnrOccluded, 2) << " | " << fixed(r.heldOut.psnr, 2) << " / " << fixed(r.heldOut.psnrOccluded, 2) << " ("
           << fixed(r.before.psnr, 2) << " / " << fixed(r.before.psnrOccluded, 2) << ") | " << fixed(r.heldOut.worstPsnr, 2) << " / "
           << fixed(r.heldOut.worstPsnrOccluded, 2) << " | " << fixed(r.heldOut.signedOccluded, 3) << " | "
           << fixed(r.heldOut.psnrOccluded - none.at("held-out").psnrOccluded, 2) << " dB |";
        for (const auto& [family, score] : r.heldOutFamilies)
            md << " " << family << " " << fixed(score.psnr, 2) << " / " << fixed(score.psnrOccluded, 2) << ";";
        md << " |\n";
    }
    md << "| - | none | visibility 1 | " << fixed(none.at("training").psnr, 2) << " / " << fixed(none.at("training").psnrOccluded, 2) << " | "
       << fixed(none.at("held-out").psnr, 2) << " / " << fixed(none.at("held-out").psnrOccluded, 2) << " | "
       << fixed(none.at("held-out").worstPsnr, 2) << " / " << fixed(none.at("held-out").worstPsnrOccluded, 2) << " | "
       << fixed(none.at("held-out").signedOccluded, 3) << " | 0 | - |\n";
    return md.str();
}

// The leave-one-out run's CSV and its section of <out-dir>/ao_families.md.
bool writeLeaveOneOut(const Options& o, const std::vector<tools::LeaveOneOut>& runs, const std::vector<tools::AoCase>& cases,
                      const std::vector<tools::TradeView>& views, const std::string& machine, double seconds) {
    if (runs.empty()) return false;
    std::map<std::string, std::vector<tools::AoCase>> byFamily;
    for (const tools::AoCase& c : cases) byFamily[views[c.view].family].push_back(c);
    std::map<std::string, tools::AoScore> none;
    for (const auto& [family, c] : byFamily) none[family] = tools::noAoScore(c);
    std::filesystem::create_directories(o.outDir);
    std::ofstream(o.outDir + "/ao_loo.csv") << tools::leaveOneOutCsv(runs);
    if (Status st = tools::replaceMarkdownSection(
            o.outDir + "/ao_families.md", "fit_ao_loo",
            tools::leaveOneOutMarkdown(
                runs, none, machine, seconds,
                o.start == "both" ? "the tier table's look and the papers' look, the better fit kept" : "the tier table's look"));
        !st) {
        std::cerr << "fit_ao: " << st.toString() << "\n";
        return false;
    }
    std::cout << "fit_ao: " << runs.size() << " leave-one-out runs -> " << o.outDir << "/ao_loo.csv and " << o.outDir << "/ao_families.md in "
              << fixed(seconds, 1) << " s" << std::endl;
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"fit_ao - calibrates the AO defaults against ray-traced ground truth", "fit_ao"};
    app.add_option("--width", o.width, "pixels")->capture_default_str();
    app.add_option("--height", o.height, "pixels")->capture_default_str();
    app.add_option("--samples", o.samples, "truth directions per pixel (a square >= 256)")->capture_default_str();
    app.add_option("--training-radii", o.trainingRadii, "comma-separated world-space radii of the training views (none: each view's own)")
        ->delimiter(',')
        ->capture_default_str();
    app.add_option("--held-out-radii", o.heldOutRadii, "comma-separated radii of the held-out views (none: each view's own)")
        ->delimiter(',')
        ->capture_default_str();
    app.add_option("--backend", o.backend, "vulkan, gles, gl, gl-egl, gl-osmesa (the backends agree)")->capture_default_str();
    app.add_option("--techniques", o.techniques, "comma-separated: alchemy, scalable, crease, horizon (horizon's look: a power on its visibility)")
        ->delimiter(',')
        ->capture_default_str();
    app.add_option("--refinements", o.search.refinements, "halvings of the fine search's step")->capture_default_str();
    app.add_option("--tiers", o.tiers, "comma-separated: high, current")->delimiter(',')->capture_default_str();
    app.add_option("--start", o.start,
                   "where the search starts: paper (the papers' look), tier (the tier table's) or both (a search from each, the better "
                   "objective kept); --leave-one-out: tier or both")
        ->check(CLI::IsMember({"paper", "tier", "both"}))
        ->capture_default_str();
    app.add_option("--bright-limit", o.search.brightLimit,
                   "training mean signed error where occluded above which the objective pays " + fixed(tools::kBrightPenaltyDb, 0) +
                       " dB per unit (< 0: none)")
        ->capture_default_str();
    app.add_option("--frame-weight", o.search.frameWeight, "the objective: this x frame PSNR + PSNR where occluded (0: occluded only)")
        ->capture_default_str();
    app.add_option("--epsilon", o.epsilon, "AoSettings::epsilon during the fit, in units of radius^2 (unset: the settings' default)");
    app.add_option("--radius-exponent", o.radiusExponent,
                   "A, AoSettings::radiusExponent of every start (intensity times (r / 0.5 m)^-A; the families are in metres), [0, 2]; "
                   "not given: the tier table's look's")
        ->check(CLI::Range(0.0, 2.0));
    app.add_flag("--leave-one-out", o.leaveOneOut,
                 "fit on every family and on every family but one (from --start), score each family under each "
                 "(<out-dir>/ao_loo.csv, ao_families.md)");
    app.add_flag("--diagnose", o.diagnose, "score variants of the tier defaults on the training and the held-out views instead of fitting");
    app.add_flag("--solid-sheet", o.solidSheet,
                 "--diagnose: the held-out thin views with a solid block of the sheet's footprint and height in place of the sheet and its legs");
    app.add_option("--variants", o.variants, "--diagnose: comma-separated parts of the variants' names to run (none: every variant)")->delimiter(',');
    app.add_option("--cache-dir", o.cacheDir, "where truth images are cached")->capture_default_str();
    app.add_option("--out-dir", o.outDir, "ao_fit.csv and trade.md (tables between its fit_ao markers)")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    if (o.leaveOneOut && o.start == "paper") {
        std::cerr << "fit_ao: --start paper with --leave-one-out: allowed tier or both (the tier table's look is what the fits are judged against)\n";
        return 2;
    }
    if (o.solidSheet && !o.diagnose) {
        std::cerr << "fit_ao: --solid-sheet: allowed only with --diagnose (the families a fit is judged on keep their sheet)\n";
        return 2;
    }
    const auto started = std::chrono::steady_clock::now();
    auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
    auto elapsed = [&] { return fixed(seconds(), 1); };

    const std::vector<tools::TradeView> trainingViews = tools::familyViews(false);
    std::vector<tools::TradeView> heldOutViews = tools::familyViews(true);
    if (o.solidSheet) std::transform(heldOutViews.begin(), heldOutViews.end(), heldOutViews.begin(), tools::withSolidSheet);
    std::vector<tools::TradeView> views = trainingViews;
    views.insert(views.end(), heldOutViews.begin(), heldOutViews.end());
    auto progress = [&](const std::string& line) { std::cout << "[" << elapsed() << " s] " << line << std::endl; };
    const tools::TruthSettings truthSettings{o.width, o.height, o.samples, o.cacheDir};
    Result<std::vector<tools::AoCase>> training = tools::loadCases(views, 0, trainingViews.size(), o.trainingRadii, truthSettings, progress);
    Result<std::vector<tools::AoCase>> heldOut = training
        ? tools::loadCases(views, trainingViews.size(), views.size(), o.heldOutRadii, truthSettings, progress)
        : training;
    if (!heldOut) {
        std::cerr << "fit_ao: " << heldOut.status().toString() << "\n";
        return 1;
    }
    std::map<std::string, tools::AoScore> none{{"training", tools::noAoScore(training.value())}, {"held-out", tools::noAoScore(heldOut.value())}};

    BackendConfig config;
    if (!parseBackendConfig(o.backend, &config)) {
        std::cerr << "fit_ao: --backend: unknown backend '" << o.backend << "'\n";
        return 1;
    }
    std::vector<FitRow> rows;
    std::vector<tools::LeaveOneOut> looRuns;
    std::vector<tools::AoCase> allCases = training.value();
    if (o.leaveOneOut) allCases.insert(allCases.end(), heldOut->begin(), heldOut->end());
    std::string machine;
    for (Tier tier : {Tier::High, Tier::Current}) {
        if (std::find(o.tiers.begin(), o.tiers.end(), toString(tier)) == o.tiers.end()) continue;
        Result<std::unique_ptr<Device>> dev = tools::openForTier(config, tier);
        if (!dev) {
            std::cout << "fit_ao: skipping " << toString(tier) << ": " << dev.status().toString() << std::endl;
            continue;
        }
        if (machine.empty()) machine = dev.value()->caps().deviceName;
        std::cout << "[" << elapsed() << " s] " << dev.value()->caps().summary() << ", tier " << toString(tier) << std::endl;
        tools::AoEvaluator ev(*dev.value(), tier, o.width, o.height);
        if (Status st = ev.prepare(views); !st) {
            std::cerr << "fit_ao: " << st.toString() << "\n";
            return 1;
        }
        for (const std::string& name : o.techniques) {
            AoTechnique technique;
            if (!parseAoTechnique(name, &technique)) {
                std::cerr << "fit_ao: --techniques: unknown technique '" << name << "'\n";
                return 1;
            }
            const std::string label = std::string(toString(tier)) + "/" + name;
            if (o.diagnose) {
                if (Status st = diagnose(ev, tier, technique, training.value(), heldOut.value(), views, o.variants); !st) {
                    std::cerr << "fit_ao: " << label << ": " << st.toString() << "\n";
                    return 1;
                }
                continue;
            }
            // The tier table's look first: it is the look a fit is judged against (and the search's
            // "before"), and with --start both a tie keeps it.
            std::vector<AoSettings> starts;
            const AoSettings tableLook = tools::tierLook(technique, tiers::choose(dev.value()->caps(), tier)->profile);
            if (o.start != "paper") starts.push_back(tableLook);
            if (o.start != "tier") starts.push_back(tools::paperLook(technique));
            // A is chosen, not searched: every start shares it (docs/ao_families.md says how it was chosen).
            for (AoSettings& s : starts) {
                if (o.epsilon) s.epsilon = *o.epsilon;
                s.radiusExponent = o.radiusExponent.value_or(tableLook.radiusExponent.value());
            }
            const AoSettings& start = starts.front();
            if (o.leaveOneOut) {
                Result<tools::LeaveOneOut> r = tools::leaveOneOut(ev, views, allCases, starts, o.search, label);
                if (!r) {
                    std::cerr << "fit_ao: " << label << ": " << r.status().toString() << "\n";
                    return 1;
                }
                looRuns.push_back(r.value());
                progress(label + ": leave-one-out done");
                continue;
            }
            Result<AoSettings> fitted = tools::searchLookFrom([&](const AoSettings& s) { return ev.score(s, training.value()); }, starts, o.search,
                                                              label);
            Result<tools::AoScore> before = fitted ? ev.score(start, heldOut.value()) : Result<tools::AoScore>(fitted.status());
            Result<tools::AoScore> trained = before ? ev.score(fitted.value(), training.value()) : Result<tools::AoScore>(before.status());
            Result<tools::AoScore> held = trained ? ev.score(fitted.value(), heldOut.value()) : Result<tools::AoScore>(trained.status());
            if (!held) {
                std::cerr << "fit_ao: " << label << ": " << held.status().toString() << "\n";
                return 1;
            }
            Result<std::map<std::string, tools::AoScore>> families = scoreByFamily(ev, fitted.value(), heldOut.value(), views);
            if (!families) {
                std::cerr << "fit_ao: " << label << ": " << families.status().toString() << "\n";
                return 1;
            }
            rows.push_back({toString(tier), name, tools::describeLook(fitted.value()), fitted.value(), before.value(), trained.value(), held.value(),
                            families.value()});
            std::cout << "[" << elapsed() << " s] " << label << ": " << rows.back().fitted << "; held out " << fixed(held->psnr, 2)
                      << " dB, occluded " << fixed(held->psnrOccluded, 2) << " dB (before the fit " << fixed(before->psnr, 2) << " / "
                      << fixed(before->psnrOccluded, 2) << "; no AO " << fixed(none["held-out"].psnr, 2) << " / "
                      << fixed(none["held-out"].psnrOccluded, 2) << ")" << std::endl;
        }
    }
    if (o.diagnose) return 0;
    if (o.leaveOneOut) return writeLeaveOneOut(o, looRuns, allCases, views, machine, seconds()) ? 0 : 1;
    std::filesystem::create_directories(o.outDir);
    std::ofstream csv(o.outDir + "/ao_fit.csv");
    csv << "tier,technique,intensity,contrast,bias,sum_exponent,crease_range,crease_bias,radius_exponent,training_psnr_db,training_psnr_occluded_db,"
           "heldout_psnr_db,heldout_psnr_occluded_db,heldout_signed_error_occluded,before_heldout_psnr_db,before_heldout_psnr_occluded_db,"
           "none_heldout_psnr_db,none_heldout_psnr_occluded_db\n";
    for (const FitRow& r : rows) {
        const AoSettings& rs = r.settings;
        csv << r.tier << "," << r.technique << "," << rs.intensity.value() << "," << rs.contrast.value() << "," << rs.bias.value() << ","
            << (rs.technique == AoTechnique::Scalable ? rs.sumExponent.value() : -1.0f) << "," << rs.crease.range.value() << ","
            << rs.crease.bias.value() << "," << rs.radiusExponent.value() << "," << fixed(r.trainingScore.psnr, 3) << ","
            << fixed(r.trainingScore.psnrOccluded, 3) << "," << fixed(r.heldOut.psnr, 3) << "," << fixed(r.heldOut.psnrOccluded, 3) << ","
            << fixed(r.heldOut.signedOccluded, 4) << "," << fixed(r.before.psnr, 3) << "," << fixed(r.before.psnrOccluded, 3) << ","
            << fixed(none["held-out"].psnr, 3) << "," << fixed(none["held-out"].psnrOccluded, 3) << "\n";
    }
    if (Status st = tools::replaceMarkdownSection(o.outDir + "/trade.md", "fit_ao",
                                                  markdown(o, rows, none, trainingViews, heldOutViews, machine.empty() ? "no device" : machine));
        !st) {
        std::cerr << "fit_ao: " << st.toString() << "\n";
        return 1;
    }
    std::cout << "fit_ao: " << rows.size() << " fits -> " << o.outDir << "/ao_fit.csv and " << o.outDir << "/trade.md in " << elapsed() << " s"
              << std::endl;
    return rows.empty() ? 1 : 0;
}
