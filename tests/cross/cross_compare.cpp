#include "cross_compare.hpp"

#include <algorithm>
#include <cmath>

#include "sfx/tiers.hpp"

namespace sfx::test {

std::vector<Opened> openAll(Tier tier) {
    std::vector<Opened> out;
    for (const BackendConfig& config : compiledBackends()) {
        std::vector<std::string> choices{""};  // "": the backend's own choice
        if (config.backend == BackendKind::Vulkan) {
            if (Result<std::vector<std::string>> listed = describeVulkanDevices(); listed && listed->size() > 1) {
                choices.clear();
                for (size_t i = 0; i < listed->size(); ++i) choices.push_back(std::to_string(i));
            }
        }
        for (const std::string& choice : choices) {
            DeviceOptions options;
            options.validation = true;
            options.ceiling = tiers::row(tier).ceiling;
            options.physicalDevice = choice;
            Result<std::unique_ptr<Device>> device = openDevice(config, options);
            if (!device) {
                WARN("backend " << toString(config) << (choice.empty() ? "" : " device " + choice)
                                << " could not be opened: " << device.status().toString());
                if (requireAllBackends()) FAIL("SFX_REQUIRE_ALL_BACKENDS is set: every backend is required here");
                continue;
            }
            const std::string name = choice.empty() ? toString(config) : toString(config) + " (" + device.value()->caps().deviceName + ")";
            out.push_back({name, config.backend, std::move(device.value())});
        }
    }
    return out;
}

void requireNoValidation(std::vector<Opened>& devices) {
    for (Opened& o : devices) {
        auto messages = o.device->takeValidationMessages();
        for (const auto& m : messages) UNSCOPED_INFO(o.name << " validation: " << m);
        REQUIRE(messages.empty());
    }
}

namespace {

// worstDifference with value i's bound given by boundAt(i).
template <class BoundAt>
Worst compareValues(const std::vector<double>& a, const std::vector<double>& b, BoundAt boundAt) {
    REQUIRE(a.size() == b.size());
    Worst w;
    size_t nonFinite = 0, firstNonFinite = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        if (!std::isfinite(a[i]) || !std::isfinite(b[i])) {
            if (nonFinite++ == 0) firstNonFinite = i;
            continue;
        }
        const double d = std::abs(a[i] - b[i]), bound = boundAt(i);
        if (d > w.value) w.value = d, w.at = i;
        if (bound > 0 && d / bound > w.ratio) w.ratio = d / bound, w.ratioAt = i;
        w.beyond += d > bound ? 1 : 0;
    }
    // One assertion for the lot: a per-value one costs more than the comparison.
    INFO(nonFinite << " values not finite, the first at " << firstNonFinite);
    REQUIRE(nonFinite == 0);
    return w;
}

}  // namespace

Worst worstDifference(const std::vector<double>& a, const std::vector<double>& b, double bound) {
    return compareValues(a, b, [bound](size_t) { return bound; });
}

Worst worstDifference(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& bounds) {
    REQUIRE(a.size() == bounds.size());
    return compareValues(a, b, [&bounds](size_t i) { return bounds[i]; });
}

void requirePairsWithin(const std::map<std::string, std::vector<double>>& results, double bound, const std::string& what, double tieFraction) {
    for (auto a = results.begin(); a != results.end(); ++a)
        for (auto b = std::next(a); b != results.end(); ++b) {
            const Worst worst = worstDifference(a->second, b->second, bound);
            INFO(what << ": " << a->first << " vs " << b->first << ": worst difference " << worst.value << " at value " << worst.at << " ("
                      << a->second[worst.at] << " vs " << b->second[worst.at] << ", bound " << bound << "), " << worst.beyond << " of "
                      << a->second.size() << " values beyond it");
            if (tieFraction > 0.0)
                CHECK(double(worst.beyond) <= tieFraction * double(a->second.size()));
            else
                CHECK(worst.value <= bound);
            WARN(what << ": " << a->first << " vs " << b->first << ": worst " << worst.value << " (bound " << bound << "; " << worst.beyond << " of "
                      << a->second.size() << " values beyond it)");
        }
}

