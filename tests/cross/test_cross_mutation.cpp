// The cross-backend comparison catches a real defect in what one backend runs: one GL device's
// programs are rewritten (FaultInjectingDevice::rewritePrograms) with a defect a cross-compiler
// or a driver could plausibly introduce, and the same case as test_cross_backend.cpp is run on
// it and on another device. The worst difference must exceed the bound the agreement test
// holds every pair to; it is printed beside the bound (docs/conformance.md).
#include <catch2/catch.hpp>

#include <optional>
#include <string>

#include "cross_bounds.hpp"
#include "cross_compare.hpp"
#include "effect_runs.hpp"
#include "fault_injection.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;
using namespace sfx::test;

namespace {

// Replaces `from` with `to` in every GL dialect of program `name`; true when it did.
bool replaceInGlsl(CompiledProgram& p, const std::string& name, const std::string& from, const std::string& to) {
    if (p.name != name) return false;
    bool changed = false;
    for (StageCode& stage : p.stages)
        for (std::string& glsl : stage.glsl)
            for (size_t at = glsl.find(from); at != std::string::npos; at = glsl.find(from, at + to.size())) {
                glsl.replace(at, from.size(), to);
                changed = true;
            }
    return changed;
}

// The first GL-family device (its programs are GLSL, which the rewrite edits) and another device
// to compare it with, or nothing when this machine has no such pair.
struct Pair {
    Opened* mutated = nullptr;
    Opened* clean = nullptr;
};
Pair pickPair(std::vector<Opened>& devices) {
    Pair p;
    for (Opened& o : devices)
        if (!p.mutated && (o.backend == BackendKind::GL || o.backend == BackendKind::GLES)) p.mutated = &o;
    for (Opened& o : devices)
        if (&o != p.mutated && !p.clean) p.clean = &o;
    return p;
}

// The comparison of `mutated` with `clean` fails: the worst difference exceeds `bound`.
void requireCaught(const std::vector<double>& mutated, const std::vector<double>& clean, double bound, const std::string& what) {
    const Worst worst = worstDifference(mutated, clean, bound);
    INFO(what << ": worst difference " << worst.value << " at value " << worst.at << " (" << mutated[worst.at] << " vs " << clean[worst.at]
              << "), bound " << bound << ", " << worst.beyond << " of " << clean.size() << " values beyond it");
    CHECK(worst.value > bound);
    WARN(what << ": caught, worst " << worst.value << " against bound " << bound << ", " << worst.beyond << " of " << clean.size()
              << " values beyond it");
}

// Motion blur with the velocity of one defective device mis-rounded in pass 1 (mb_pack's
// mbQuantizeVelocity, what every later pass reads): the worst against a clean device of the
// output and of the pass-1 velocities, each printed against its bound.
struct MotionBlurCaught {
    Worst color, velocity;
};
MotionBlurCaught motionBlurWithVelocityDefect(Tier tier, const std::string& from, const std::string& to, const std::string& what) {
    std::vector<Opened> devices = openAll(tier);
    const Pair pair = pickPair(devices);
    REQUIRE(pair.mutated);
    REQUIRE(pair.clean);
    FaultInjectingDevice defective(*pair.mutated->device);
    defective.rewritePrograms([&](CompiledProgram& p) { return replaceInGlsl(p, "mb_pack", from, to); });
    using namespace reference;
    const MotionScene scene = movingAndStillLayersScene();
    const SceneFrame f = scene.render(0);
    // Velocities off fp16's grid (the scene's are whole pixels, which no rounding moves): 6.1
    // times the scene's, the disc's clamped to the largest radius, 64 px.
    VelocityGrid velocity = f.velocity;
    for (auto& v : velocity.values) v[0] *= 6.1, v[1] *= 6.1;
    MotionBlurSettings s;
    s.maxRadiusPx = 64.0f;
    s.referenceRows = 0;
    auto flatten = [](const GpuMotionBlur& g, std::vector<double>& color, std::vector<double>& vel) {
        for (const auto& px : g.color.values) color.insert(color.end(), px.begin(), px.end());
        for (const auto& v : g.radiusPx.values) vel.insert(vel.end(), v.begin(), v.end());
    };
    std::vector<double> badColor, badVelocity, goodColor, goodVelocity;
    flatten(runMotionBlurPasses(defective, tiers::profile(tier), f.color, f.depth, &velocity, s), badColor, badVelocity);
    flatten(runMotionBlurPasses(*pair.clean->device, tiers::profile(tier), f.color, f.depth, &velocity, s), goodColor, goodVelocity);
    REQUIRE(defective.rewrittenPrograms() == 1);
    requireNoValidation(devices);
    const std::string label = "motion blur radius 64, " + what + " on " + pair.mutated->name + " vs " + pair.clean->name + " at tier " +
        toString(tier);
    const MotionBlurCaught caught{worstDifference(badColor, goodColor, kMotionBlurPairWorst),
                                  worstDifference(badVelocity, goodVelocity, kVelocityPairWorst)};
    WARN(label << ": output worst " << caught.color.value << " against bound " << kMotionBlurPairWorst << " (" << caught.color.beyond << " of "
               << badColor.size() << " values beyond it); pass-1 velocities worst " << caught.velocity.value << " px against " << kVelocityPairWorst
               << " (" << caught.velocity.beyond << " of " << badVelocity.size() << " beyond)");
    return caught;
}

bool hasGlPair(Tier tier) {
    std::vector<Opened> devices = openAll(tier);
    const Pair pair = pickPair(devices);
    return pair.mutated && pair.clean;
}

}  // namespace

