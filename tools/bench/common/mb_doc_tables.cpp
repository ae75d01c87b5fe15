#include "mb_doc_tables.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "markdown_section.hpp"

namespace sfx::tools {
namespace {

// Above this PSNR input, truth and output agree to float rounding: nothing to score.
constexpr double kExactDb = 60;

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
}

double number(const std::string& s) {
    if (s.empty() || s == "-") return NAN;
    if (s == "inf") return INFINITY;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    return end == s.c_str() ? NAN : v;
}

// "a / b" with one decimal each.
std::string pair1(double a, double b) { return fixedOrDash(a, 1) + " / " + fixedOrDash(b, 1); }

// The CPU reference's rows by (family, speed, tier), and the families in file order.
struct ReferenceRows {
    std::map<std::tuple<std::string, double, std::string>, const MbFamilyRow*> byKey;
    std::vector<std::string> families;
    std::map<std::string, std::vector<double>> speeds;  // per family, ascending
    const MbFamilyRow* find(const std::string& f, double s, const char* tier) const {
        auto it = byKey.find({f, s, tier});
        return it == byKey.end() ? nullptr : it->second;
    }
};
ReferenceRows referenceRows(const std::vector<MbFamilyRow>& rows, bool referenceOnly) {
    ReferenceRows r;
    for (const MbFamilyRow& row : rows) {
        if (referenceOnly && row.source != "reference") continue;
        if (std::find(r.families.begin(), r.families.end(), row.family) == r.families.end()) r.families.push_back(row.family);
        std::vector<double>& s = r.speeds[row.family];
        if (std::find(s.begin(), s.end(), row.speed) == s.end()) s.push_back(row.speed);
        r.byKey[{row.family, row.speed, row.tier}] = &row;
    }
    for (auto& [family, s] : r.speeds) std::sort(s.begin(), s.end());
    return r;
}

// How far the backends' rows are from the CPU reference's, over every score both have where the
// reference is below 60 dB (above it input, truth and output agree to float rounding).
std::string backendAgreement(const std::vector<MbFamilyRow>& rows, const ReferenceRows& ref) {
    double worst = 0;
    std::string where, sources;
    for (const MbFamilyRow& row : rows) {
        if (row.source == "reference") continue;
        if (sources.find(row.source) == std::string::npos) sources += (sources.empty() ? "" : ", ") + row.source;
        const MbFamilyRow* r = ref.find(row.family, row.speed, row.tier.c_str());
        if (!r) continue;
        const double pairs[][2] = {{row.moving, r->moving}, {row.frame, r->frame}, {row.leading, r->leading}, {row.trailing, r->trailing}};
        for (const auto& p : pairs) {
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || p[1] > kExactDb) continue;
            if (std::fabs(p[0] - p[1]) > worst) {
                worst = std::fabs(p[0] - p[1]);
                where = row.family + " at " + compactNumber(row.speed) + " px, " + row.tier + " tier, " + row.source;
            }
        }
    }
    if (sources.empty()) return "No backend was run: the CPU reference's figures only.\n\n";
    if (worst < 0.005) return "The backends (" + sources + ") give the CPU reference's figures to the CSV's 0.01 dB on every score below 60 dB.\n\n";
    return "The backends (" + sources + ") are within " + fixed(worst, 2) +
        " dB of the CPU reference on every score below 60 dB (the largest: " + where + "); the tables give the reference's figures.\n\n";
}

template <class Get>
double meanOver(const ReferenceRows& ref, const std::string& family, const char* tier, double fromSpeed, Get get) {
    double sum = 0;
    int n = 0;
    for (double s : ref.speeds.at(family))
        if (const MbFamilyRow* r = ref.find(family, s, tier); r && s >= fromSpeed) sum += get(*r), ++n;
    return n ? sum / n : NAN;
}
// The worst high - current over the speeds of 2 px and more of `get`; NaN where none.
template <class Get>
double worstHighMinusCurrent(const ReferenceRows& ref, const std::string& family, Get get) {
    double worst = NAN;
    for (double s : ref.speeds.at(family)) {
        const MbFamilyRow *c = ref.find(family, s, "current"), *h = ref.find(family, s, "high");
        if (!c || !h || s < 2) continue;
        const double d = get(*h) - get(*c);
        if (!std::isnan(d) && !(d >= worst)) worst = d;
    }
    return worst;
}

}  // namespace

