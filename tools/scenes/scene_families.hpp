// AO truth scene families: procedurally generated scenes, each family seen from several
// cameras, so that a fit of the AO defaults can be held out by family (trained on some
// families, scored on families whose kind of geometry it never saw). docs/ao_families.md states
// every family and view.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene.hpp"
#include "trade_views.hpp"

namespace sfx::tools {

struct SceneFamily {
    std::string name;
    bool heldOut = false;  // never seen by fit_ao's search
    std::string made;      // how its scenes are generated, one sentence
};

// "blocks", "interior" (training); "thin", "meshes", "independent" (held out).
std::vector<SceneFamily> sceneFamilies();

// The views of every family (TradeView::family set, radius set), in family order; heldOut picks
// the held-out families' views, or the training families'.
std::vector<TradeView> familyViews(bool heldOut);
// Every family's views, training families first.
std::vector<TradeView> allFamilyViews();

// A thin view with its sheet and legs replaced by a solid block of the sheet's footprint and
// height, the same camera: its variant carries kSolidSheetSuffix ("thin.s33+solid"), so its truth
// is cached apart. Any other view is returned as it is. It is no family's view: it measures what
// the sheet alone costs an estimator (fit_ao --diagnose --solid-sheet).
inline constexpr std::string_view kSolidSheetSuffix = "+solid";
TradeView withSolidSheet(TradeView view);

// The view's camera in words: "elevation 5 deg, azimuth 20 deg, fov-y 50, r 0.5".
std::string describeCamera(const TradeView& view);

// The scene of a family view with the view's camera. InvalidArgument for an unknown family or
// variant; FileError when a glmark2 model is missing (package glmark2-data).
Result<RasterScene> familyScene(const TradeView& view);

}  // namespace sfx::tools
