#include "mb_flicker_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "markdown_section.hpp"

namespace sfx::tools {
namespace {

using Row = std::map<std::string, std::string>;

double num(const Row& r, const char* column) {
    auto it = r.find(column);
    if (it == r.end() || it->second.empty() || it->second == "-") return NAN;
    return std::strtod(it->second.c_str(), nullptr);
}

std::string one(double v) { return fixedOrDash(v, 1); }
std::string two(double v) { return fixedOrDash(v, 2); }

// The CSV's rows, and per family the speeds and per tier the radii, in file order.
struct FlickerRows {
    std::vector<Row> rows;
    std::vector<std::string> families;
    std::map<std::string, std::vector<std::string>> speeds;
    std::map<std::string, std::vector<double>> radii;  // per tier, ascending: the tier's own, then the longer
    const Row* find(const std::string& family, const std::string& speed, const std::string& tier, const std::string& source, double radius = NAN,
                    int jitter = 0) const {
        for (const Row& r : rows) {
            if (r.at("family") != family || r.at("speed_px") != speed || r.at("tier") != tier || r.at("source") != source) continue;
            if (!std::isnan(radius) && num(r, "radius_px") != radius) continue;
            if (jitter && num(r, "jitter") != jitter) continue;
            return &r;
        }
        return nullptr;
    }
};

Result<FlickerRows> read(const std::string& path) {
    std::ifstream in(path);
    if (!in) return Status{StatusCode::FileError, path + ": cannot read"};
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    for (std::stringstream ss(line); std::getline(ss, line, ',');) header.push_back(line);
    for (const char* needed : {"family", "split", "speed_px", "tier", "source", "radius_px", "jitter", "tier_jitter", "temporal_psnr_mean",
                               "temporal_psnr_worst", "psnr_mean"})
        if (std::find(header.begin(), header.end(), needed) == header.end())
            return Status{StatusCode::InvalidArgument, path + ": no column " + needed};
    FlickerRows f;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        Row r;
        std::stringstream ss(line);
        std::string cell;
        for (const std::string& name : header) {
            std::getline(ss, cell, ',');
            r[name] = cell;
        }
        const std::string& family = r["family"];
        if (std::find(f.families.begin(), f.families.end(), family) == f.families.end()) f.families.push_back(family);
        std::vector<std::string>& s = f.speeds[family];
        if (std::find(s.begin(), s.end(), r["speed_px"]) == s.end()) s.push_back(r["speed_px"]);
        if (r["source"] == "reference") {
            std::vector<double>& radii = f.radii[r["tier"]];
            if (std::find(radii.begin(), radii.end(), num(r, "radius_px")) == radii.end()) radii.push_back(num(r, "radius_px"));
        }
        f.rows.push_back(std::move(r));
    }
    for (auto& [tier, radii] : f.radii) std::sort(radii.begin(), radii.end());
    return f;
}

// The tier's own jitter pattern (tier_jitter = 1) in its reference rows.
int ownJitter(const FlickerRows& f, const std::string& tier) {
    for (const Row& r : f.rows)
        if (r.at("tier") == tier && r.at("source") == "reference" && r.at("tier_jitter") == "1") return int(num(r, "jitter"));
    return 2;
}

struct Range {
    double lo = INFINITY, hi = -INFINITY;
    void add(double v) {
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    std::string text(int digits) const { return fixedOrDash(lo, digits) + " to " + fixedOrDash(hi, digits); }
};

}  // namespace

Result<std::string> mbFlickerTables(const std::string& csvPath, const std::string& setup) {
    Result<FlickerRows> read_ = read(csvPath);
    if (!read_) return read_.status();
    const FlickerRows& f = read_.value();
    const char* tiers[2] = {"current", "high"};
    int own[2] = {ownJitter(f, "current"), ownJitter(f, "high")};
    double radius[2], longRadius[2];
    for (int t = 0; t < 2; ++t) {
        const std::vector<double>& r = f.radii.count(tiers[t]) ? f.radii.at(tiers[t]) : std::vector<double>{NAN};
        radius[t] = r.front(), longRadius[t] = r.back();
    }
    std::ostringstream md;
    md << setup << "\n\nTemporal PSNR in dB, mean over the pairs / worst pair, at each tier's default (radius " << fixedOrDash(radius[0], 0)
       << " px current, " << fixedOrDash(radius[1], 0)
       << " px high at this height), CPU reference; the last column is the ordinary per-frame PSNR against the truth over the objects, for "
          "context:\n\n| family | px | input: mean / worst | current: mean / worst | high: mean / worst | per frame: input / current / high |\n"
          "| --- | --- | --- | --- | --- | --- |\n";
    Range gain, belowPerFrame;
    double worstMean = INFINITY, worstWorst = INFINITY;
    for (const std::string& family : f.families)
        for (const std::string& speed : f.speeds.at(family)) {
            const Row* in = f.find(family, speed, "-", "input");
            const Row* c = f.find(family, speed, "current", "reference", radius[0], own[0]);
            const Row* h = f.find(family, speed, "high", "reference", radius[1], own[1]);
            if (!in || !c || !h) continue;
            md << "| " << family << " (" << in->at("split") << ") | " << speed << " | " << one(num(*in, "temporal_psnr_mean")) << " / "
               << one(num(*in, "temporal_psnr_worst")) << " | " << one(num(*c, "temporal_psnr_mean")) << " / " << one(num(*c, "temporal_psnr_worst"))
               << " | " << one(num(*h, "temporal_psnr_mean")) << " / " << one(num(*h, "temporal_psnr_worst")) << " | " << one(num(*in, "psnr_mean"))
               << " / " << one(num(*c, "psnr_mean")) << " / " << one(num(*h, "psnr_mean")) << " |\n";
            for (const Row* t : {c, h}) {
                gain.add(num(*t, "temporal_psnr_mean") - num(*in, "temporal_psnr_mean"));
                belowPerFrame.add(num(*t, "psnr_mean") - num(*t, "temporal_psnr_mean"));
            }
            worstMean = std::min(worstMean, num(*h, "temporal_psnr_mean") - num(*c, "temporal_psnr_mean"));
            worstWorst = std::min(worstWorst, num(*h, "temporal_psnr_worst") - num(*c, "temporal_psnr_worst"));
        }
    md << "\nOver these cases: each tier's temporal PSNR is " << gain.text(1) << " dB above the input's and " << belowPerFrame.text(1)
       << " dB below its own per-frame PSNR; the high tier less the current one is at least " << signedFixed(worstMean, 2) << " dB on the mean and "
       << signedFixed(worstWorst, 2) << " on the worst pair.";
    // The backends against the reference, each tier as it is.
    double backendWorst = 0;
    std::string backends;
    for (const Row& r : f.rows) {
        const std::string& source = r.at("source");
        if (source == "input" || source == "reference") continue;
        if (backends.find(source) == std::string::npos) backends += (backends.empty() ? "" : ", ") + source;
        const int t = r.at("tier") == "high";
        if (const Row* ref = f.find(r.at("family"), r.at("speed_px"), r.at("tier"), "reference", radius[t], own[t]))
            for (const char* column : {"temporal_psnr_mean", "temporal_psnr_worst", "psnr_mean"})
                backendWorst = std::max(backendWorst, std::fabs(num(r, column) - num(*ref, column)));
    }
    if (!backends.empty()) md << " The backends (" << backends << ") are within " << two(backendWorst) << " dB of the CPU reference on every row.";
    md << "\n";

    // The jitter patterns at the longer radius, where the jitter acts at its full share.
    const int other[2] = {own[0] == 2 ? 4 : 2, own[1] == 2 ? 4 : 2};
    auto pattern = [](int j) { return j == 2 ? std::string("checkerboard") : std::string("4 × 4"); };
    md << "\nThe jitter patterns at the longer radii (" << fixedOrDash(longRadius[0], 0) << " px current, " << fixedOrDash(longRadius[1], 0)
       << " px high), at 12 px and faster: temporal PSNR mean (worst pair), the tier's own pattern first:\n\n| family | px | current, "
       << fixedOrDash(longRadius[0], 0) << " px: " << pattern(own[0]) << " / " << pattern(other[0]) << " | high, " << fixedOrDash(longRadius[1], 0)
       << " px: " << pattern(own[1]) << " / " << pattern(other[1]) << " |\n| --- | --- | --- | --- |\n";
    struct Bound {
        double db = 0, perFrame = 0;
        std::string where;
    } boundLong, boundWorst, boundOwn, beyond;
    for (const std::string& family : f.families)
        for (const std::string& speed : f.speeds.at(family)) {
            std::string cells[2];
            for (int t = 0; t < 2; ++t)
                for (int radiusKind = 0; radiusKind < 2; ++radiusKind) {
                    const double r = radiusKind ? longRadius[t] : radius[t];
                    const Row* a = f.find(family, speed, tiers[t], "reference", r, own[t]);
                    const Row* b = f.find(family, speed, tiers[t], "reference", r, other[t]);
                    if (!a || !b) continue;
                    const double d = std::fabs(num(*a, "temporal_psnr_mean") - num(*b, "temporal_psnr_mean"));
                    const double dw = std::fabs(num(*a, "temporal_psnr_worst") - num(*b, "temporal_psnr_worst"));
                    const double dp = std::fabs(num(*a, "psnr_mean") - num(*b, "psnr_mean"));
                    const std::string where = family + " at " + speed + " px, " + tiers[t] + " tier, " + fixedOrDash(r, 0) + " px";
                    Bound& mean = radiusKind ? boundLong : boundOwn;
                    if (d > mean.db) mean = {d, dp, where};
                    if (dw > boundWorst.db) boundWorst = {dw, dp, where};
                    if (d - dp > beyond.db) beyond = {d - dp, dp, where};
                    if (radiusKind && std::strtod(speed.c_str(), nullptr) >= 12)
                        cells[t] = two(num(*a, "temporal_psnr_mean")) + " (" + two(num(*a, "temporal_psnr_worst")) + ") / " +
                            two(num(*b, "temporal_psnr_mean")) + " (" + two(num(*b, "temporal_psnr_worst")) + ")";
                }
            if (!cells[0].empty() || !cells[1].empty())
                md << "| " << family << " | " << speed << " | " << (cells[0].empty() ? "-" : cells[0]) << " | " << (cells[1].empty() ? "-" : cells[1])
                   << " |\n";
        }
    md << "\nThe bound: the choice of jitter pattern moves the temporal PSNR by at most " << two(boundLong.db) << " dB on the mean ("
       << boundLong.where << ") and " << two(boundWorst.db) << " dB on the worst pair (" << boundWorst.where << "), and by at most "
       << two(boundOwn.db) << " dB at the tiers' own radii (" << boundOwn.where
       << "). Beyond what it moves the per-frame PSNR it moves the temporal PSNR by at most " << two(beyond.db) << " dB (" << beyond.where << ").\n";
    return md.str();
}

}  // namespace sfx::tools
