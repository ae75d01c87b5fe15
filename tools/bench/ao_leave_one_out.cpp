#include "ao_leave_one_out.hpp"

#include <algorithm>
#include <cstring>
#include <iostream>
#include <optional>
#include <sstream>

#include "markdown_section.hpp"

namespace sfx::tools {

namespace {

// Every case's comparison at each look the searches tried: the fits of one tier x technique
// start at the same look and cross each other's paths, and scoring a fitted look on its
// left-out family needs only the cases it was not fitted on.
class CaseMemo {
public:
    CaseMemo(AoEvaluator& ev, const std::vector<AoCase>& cases) : ev_(ev), cases_(cases) {}

    Result<std::vector<truth::Comparison>> run(const AoSettings& s, const std::vector<size_t>& which) {
        std::vector<std::optional<truth::Comparison>>& known = memo_[key(s)];
        known.resize(cases_.size());
        std::vector<AoCase> missing;
        std::vector<size_t> missingIndex;
        for (size_t i : which)
            if (!known[i]) missing.push_back(cases_[i]), missingIndex.push_back(i);
        if (!missing.empty()) {
            Result<std::vector<truth::Comparison>> e = ev_.run(s, missing);
            if (!e) return e.status();
            for (size_t k = 0; k < missingIndex.size(); ++k) known[missingIndex[k]] = e.value()[k];
        }
        std::vector<truth::Comparison> out;
        for (size_t i : which) out.push_back(*known[i]);
        return out;
    }
    Result<AoScore> score(const AoSettings& s, const std::vector<size_t>& which) {
        Result<std::vector<truth::Comparison>> e = run(s, which);
        if (!e) return e.status();
        return summarise(e.value());
    }

private:
    // The searched fields' bits: two looks the search reaches by different paths are one look.
    static std::string key(const AoSettings& s) {
        std::string k;
        for (const LookParameter& p : lookParametersOf(s.technique.value())) {
            const float v = p.of(s);
            char bits[sizeof v];
            std::memcpy(bits, &v, sizeof v);
            k.append(bits, sizeof v);
        }
        return k;
    }
    AoEvaluator& ev_;
    const std::vector<AoCase>& cases_;
    std::map<std::string, std::vector<std::optional<truth::Comparison>>> memo_;
};

bool isHeldOut(const std::string& family) {
    for (const SceneFamily& f : sceneFamilies())
        if (f.name == family) return f.heldOut;
    return false;
}

std::string pair(const AoScore& s) { return fixed(s.psnr, 2) + " / " + fixed(s.psnrOccluded, 2); }

// What the fit that saw F gains on F over the fit that did not, frame and occluded.
std::pair<double, double> gapOf(const LeaveOneOut& r, const std::string& family) {
    const AoScore& with = r.allFamilies.families.at(family);
    const AoScore& without = r.without.at(family).families.at(family);
    return {with.psnr - without.psnr, with.psnrOccluded - without.psnrOccluded};
}

// The adoption rule against the tier table's look: the training families' objective rises by
// kAdoptionDb and no held-out family falls by it, frame or occluded. Below it a change is one the
// tables do not show (a bias moving between 1e-7 and 2e-7). Empty when it holds, else what breaks it.
constexpr double kAdoptionDb = 0.01;
std::string breaksAdoption(const ScoredLook& look, const ScoredLook& table) {
    std::string why;
    const double rise = look.training.objective() - table.training.objective();
    if (rise < kAdoptionDb) why = "training objective " + fixed(rise, 2);
    for (const auto& [family, s] : look.families) {
        if (!isHeldOut(family)) continue;
        const AoScore& t = table.families.at(family);
        if (s.psnr <= t.psnr - kAdoptionDb) why += (why.empty() ? "" : ", ") + family + " frame " + fixed(s.psnr - t.psnr, 2);
        if (s.psnrOccluded <= t.psnrOccluded - kAdoptionDb)
            why += (why.empty() ? "" : ", ") + family + " occluded " + fixed(s.psnrOccluded - t.psnrOccluded, 2);
    }
    return why;
}

}  // namespace

Result<LeaveOneOut> leaveOneOut(AoEvaluator& ev, const std::vector<TradeView>& views, const std::vector<AoCase>& cases,
                                const std::vector<AoSettings>& starts, const LookSearch& search, const std::string& label) {
    if (starts.empty()) return invalidArgument("leaveOneOut starts", "empty", "the tier table's look, then any others");
    const AoSettings& start = starts.front();
    CaseMemo memo(ev, cases);
    std::vector<size_t> all, training;
    std::map<std::string, std::vector<size_t>> byFamily;
    for (size_t i = 0; i < cases.size(); ++i) {
        const std::string& family = views[cases[i].view].family;
        all.push_back(i), byFamily[family].push_back(i);
        if (!isHeldOut(family)) training.push_back(i);
    }
    auto scored = [&](const AoSettings& s) -> Result<ScoredLook> {
        ScoredLook look{s, {}, {}};
        for (const auto& [family, which] : byFamily) {
            Result<AoScore> r = memo.score(s, which);
            if (!r) return r.status();
            look.families[family] = r.value();
        }
        Result<AoScore> t = memo.score(s, training);
        if (!t) return t.status();
        look.training = t.value();
        return look;
    };
    auto fitOn = [&](const std::vector<size_t>& which, const std::string& what) -> Result<ScoredLook> {
        Result<AoSettings> fitted = searchLookFrom([&](const AoSettings& s) { return memo.score(s, which); }, starts, search, label + " " + what);
        if (!fitted) return fitted.status();
        return scored(fitted.value());
    };
    LeaveOneOut r;
    r.tier = label.substr(0, label.find('/')), r.technique = toString(start.technique.value());
    Result<ScoredLook> table = scored(start);
    if (!table) return table.status();
    r.tierTable = table.value();
    Result<ScoredLook> allFamilies = fitOn(all, "on every family");
    if (!allFamilies) return allFamilies.status();
    r.allFamilies = allFamilies.value();
    for (const auto& [family, which] : byFamily) {
        std::vector<size_t> others;
        for (size_t i : all)
            if (views[cases[i].view].family != family) others.push_back(i);
        Result<ScoredLook> without = fitOn(others, "without " + family);
        if (!without) return without.status();
        r.without[family] = without.value();
        const auto [frame, occluded] = gapOf(r, family);
        std::cout << "  " << label << " " << family << ": with it " << pair(r.allFamilies.families.at(family)) << ", without it "
                  << pair(without->families.at(family)) << ", the table's look " << pair(r.tierTable.families.at(family)) << "; gap "
                  << fixed(frame, 2) << " / " << fixed(occluded, 2) << " dB" << std::endl;
    }
    return r;
}

std::string leaveOneOutMarkdown(const std::vector<LeaveOneOut>& runs, const std::map<std::string, AoScore>& none, const std::string& machine,
                                double seconds, const std::string& starts) {
    std::ostringstream md;
    std::vector<std::string> families;
    for (const SceneFamily& f : sceneFamilies()) families.push_back(f.name);
    md << "Measured by `build/tools/bench/fit_ao --leave-one-out` on " << machine << " in " << fixed(seconds / 60.0, 1)
       << " minutes; each fit searches from " << starts << ", with the search of the default run. Frame PSNR / PSNR where the truth < 0.95 (dB).\n\n";
    md << "The gap: a family's score under the look fitted on every family less its score under the look fitted on the other four.\n\n";
    md << "| tier | technique |";
    for (const std::string& f : families) md << " " << f << " |";
    md << " worst gap | within 0.5 dB |\n| --- | --- |";
    for (size_t i = 0; i < families.size(); ++i) md << " --- |";
    md << " --- | --- |\n";
    for (const LeaveOneOut& r : runs) {
        md << "| " << r.tier << " | " << r.technique << " |";
        double worstFrame = -1e9, worstOccluded = -1e9;
        for (const std::string& f : families) {
            const auto [frame, occluded] = gapOf(r, f);
            worstFrame = std::max(worstFrame, frame), worstOccluded = std::max(worstOccluded, occluded);
            md << " " << fixed(frame, 2) << " / " << fixed(occluded, 2) << " |";
        }
        md << " " << fixed(worstFrame, 2) << " / " << fixed(worstOccluded, 2) << " | " << (std::max(worstFrame, worstOccluded) <= 0.5 ? "yes" : "no")
           << " |\n";
    }
    md << "\nEach family's score under the tier table's look (what ships), under the look fitted on every family and under the look fitted "
          "without it; \"no AO\" is visibility 1:\n\n| tier | technique | family | no AO | the table's look | fitted with it | fitted without it "
          "|\n| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const LeaveOneOut& r : runs)
        for (const std::string& f : families)
            md << "| " << r.tier << " | " << r.technique << " | " << f << " | " << pair(none.at(f)) << " | " << pair(r.tierTable.families.at(f))
               << " | " << pair(r.allFamilies.families.at(f)) << " | " << pair(r.without.at(f).families.at(f)) << " |\n";
    md << "\nEvery fitted look against the adoption rule (the training families' frame + occluded PSNR rises over the table's look by 0.01 dB "
          "or more; no held-out family falls by as much, frame or occluded):\n\n| tier | technique | fitted | look | training | thin | meshes | "
          "independent | adoptable |\n| --- | --- "
          "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const LeaveOneOut& r : runs) {
        auto row = [&](const std::string& what, const ScoredLook& l) {
            const std::string why = what == "the table's" ? "-" : breaksAdoption(l, r.tierTable);
            md << "| " << r.tier << " | " << r.technique << " | " << what << " | " << describeLook(l.settings) << " | " << pair(l.training);
            for (const char* f : {"thin", "meshes", "independent"}) md << " | " << pair(l.families.at(f));
            md << " | " << (why.empty() ? "yes" : why == "-" ? "-" : "no: " + why) << " |\n";
        };
        row("the table's", r.tierTable);
        row("on every family", r.allFamilies);
        for (const auto& [family, look] : r.without) row("without " + family, look);
    }
    return md.str();
}

std::string leaveOneOutCsv(const std::vector<LeaveOneOut>& runs) {
    std::ostringstream csv;
    csv << "tier,technique,look,intensity,contrast,bias,sum_exponent,crease_range,crease_bias,family,psnr_db,psnr_occluded_db,signed_error_"
           "occluded\n";
    for (const LeaveOneOut& r : runs) {
        auto rows = [&](const std::string& what, const ScoredLook& l) {
            const AoSettings& s = l.settings;
            for (const auto& [family, score] : l.families)
                csv << r.tier << "," << r.technique << "," << what << "," << s.intensity.value() << "," << s.contrast.value() << "," << s.bias.value()
                    << "," << (s.technique == AoTechnique::Scalable ? s.sumExponent.value() : -1.0f) << "," << s.crease.range.value() << ","
                    << s.crease.bias.value() << "," << family << "," << fixed(score.psnr, 3) << "," << fixed(score.psnrOccluded, 3) << ","
                    << fixed(score.signedOccluded, 4) << "\n";
        };
        rows("table", r.tierTable);
        rows("all", r.allFamilies);
        for (const auto& [family, look] : r.without) rows("without-" + family, look);
    }
    return csv.str();
}

}  // namespace sfx::tools