Result<std::vector<MbFamilyRow>> readMbFamilyCsv(const std::string& path) {
    std::ifstream in(path);
    if (!in) return Status{StatusCode::FileError, path + ": cannot read"};
    std::string line;
    if (!std::getline(in, line)) return Status{StatusCode::FileError, path + ": empty"};
    const std::vector<std::string> header = splitCsvLine(line);
    auto column = [&](const char* name) -> int {
        auto it = std::find(header.begin(), header.end(), name);
        return it == header.end() ? -1 : int(it - header.begin());
    };
    const int family = column("family"), split = column("split"), speed = column("speed_px"), tier = column("tier"), source = column("source"),
              layout = column("layout");
    if (family < 0 || speed < 0 || tier < 0) return Status{StatusCode::InvalidArgument, path + ": the header must name family, speed_px and tier"};
    const int numbers[] = {column("psnr_moving"),     column("psnr_frame"),         column("psnr_leading"),       column("psnr_trailing"),
                           column("psnr_rows"),       column("input_psnr_moving"),  column("input_psnr_leading"), column("input_psnr_trailing"),
                           column("input_psnr_rows"), column("truth_residual_psnr")};
    std::vector<MbFamilyRow> rows;
    for (int lineNo = 2; std::getline(in, line); ++lineNo) {
        if (line.empty()) continue;
        const std::vector<std::string> cells = splitCsvLine(line);
        if (cells.size() != header.size())
            return Status{StatusCode::InvalidArgument,
                          path + ":" + std::to_string(lineNo) + ": " + std::to_string(cells.size()) + " columns, the header has " +
                              std::to_string(header.size())};
        auto get = [&](int c) { return c < 0 ? NAN : number(cells[size_t(c)]); };
        MbFamilyRow r;
        r.family = cells[size_t(family)];
        r.split = split < 0 ? "" : cells[size_t(split)];
        r.tier = cells[size_t(tier)];
        r.source = source < 0 ? "reference" : cells[size_t(source)];
        r.speed = number(cells[size_t(speed)]);
        const double layoutNumber = layout < 0 ? NAN : number(cells[size_t(layout)]);
        r.layout = std::isfinite(layoutNumber) ? int(layoutNumber) : 0;
        double* fields[] = {&r.moving,      &r.frame,        &r.leading,       &r.trailing,  &r.rows,
                            &r.inputMoving, &r.inputLeading, &r.inputTrailing, &r.inputRows, &r.residual};
        for (size_t i = 0; i < std::size(fields); ++i) *fields[i] = get(numbers[i]);
        rows.push_back(std::move(r));
    }
    return rows;
}

