// Settings chosen by a cost budget: given a device, an effect, a size, a tier's presets and a
// budget in milliseconds, the most accurate preset whose cost measured on THIS device fits.
// Accuracy is each preset's PSNR against ground truth, measured offline (tools/run_trade.sh)
// and kept beside the presets in the tier table (tiers::row(tier).presets, sfx/tiers.hpp); cost
// comes from a short calibration run of every candidate on the device, cached in a file per
// device name, effect and size.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sfx/ao.hpp"
#include "sfx/hal.hpp"
#include "sfx/tier.hpp"

namespace sfx::budget {

enum class Effect : uint32_t { AmbientObscurance, MotionBlur };
const char* toString(Effect effect);  // "ao", "motion-blur"
bool parseEffect(const std::string& text, Effect* out);

// One way to run an effect: a preset of the device's tier (and, for AO, a technique).
struct Candidate {
    Effect effect = Effect::AmbientObscurance;
    std::string preset;                            // a preset name of the tier's row
    AoTechnique technique = AoTechnique::Alchemy;  // AO only
    double psnrDb = 0;                             // accuracy against the truth, higher is better
    std::string name() const;                      // "medium/alchemy" (AO), "medium" (motion blur)
};

struct CostEntry {
    Candidate candidate;
    double milliseconds = 0;  // median of the calibration runs on the device
};

struct CostTable {
    std::string device;  // DeviceCaps::deviceName
    Tier tier = Tier::Current;
    Effect effect = Effect::AmbientObscurance;
    uint32_t width = 0, height = 0;
    std::vector<CostEntry> entries;
    uint64_t fingerprint = 0;  // what was measured (budget::fingerprint); a cached table must match it
};

struct Choice {
    CostEntry chosen;
    double budgetMs = 0;
    CostTable table;  // the figures the choice was made from
};

// The candidates of `effect` among `presets`: every preset (x technique for AO), with the PSNR
// it records.
std::vector<Candidate> candidates(Effect effect, const std::vector<Preset>& presets);

// The most accurate entry whose cost is within budgetMs (equal accuracy: the cheaper one).
// InvalidArgument naming budgetMs when it is not a positive finite number, or naming the table
// when it is empty; OverBudget stating the cheapest entry and its cost when none fits.
Result<Choice> choose(const CostTable& table, double budgetMs);

struct CalibrationOptions {
    std::string cacheDir;      // where cost tables are cached; empty = no cache (always measure)
    bool recalibrate = false;  // measure again even when a cached table exists
    uint32_t runs = 5;         // timed runs per candidate (median), after one warm-up
};

// The cost table of `effect` at width x height on `device` for `presets` (one tier's, the tier
// the device runs): read from the cache when one for this backend, device, effect, size and
// candidate list exists and its fingerprint is this run's, else measured (every candidate
// rendered on synthetic inputs, timed with the HAL's timers) and cached. InvalidArgument naming
// presets when the list is empty or mixes tiers.
Result<CostTable> costTable(Device& device, const std::vector<Preset>& presets, Effect effect, uint32_t width, uint32_t height,
                            const CalibrationOptions& options);

// Median of `runs` timed recordings (after one warm-up that compiles pipelines and warms caches),
// each flushed on its own so a reading covers exactly one recording: the calibration's clock,
// which the benchmarks share. InvalidArgument naming runs when it is 0.
Result<TimerReading> timeMedian(Device& device, uint32_t runs, const std::function<Status()>& record);

// What a cost table of `effect` over `presets` on a device measures, as one number: the backend,
// API and device names, every preset's parameters and the code of the presets' tier's programs.
// A cached table with another fingerprint was measured on something else and is measured again.
uint64_t fingerprint(const DeviceCaps& caps, Effect effect, const std::vector<Preset>& presets);

// The cache file of a table, and the file's text form (one entry per line); readCostTable is
// FileError when the file is missing or not a cost table of these candidates. The first form
// names the file by a device string; the second by the backend and device of `caps`, so a
// device's Vulkan and GL costs are cached apart (costTable uses it).
std::string costTablePath(const std::string& cacheDir, const std::string& device, Effect effect, uint32_t width, uint32_t height);
std::string costTablePath(const std::string& cacheDir, const DeviceCaps& caps, Effect effect, uint32_t width, uint32_t height);
Status writeCostTable(const std::string& path, const CostTable& table);
Result<CostTable> readCostTable(const std::string& path, const std::vector<Candidate>& expected);

}  // namespace sfx::budget
