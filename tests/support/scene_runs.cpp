#include "scene_runs.hpp"

#include <catch2/catch.hpp>

#include <utility>

namespace sfx::test {

tiers::TierChoice chooseTier(const Device& device, Tier tier) {
    Result<tiers::TierChoice> choice = tiers::choose(device.caps(), tier);
    INFO(choice.status().toString());
    REQUIRE(choice.isOk());
    return choice.value();
}

render::RenderResult renderScene(Device& device, Tier tier, const scene::Scene& scene, const render::RenderOptions& options,
                                 render::FramePlan* plan) {
    auto renderer = render::SceneRender::create(device, chooseTier(device, tier), scene, options);
    INFO(renderer.status().toString());
    REQUIRE(renderer.isOk());
    if (plan) *plan = renderer.value()->plan();
    Result<render::RenderResult> out = renderer.value()->render();
    INFO(out.status().toString());
    REQUIRE(out.isOk());
    return std::move(out.value());
}

}  // namespace sfx::test