std::string mbFamilyTables(const std::vector<MbFamilyRow>& rows, const std::vector<MbFamilyRow>& before, const std::string& setup) {
    const ReferenceRows now = referenceRows(rows, true), then = referenceRows(before, false);
    std::ostringstream md;
    md << setup << " " << backendAgreement(rows, now);
    md << "PSNR in dB over the moving region, current / high tier, then the edges (before: the 2012 reconstruction, recorded to 0.1 dB; "
          "after: this run):\n\n";
    md << "| family | px | input | before cur / high | after cur / high | after − before cur / high | leading edge: input, before, after (cur / "
          "high) | "
          "trailing edge: input, before, after (cur / high) |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n";
    auto edge = [](double input, const MbFamilyRow* bc, const MbFamilyRow* bh, double c, double h, double MbFamilyRow::*field) {
        if (std::isnan(input)) return std::string("-, - / -, - / -");
        return fixedOrDash(input, 1) + ", " + pair1(bc ? bc->*field : NAN, bh ? bh->*field : NAN) + ", " + pair1(c, h);
    };
    std::string exact;  // cases where nothing crosses a pixel centre
    for (const std::string& f : now.families)
        for (double s : now.speeds.at(f)) {
            const MbFamilyRow *c = now.find(f, s, "current"), *h = now.find(f, s, "high");
            if (!c || !h) continue;
            if (c->inputMoving > kExactDb) {
                exact += (exact.empty() ? "" : ", ") + f + " at " + compactNumber(s) + " px";
                continue;
            }
            const MbFamilyRow *bc = then.find(f, s, "current"), *bh = then.find(f, s, "high");
            const double bcm = bc ? bc->moving : NAN, bhm = bh ? bh->moving : NAN;
            // The change of the rounded figures, so a row's columns agree with each other.
            const double dc = std::round(c->moving * 10) / 10 - bcm, dh = std::round(h->moving * 10) / 10 - bhm;
            md << "| " << f << " (" << c->split << ") | " << compactNumber(s) << " | " << fixedOrDash(c->inputMoving, 1) << " | " << pair1(bcm, bhm)
               << " | " << pair1(c->moving, h->moving) << " | " << signedFixed(dc, 1) << " / " << signedFixed(dh, 1) << " | "
               << edge(c->inputLeading, bc, bh, c->leading, h->leading, &MbFamilyRow::leading) << " | "
               << edge(c->inputTrailing, bc, bh, c->trailing, h->trailing, &MbFamilyRow::trailing) << " |\n";
        }
    if (!exact.empty())
        md << "\nLeft out: " << exact << ", where nothing crosses a pixel centre and input, truth and output agree to float rounding.\n";
    md << "\nPer family, the mean over the speeds of 2 px and more (moving region), and the worst per-speed high − current tier:\n\n";
    md << "| family | split | before cur / high | after cur / high | gain cur / high | worst high − current, moving region: before / after | "
          "after: frame and edges |\n| --- | --- | --- | --- | --- | --- | --- |\n";
    auto moving = [](const MbFamilyRow& r) { return r.moving; };
    for (const std::string& f : now.families) {
        const bool haveBefore = then.speeds.count(f) != 0;
        const double bc = haveBefore ? meanOver(then, f, "current", 2, moving) : NAN, bh = haveBefore ? meanOver(then, f, "high", 2, moving) : NAN;
        const double ac = meanOver(now, f, "current", 2, moving), ah = meanOver(now, f, "high", 2, moving);
        double worstOther = INFINITY;
        for (double MbFamilyRow::*field : {&MbFamilyRow::frame, &MbFamilyRow::leading, &MbFamilyRow::trailing})
            worstOther = std::min(worstOther, worstHighMinusCurrent(now, f, [field](const MbFamilyRow& r) { return r.*field; }));
        md << "| " << f << " | " << now.find(f, now.speeds.at(f).front(), "current")->split << " | " << fixedOrDash(bc) << " / " << fixedOrDash(bh)
           << " | " << fixedOrDash(ac) << " / " << fixedOrDash(ah) << " | " << signedFixed(ac - bc, 2) << " / " << signedFixed(ah - bh, 2) << " | "
           << signedFixed(haveBefore ? worstHighMinusCurrent(then, f, moving) : NAN, 2) << " / "
           << signedFixed(worstHighMinusCurrent(now, f, moving), 2) << " | " << signedFixed(worstOther, 2) << " |\n";
    }
    if (now.speeds.count("square")) {
        md << "\nThe independent square over the rows it spans (its report measured 25.5 / 24.7 dB at 6 px on its own layout, with 15.5 dB "
              "for the input):\n\n| speed | square rows before cur / high | after cur / high | input |\n| --- | --- | --- | --- |\n";
        for (double s : now.speeds.at("square")) {
            const MbFamilyRow *c = now.find("square", s, "current"), *h = now.find("square", s, "high");
            const MbFamilyRow *bc = then.find("square", s, "current"), *bh = then.find("square", s, "high");
            if (!c || !h || std::isnan(c->rows) || c->inputRows > kExactDb) continue;
            md << "| " << compactNumber(s) << " px | " << pair1(bc ? bc->rows : NAN, bh ? bh->rows : NAN) << " | " << pair1(c->rows, h->rows) << " | "
               << fixedOrDash(c->inputRows, 1) << " |\n";
        }
    }
    return md.str();
}