TEST_CASE("a one-row tap offset in one backend's AO fails the cross-backend bound", "[cross-backend][mutation][ao]") {
    for (Tier tier : {Tier::High, Tier::Current}) {
        std::vector<Opened> devices = openAll(tier);
        const Pair pair = pickPair(devices);
        if (!pair.mutated || !pair.clean) SFX_SKIP("no GL backend and another to compare it with at tier " << toString(tier));
        FaultInjectingDevice defective(*pair.mutated->device);
        // Every tap reads the row below the one it should: aoTap's clamp of p.y + s.y.
        defective.rewritePrograms([](CompiledProgram& p) {
            return replaceInGlsl(p, "ao_alchemy", "clamp(p.y + s.y, 0, size.y - 1)", "clamp(p.y + s.y + 1, 0, size.y - 1)");
        });
        const tools::AnalyticScene scene = tools::columnsScene(96, 64, 1.0);
        AoSettings s = aoTestSettings(AoTechnique::Alchemy);
        s.blur = true;
        s.resolution = AoResolution::Full;
        const std::vector<double> bad = runAo(defective, tiers::profile(tier), scene, s).visibility.values;
        const std::vector<double> good = runAo(*pair.clean->device, tiers::profile(tier), scene, s).visibility.values;
        REQUIRE(defective.rewrittenPrograms() == 1);
        requireNoValidation(devices);
        requireCaught(bad, good, kAoPairWorst,
                      "ao alchemy blur, tap row +1 on " + pair.mutated->name + " vs " + pair.clean->name + " at tier " + toString(tier));
    }
}

TEST_CASE("a velocity floored to a whole pixel in one backend's motion blur fails the cross-backend bound",
          "[cross-backend][mutation][motion_blur]") {
    for (Tier tier : {Tier::High, Tier::Current}) {
        if (!hasGlPair(tier)) SFX_SKIP("no GL backend and another to compare it with at tier " << toString(tier));
        const MotionBlurCaught caught = motionBlurWithVelocityDefect(tier, "return uintBitsToFloat((bits + 4096u) & 4294959104u);",
                                                                     "return floor(v);", "velocity floored to a whole pixel");
        CHECK(caught.color.value > kMotionBlurPairWorst);
        CHECK(caught.velocity.value > kVelocityPairWorst);
    }
}

// The subtlest velocity defect: truncated to fp16's grid instead of rounded (what a truncating
// half store did before the quantisation), under 2^-11 relative, at most 1/32 px at 64 px. The
// pass-1 velocities, bit for bit across backends, see it; the output may not (docs/conformance.md).
TEST_CASE("a velocity truncated to fp16's grid in one backend's motion blur fails the pass-1 comparison", "[cross-backend][mutation][motion_blur]") {
    for (Tier tier : {Tier::High, Tier::Current}) {
        if (!hasGlPair(tier)) SFX_SKIP("no GL backend and another to compare it with at tier " << toString(tier));
        const MotionBlurCaught caught = motionBlurWithVelocityDefect(tier, "(bits + 4096u) & 4294959104u", "bits & 4294959104u",
                                                                     "velocity truncated to fp16's grid");
        CHECK(caught.velocity.value > kVelocityPairWorst);
    }
}
