// Choosing a candidate within a budget, and the cost tables' file form. No device work here
// (budget_calibration.cpp measures): everything in this file is deterministic.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "sfx/budget.hpp"

namespace sfx::budget {
namespace {

std::string ms(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f ms", v);
    return buf;
}

constexpr const char* kFileHeader = "sfx-cost-table 2";

}  // namespace

const char* toString(Effect effect) { return effect == Effect::MotionBlur ? "motion-blur" : "ao"; }

bool parseEffect(const std::string& text, Effect* out) {
    for (Effect e : {Effect::AmbientObscurance, Effect::MotionBlur})
        if (text == toString(e)) {
            *out = e;
            return true;
        }
    return false;
}

std::string Candidate::name() const { return preset + (effect == Effect::AmbientObscurance ? std::string("/") + sfx::toString(technique) : ""); }

Result<Choice> choose(const CostTable& table, double budgetMs) {
    if (!(budgetMs > 0) || std::isinf(budgetMs)) {
        std::ostringstream v;
        v << budgetMs;
        return invalidArgument("budgetMs", v.str(), "a positive finite number of milliseconds");
    }
    if (table.entries.empty()) return invalidArgument("table", "a cost table with no entries", "at least one measured candidate");
    const CostEntry* best = nullptr;
    const CostEntry* cheapest = &table.entries.front();
    for (const CostEntry& e : table.entries) {
        if (e.milliseconds < cheapest->milliseconds) cheapest = &e;
        if (e.milliseconds > budgetMs) continue;
        if (!best || e.candidate.psnrDb > best->candidate.psnrDb ||
            (e.candidate.psnrDb == best->candidate.psnrDb && e.milliseconds < best->milliseconds))
            best = &e;
    }
    if (!best)
        return Status{StatusCode::OverBudget,
                      "no " + std::string(toString(table.effect)) + " preset fits " + ms(budgetMs) + " at " + std::to_string(table.width) + "x" +
                          std::to_string(table.height) + " on " + table.device + ": the cheapest, " + cheapest->candidate.name() + ", costs " +
                          ms(cheapest->milliseconds)};
    return Choice{*best, budgetMs, table};
}

std::string costTablePath(const std::string& cacheDir, const std::string& device, Effect effect, uint32_t width, uint32_t height) {
    std::string safe;
    for (char c : device) safe += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return cacheDir + "/costs_" + safe + "_" + toString(effect) + "_" + std::to_string(width) + "x" + std::to_string(height) + ".txt";
}

std::string costTablePath(const std::string& cacheDir, const DeviceCaps& caps, Effect effect, uint32_t width, uint32_t height) {
    return costTablePath(cacheDir, std::string(toString(caps.backend)) + " " + caps.deviceName, effect, width, height);
}

Status writeCostTable(const std::string& path, const CostTable& t) {
    std::ofstream out(path);
    char fingerprint[24];
    std::snprintf(fingerprint, sizeof fingerprint, "%016llx", static_cast<unsigned long long>(t.fingerprint));
    out << kFileHeader << "\n"
        << t.device << "\n"
        << toString(t.tier) << " " << toString(t.effect) << " " << t.width << " " << t.height << " " << fingerprint << "\n";
    for (const CostEntry& e : t.entries) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6f", e.milliseconds);
        out << e.candidate.name() << " " << buf << "\n";
    }
    return out ? Status::ok() : Status{StatusCode::FileError, path + ": cannot write the cost table"};
}

Result<CostTable> readCostTable(const std::string& path, const std::vector<Candidate>& expected) {
    std::ifstream in(path);
    if (!in) return Status{StatusCode::FileError, path + ": no cost table"};
    std::string header, tierName, effectName, fingerprint;
    CostTable t;
    if (!std::getline(in, header) || header != kFileHeader || !std::getline(in, t.device) ||
        !(in >> tierName >> effectName >> t.width >> t.height >> fingerprint) || !parseTier(tierName, &t.tier) ||
        !parseEffect(effectName, &t.effect) || fingerprint.size() != 16 || fingerprint.find_first_not_of("0123456789abcdef") != std::string::npos)
        return Status{StatusCode::FileError, path + ": not a cost table (bad header)"};
    t.fingerprint = std::stoull(fingerprint, nullptr, 16);
    for (const Candidate& c : expected) {
        std::string name;
        double milliseconds = 0;
        if (!(in >> name >> milliseconds) || name != c.name() || !(milliseconds >= 0) || std::isinf(milliseconds))
            return Status{StatusCode::FileError, path + ": not a cost table of these candidates (expected " + c.name() + ")"};
        t.entries.push_back({c, milliseconds});
    }
    std::string extra;
    if (in >> extra) return Status{StatusCode::FileError, path + ": more entries than candidates (" + extra + ")"};
    return t;
}

}  // namespace sfx::budget