std::string mbRasterTables(const std::vector<MbFamilyRow>& rows, const std::string& setup) {
    const ReferenceRows now = referenceRows(rows, true);
    std::ostringstream md;
    md << setup << " " << backendAgreement(rows, now);
    md << "PSNR in dB (CPU reference), moving region unless named, current / high tier:\n\n";
    md << "| family | px | input | current / high | gain cur / high | high − current | frame cur / high | leading edge: input, cur / high | "
          "trailing edge: input, cur / high | truth residual RMSE |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const std::string& f : now.families)
        for (double s : now.speeds.at(f)) {
            const MbFamilyRow *c = now.find(f, s, "current"), *h = now.find(f, s, "high");
            if (!c || !h) continue;
            char residual[32] = "-";
            if (std::isfinite(c->residual)) std::snprintf(residual, sizeof residual, "%.5f", std::pow(10.0, -c->residual / 20.0));
            md << "| " << f << " | " << compactNumber(s) << " | " << fixedOrDash(c->inputMoving, 1) << " | " << pair1(c->moving, h->moving) << " | "
               << signedFixed(c->moving - c->inputMoving, 1) << " / " << signedFixed(h->moving - h->inputMoving, 1) << " | "
               << signedFixed(h->moving - c->moving, 2) << " | " << pair1(c->frame, h->frame) << " | " << fixedOrDash(c->inputLeading, 1) << ", "
               << pair1(c->leading, h->leading) << " | " << fixedOrDash(c->inputTrailing, 1) << ", " << pair1(c->trailing, h->trailing) << " | "
               << residual << " |\n";
        }
    md << "\nPer family, the mean over the speeds of 2 px and more, and the worst per-speed high − current tier (moving region; "
          "in brackets the frame and both edges):\n\n| family | input | current / high | gain cur / high | worst high − current |\n"
          "| --- | --- | --- | --- | --- |\n";
    auto moving = [](const MbFamilyRow& r) { return r.moving; };
    auto input = [](const MbFamilyRow& r) { return r.inputMoving; };
    for (const std::string& f : now.families) {
        const double in = meanOver(now, f, "current", 2, input), c = meanOver(now, f, "current", 2, moving), h = meanOver(now, f, "high", 2, moving);
        double other = INFINITY;
        for (double MbFamilyRow::*field : {&MbFamilyRow::frame, &MbFamilyRow::leading, &MbFamilyRow::trailing})
            other = std::min(other, worstHighMinusCurrent(now, f, [field](const MbFamilyRow& r) { return r.*field; }));
        md << "| " << f << " | " << fixedOrDash(in) << " | " << fixedOrDash(c) << " / " << fixedOrDash(h) << " | " << signedFixed(c - in, 2) << " / "
           << signedFixed(h - in, 2) << " | " << signedFixed(worstHighMinusCurrent(now, f, moving), 2) << " (" << signedFixed(other, 2) << ") |\n";
    }
    return md.str();
}

