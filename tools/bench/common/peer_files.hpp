// The files a peer AO implementation is measured through (tools/run_xegtao.sh runs XeGTAO on
// them): every view's inputs exactly as `sfx ao` reads them from files (linear eye depth, +inf
// on sky, and view-space normals, PFM), the peer's visibility outputs, and its timings.
#pragma once

#include <string>
#include <vector>

#include "sfx/truth_metrics.hpp"
#include "trade_views.hpp"

namespace sfx::tools {

// The peer's quality presets, cheapest first (XeGTAO's Low, Medium, High, Ultra).
inline const std::vector<std::string> kPeerPresets{"low", "medium", "high", "ultra"};

struct PeerInputs {
    std::string dir;      // written: <view>.depth.pfm, <view>.normals.pfm, views.txt
    std::string backend;  // the device that rasterises the G-buffers (high tier)
    uint32_t width = 320, height = 180;
    std::string costView;  // also written at costWidth x costHeight as cost.depth.pfm, cost.normals.pfm
    uint32_t costWidth = 1280, costHeight = 720;
};

// Renders each view's G-buffer and writes its inputs; views.txt gets one line per view,
// "name width height fov_y radius" (the cost view as "cost").
Status writePeerInputs(const PeerInputs& inputs, const std::vector<TradeView>& views);

// <dir>/<view>.xegtao-<preset>.pfm as visibility, row 0 = top; FileError when it is missing or
// unreadable.
Result<std::vector<double>> readPeerOutput(const std::string& dir, const std::string& view, const std::string& preset);

// That output scored against the view's truth. The peer shades sky pixels (infinite depth) too;
// a renderer never composites AO there and the SDK leaves them at 1, so they count as the
// truth's 1 (in `visibility` as well). FileError when the output is missing; the comparison's
// errors otherwise.
struct PeerScore {
    std::vector<double> visibility;
    truth::Comparison comparison;
};
Result<PeerScore> scorePeerOutput(const std::string& dir, const std::string& view, const std::string& preset, const truth::Image& truth);

struct PeerCost {
    std::string preset;
    double prefilterMs = 0, mainMs = 0, denoiseMs = 0, totalMs = 0;
};
// <dir>/xegtao_cost.txt, lines "preset prefilter main denoise total" (ms); none when missing.
std::vector<PeerCost> readPeerCosts(const std::string& dir);

}  // namespace sfx::tools
