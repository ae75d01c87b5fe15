// The views the trade scores AO on: the scene families' views (scene_families.hpp: fit_ao
// trains on the training families and scores the held-out ones), and the sample scenes from
// their own cameras and from cameras moved about their targets with the analytic scenes, which
// trade_presets scores its presets on.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "analytic_scenes.hpp"
#include "scene.hpp"
#include "truth_scenes.hpp"

namespace sfx::tools {

struct TradeView {
    std::string scene;  // a sample scene (sceneNames()) or an analytic one (analyticSceneNames())
    bool analytic = false;
    double turnDegrees = 0;    // the eye turned about the vertical through the target
    double distanceScale = 1;  // and moved along its line of sight toward (< 1) or away from the target
    double lift = 0;           // and raised, world units
    std::string family;        // set: a scene family's view, `scene` names its variant (scene_families.hpp)
    uint32_t index = 0;        // the view's number in its family
    double radius = 0;         // the view's AO radius; 0: the caller's radii
    // "corner@0", "corner@-30_0.8_0", "analytic-contact", "blocks.s11"
    std::string name() const;
};

// The sample scene with its eye moved as the view says, or the family view's scene.
// InvalidArgument for an analytic view.
Result<RasterScene> viewScene(const TradeView& view);
// The geometry and camera the truth traces for the view (its name is view.name()).
Result<TruthScene> viewTruthScene(const TradeView& view, uint32_t width, uint32_t height);

// A view's AO inputs on one device: a rasterised G-buffer (hardware depth) or an analytic scene
// uploaded as linear depth and RGBA32F normals.
class ViewInputs {
public:
    static Result<std::unique_ptr<ViewInputs>> create(Device& device, Tier tier, const TradeView& view, uint32_t width, uint32_t height);
    ~ViewInputs();
    ViewInputs(const ViewInputs&) = delete;
    ViewInputs& operator=(const ViewInputs&) = delete;
    DepthKind depthKind() const { return kind_; }
    TextureHandle depth() const { return depth_; }
    TextureHandle normals() const { return normals_; }
    const CameraProjection& camera() const { return camera_; }

private:
    explicit ViewInputs(Device& device) : device_(device) {}
    Device& device_;
    DepthKind kind_ = DepthKind::Hardware;
    TextureHandle depth_, normals_;
    CameraProjection camera_;
};

}  // namespace sfx::tools
