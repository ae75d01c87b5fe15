// The trade's Pareto plots (tools/bench/common/svg_plot.*): which points are non-dominated, and that
// the SVG carries every point, the front's line and escaped labels.
#include <catch2/catch.hpp>

#include "svg_plot.hpp"

using namespace sfx::tools;

TEST_CASE("svg plot: the Pareto front is the points no other beats for no more cost", "[trade]") {
    const std::vector<PlotPoint> points = {
        {10, 25, "a", "s"}, {5, 20, "b", "s"}, {12, 24, "c", "s"},  // c: a is more accurate for less
        {20, 28, "d", "t"}, {5, 19, "e", "t"},                      // e: b is as cheap and more accurate
        {20, 27, "f", "t"},                                         // f: d costs the same, more accurate
    };
    const std::vector<size_t> front = paretoFront(points);
    CHECK(front == std::vector<size_t>{1, 0, 3});
    CHECK(paretoFront({}).empty());
}

TEST_CASE("svg plot: the document has every point, the front and escaped text", "[trade]") {
    Plot plot{"A & B <test>", "cost", "PSNR", {{1, 20, "low", "alchemy"}, {2, 25, "high", "alchemy"}, {3, 22, "x", "crease"}}};
    const std::string svg = renderSvg(plot);
    CHECK(svg.rfind("<svg", 0) == 0);
    CHECK(svg.find("</svg>") != std::string::npos);
    size_t circles = 0;
    for (size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
    CHECK(circles == 3 + 2);  // the points and one legend mark per series
    CHECK(svg.find("<polyline") != std::string::npos);
    CHECK(svg.find("A &amp; B &lt;test&gt;") != std::string::npos);
    CHECK(svg.find("<test>") == std::string::npos);
}

TEST_CASE("svg plot: a point dominates an anchor when at least as accurate for no more cost", "[trade]") {
    const std::vector<PlotPoint> points = {{10, 25, "a", "s"}, {5, 20, "b", "s"}, {13, 26, "c", "s"}, {14, 30, "d", "s"}};
    CHECK(dominating(points, {13, 26, "anchor", "x"}) == std::vector<size_t>{2});  // equal on both counts dominates
    CHECK(dominating(points, {9, 24, "anchor", "x"}).empty());                     // b is cheaper but less accurate, a more accurate but dearer
    CHECK(dominating(points, {20, 20, "anchor", "x"}) == std::vector<size_t>{0, 1, 2, 3});
    CHECK(dominating({}, {1, 1, "anchor", "x"}).empty());
}

TEST_CASE("svg plot: anchors are drawn as diamonds with their legend, outside the front", "[trade]") {
    Plot plot{"t", "cost", "PSNR", {{1, 20, "low", "alchemy"}, {2, 25, "high", "alchemy"}}};
    plot.anchors = {{1.5, 30, "ref M", "Ref (quoted, not run)"}, {3, 31, "ref H", "Ref (quoted, not run)"}};
    const std::string svg = renderSvg(plot);
    size_t diamonds = 0;
    for (size_t at = svg.find("<polygon"); at != std::string::npos; at = svg.find("<polygon", at + 1)) ++diamonds;
    CHECK(diamonds == 2 + 1);  // the anchors and one legend mark for their series
    CHECK(svg.find("ref M") != std::string::npos);
    CHECK(svg.find("quoted, not run)") != std::string::npos);
    // The anchors are above every point: were they on the front, the line would end at x = 3.
    const size_t line = svg.find("<polyline");
    REQUIRE(line != std::string::npos);
    const std::string points = svg.substr(line, svg.find("/>", line) - line);
    size_t commas = 0;
    for (char c : points) commas += c == ',';
    CHECK(commas == 2);  // two points on the front: the measured ones
}