void requirePairsWithinEach(const std::map<std::string, std::vector<double>>& results, const std::vector<double>& bounds, const std::string& what) {
    for (auto a = results.begin(); a != results.end(); ++a)
        for (auto b = std::next(a); b != results.end(); ++b) {
            const Worst worst = worstDifference(a->second, b->second, bounds);
            INFO(what << ": " << a->first << " vs " << b->first << ": worst difference / bound " << worst.ratio << " at value " << worst.ratioAt
                      << " (" << a->second[worst.ratioAt] << " vs " << b->second[worst.ratioAt] << ", bound " << bounds[worst.ratioAt] << "), "
                      << worst.beyond << " of " << bounds.size() << " values beyond their bound");
            CHECK(worst.ratio <= 1.0);
            WARN(what << ": " << a->first << " vs " << b->first << ": worst " << worst.value << ", worst difference / bound " << worst.ratio);
        }
}

void requireRasterPairsWithin(const std::vector<Opened>& devices, const std::map<std::string, std::vector<double>>& results, size_t channels,
                              double bound, const std::string& what, const std::function<PixelMask(uint32_t bits)>& excluded, OutsideBand check) {
    std::map<std::string, uint32_t> gridOf;
    for (const Opened& o : devices) gridOf[o.name] = o.device->caps().limits.subPixelPrecisionBits;
    for (auto a = results.begin(); a != results.end(); ++a)
        for (auto b = std::next(a); b != results.end(); ++b) {
            const uint32_t bitsA = gridOf.at(a->first), bitsB = gridOf.at(b->first);
            const std::string grids = "sub-pixel grid 1/" + std::to_string(1u << bitsA) +
                (bitsA == bitsB ? "" : " and 1/" + std::to_string(1u << bitsB));
            if (bitsA == bitsB) {
                requirePairsWithin({*a, *b}, bound, what + " (" + grids + ")");
                continue;
            }
            const PixelMask band = excluded(std::min(bitsA, bitsB));
            REQUIRE(band.set.size() * channels == a->second.size());
            std::vector<double> outsideA, outsideB;
            for (size_t i = 0; i < a->second.size(); ++i)
                if (!band.set[i / channels]) outsideA.push_back(a->second[i]), outsideB.push_back(b->second[i]);
            const Worst outside = worstDifference(outsideA, outsideB, bound), all = worstDifference(a->second, b->second, bound);
            const double fraction = double(band.count()) / double(band.set.size());
            INFO(what << ": " << a->first << " vs " << b->first << " (" << grids << "): " << band.count() << " of " << band.set.size()
                      << " pixels within a grid step of an edge");
            CHECK(fraction <= kMaxExcludedFraction);
            if (check == OutsideBand::Checked) {
                INFO("outside them worst " << outside.value << " at value " << outside.at << ", bound " << bound);
                CHECK(outside.value <= bound);
            }
            WARN(what << ": " << a->first << " vs " << b->first << " (" << grids << ")" << (check == OutsideBand::Checked ? "" : ", not checked")
                      << ": " << band.count() << " of " << band.set.size() << " pixels (" << 100.0 * fraction
                      << " %) within a grid step of an edge; outside them worst " << outside.value << ", " << outside.beyond << " of "
                      << outsideA.size() << " values beyond " << bound << "; everywhere worst " << all.value);
        }
}

void requireSpan(const std::vector<double>& values, double minSpan, const std::string& what) {
    REQUIRE_FALSE(values.empty());
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    INFO(what << ": the output spans " << *lo << " to " << *hi << ", less than " << minSpan << ": nothing to agree on");
    CHECK(*hi - *lo > minSpan);
}

}  // namespace sfx::test