std::string mbSweepTable(const std::vector<MbFamilyRow>& rows, const std::string& setup) {
    const ReferenceRows now = referenceRows(rows, true);
    std::ostringstream md;
    md << setup
       << "\n\nWorst high − current tier in dB and its speed, per region (CPU reference); the last column counts the speeds "
          "where the high tier is below the current one by more than 0.005 dB in some region:\n\n"
          "| family | moving | frame | leading edges | trailing edges | speeds below |\n| --- | --- | --- | --- | --- | --- |\n";
    double MbFamilyRow::*fields[] = {&MbFamilyRow::moving, &MbFamilyRow::frame, &MbFamilyRow::leading, &MbFamilyRow::trailing};
    for (const std::string& f : now.families) {
        md << "| " << f;
        for (double MbFamilyRow::*field : fields) {
            double worst = INFINITY, at = 0;
            for (double s : now.speeds.at(f)) {
                const MbFamilyRow *c = now.find(f, s, "current"), *h = now.find(f, s, "high");
                if (!c || !h) continue;
                const double d = h->*field - c->*field;
                if (std::isfinite(d) && d < worst) worst = d, at = s;
            }
            md << " | "
               << (!std::isfinite(worst) ? std::string("-")
                       : worst < -0.005  ? signedFixed(worst, 2) + " at " + compactNumber(at) + " px"
                                         : "+0.00");
        }
        int below = 0, total = 0;
        for (double s : now.speeds.at(f)) {
            const MbFamilyRow *c = now.find(f, s, "current"), *h = now.find(f, s, "high");
            if (!c || !h) continue;
            ++total;
            bool any = false;
            for (double MbFamilyRow::*field : fields) any = any || h->*field - c->*field < -0.005;
            below += any;
        }
        md << " | " << below << " of " << total << " |\n";
    }
    return md.str();
}

std::string mbLayoutsTable(const std::vector<MbFamilyRow>& rows, const std::string& setup) {
    // The CPU reference's current and high tier rows by family, speed and layout.
    std::vector<std::string> families;
    std::map<std::string, std::map<double, std::map<int, std::array<const MbFamilyRow*, 2>>>> cases;
    std::map<std::string, std::vector<int>> layouts;
    for (const MbFamilyRow& r : rows) {
        if (r.source != "reference" || (r.tier != "current" && r.tier != "high")) continue;
        if (std::find(families.begin(), families.end(), r.family) == families.end()) families.push_back(r.family);
        std::vector<int>& l = layouts[r.family];
        if (std::find(l.begin(), l.end(), r.layout) == l.end()) l.push_back(r.layout);
        cases[r.family][r.speed][r.layout][r.tier == "high"] = &r;
    }
    std::ostringstream md;
    md << setup
       << "\n\nHigh − current tier per region (CPU reference): the worst of the means over the layouts, dB, and its speed; "
          "then how many cases (speed × layout) have the high tier below the current one by more than 0.005 dB, and the worst "
          "single case:\n\n"
          "| family | layouts | moving | frame | leading edges | trailing edges |\n| --- | --- | --- | --- | --- | --- |\n";
    double MbFamilyRow::*fields[] = {&MbFamilyRow::moving, &MbFamilyRow::frame, &MbFamilyRow::leading, &MbFamilyRow::trailing};
    for (const std::string& f : families) {
        md << "| " << f << " | " << layouts[f].size();
        for (double MbFamilyRow::*field : fields) {
            double worstMean = INFINITY, worstMeanSpeed = 0, worstCase = INFINITY, worstCaseSpeed = 0;
            int worstCaseLayout = 0, below = 0, total = 0;
            for (const auto& [speed, byLayout] : cases[f]) {
                double sum = 0;
                int n = 0;
                for (const auto& [layout, tiers] : byLayout) {
                    if (!tiers[0] || !tiers[1]) continue;
                    const double d = tiers[1]->*field - tiers[0]->*field;
                    if (!std::isfinite(d)) continue;
                    sum += d, ++n, ++total;
                    below += d < -0.005;
                    if (d < worstCase) worstCase = d, worstCaseSpeed = speed, worstCaseLayout = layout;
                }
                if (n && sum / n < worstMean) worstMean = sum / n, worstMeanSpeed = speed;
            }
            md << " | ";
            if (!total) {
                md << "-";
                continue;
            }
            md << (worstMean < -0.005 ? signedFixed(worstMean, 2) + " at " + compactNumber(worstMeanSpeed) + " px" : "+0.00") << "; " << below
               << " of " << total;
            if (below)
                md << ", worst " << signedFixed(worstCase, 2) << " (" << compactNumber(worstCaseSpeed) << " px, layout " << worstCaseLayout << ")";
        }
        md << " |\n";
    }
    return md.str();
}

}  // namespace sfx::tools
