// A small SVG writer for the trade's Pareto plots: labelled points of (cost, accuracy) in named
// series, with the non-dominated points (no other point at least as accurate for no more cost)
// joined by a line. Written by the project's own code so the docs regenerate from a checkout.
#pragma once

#include <string>
#include <vector>

#include "sfx/status.hpp"

namespace sfx::tools {

struct PlotPoint {
    double x = 0, y = 0;  // cost (lower is better), accuracy (higher is better)
    std::string label;    // drawn beside the point
    std::string series;   // the legend entry and colour
};

struct Plot {
    std::string title, xLabel, yLabel;
    std::vector<PlotPoint> points;
    // Reference points (a peer measured beside the project): drawn as hollow black diamonds
    // under their own legend entry (their series), inside the axes' range, never part of the
    // non-dominated line.
    std::vector<PlotPoint> anchors;
};

// Indices of the non-dominated points, ordered by increasing cost.
std::vector<size_t> paretoFront(const std::vector<PlotPoint>& points);

// Indices of the points that dominate `anchor`: at least as accurate (y >=) for no more cost (x <=).
std::vector<size_t> dominating(const std::vector<PlotPoint>& points, const PlotPoint& anchor);

// The plot as an SVG document (800 x 500 user units).
std::string renderSvg(const Plot& plot);
// FileError when unwritable.
Status writeSvg(const std::string& path, const Plot& plot);

}  // namespace sfx::tools
