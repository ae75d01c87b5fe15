#include "svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace sfx::tools {
namespace {

constexpr double kWidth = 800, kHeight = 500, kLeft = 70, kRight = 180, kTop = 40, kBottom = 60;
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

// A "nice" tick step (1, 2 or 5 times a power of ten) for about `count` ticks over span.
double tickStep(double span, int count) {
    const double raw = span / count, p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (raw <= m * p) return m * p;
    return 10 * p;
}

}  // namespace

std::vector<size_t> paretoFront(const std::vector<PlotPoint>& points) {
    std::vector<size_t> order(points.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return points[a].x != points[b].x ? points[a].x < points[b].x : points[a].y > points[b].y; });
    std::vector<size_t> front;
    double bestY = -INFINITY;
    for (size_t i : order)
        if (points[i].y > bestY) front.push_back(i), bestY = points[i].y;
    return front;
}

std::vector<size_t> dominating(const std::vector<PlotPoint>& points, const PlotPoint& anchor) {
    std::vector<size_t> out;
    for (size_t i = 0; i < points.size(); ++i)
        if (points[i].x <= anchor.x && points[i].y >= anchor.y) out.push_back(i);
    return out;
}

std::string renderSvg(const Plot& plot) {
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
    std::vector<PlotPoint> all = plot.points;
    all.insert(all.end(), plot.anchors.begin(), plot.anchors.end());
    if (!all.empty()) {
        x0 = y0 = INFINITY, x1 = y1 = -INFINITY;
        for (const PlotPoint& p : all) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        x0 = 0;  // costs from zero, so ratios read true
        const double padY = std::max(0.5, 0.05 * (y1 - y0));
        y0 -= padY, y1 += padY, x1 *= 1.05;
        if (x1 <= x0) x1 = x0 + 1;
    }
    const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
    auto sx = [&](double x) { return kLeft + (x - x0) / (x1 - x0) * pw; };
    auto sy = [&](double y) { return kTop + (1 - (y - y0) / (y1 - y0)) * ph; };
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight << "\" viewBox=\"0 0 " << kWidth << " "
        << kHeight << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg << "<text x=\"" << kWidth / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">" << escape(plot.title) << "</text>\n";
    svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << pw << "\" height=\"" << ph << "\" fill=\"none\" stroke=\"#444\"/>\n";
    const double xs = tickStep(x1 - x0, 8), ys = tickStep(y1 - y0, 6);
    for (double x = std::ceil(x0 / xs) * xs; x <= x1; x += xs)
        svg << "<line x1=\"" << num(sx(x)) << "\" y1=\"" << kTop << "\" x2=\"" << num(sx(x)) << "\" y2=\"" << kTop + ph
            << "\" stroke=\"#ddd\"/><text x=\"" << num(sx(x)) << "\" y=\"" << kTop + ph + 15 << "\" text-anchor=\"middle\">" << x << "</text>\n";
    for (double y = std::ceil(y0 / ys) * ys; y <= y1; y += ys)
        svg << "<line x1=\"" << kLeft << "\" y1=\"" << num(sy(y)) << "\" x2=\"" << kLeft + pw << "\" y2=\"" << num(sy(y))
            << "\" stroke=\"#ddd\"/><text x=\"" << kLeft - 6 << "\" y=\"" << num(sy(y) + 4) << "\" text-anchor=\"end\">" << y << "</text>\n";
    svg << "<text x=\"" << kLeft + pw / 2 << "\" y=\"" << kHeight - 18 << "\" text-anchor=\"middle\">" << escape(plot.xLabel) << "</text>\n";
    svg << "<text transform=\"translate(18," << kTop + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">" << escape(plot.yLabel) << "</text>\n";
    const std::vector<size_t> front = paretoFront(plot.points);
    if (front.size() > 1) {
        svg << "<polyline fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\" points=\"";
        for (size_t i : front) svg << num(sx(plot.points[i].x)) << "," << num(sy(plot.points[i].y)) << " ";
        svg << "\"/>\n";
    }
    std::map<std::string, const char*> colours;
    for (const PlotPoint& p : plot.points)
        if (!colours.count(p.series)) colours[p.series] = kColours[colours.size() % (sizeof kColours / sizeof *kColours)];
    for (const PlotPoint& p : plot.points)
        svg << "<circle cx=\"" << num(sx(p.x)) << "\" cy=\"" << num(sy(p.y)) << "\" r=\"4\" fill=\"" << colours[p.series] << "\"/><text x=\""
            << num(sx(p.x) + 6) << "\" y=\"" << num(sy(p.y) - 5) << "\" font-size=\"9\" fill=\"#333\">" << escape(p.label) << "</text>\n";
    // A hollow diamond of half-diagonal 6 at (cx, cy).
    auto diamond = [&](double cx, double cy) {
        svg << "<polygon points=\"" << num(cx) << "," << num(cy - 6) << " " << num(cx + 6) << "," << num(cy) << " " << num(cx) << "," << num(cy + 6)
            << " " << num(cx - 6) << "," << num(cy) << "\" fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\"/>";
    };
    for (const PlotPoint& p : plot.anchors) {
        diamond(sx(p.x), sy(p.y));
        svg << "<text x=\"" << num(sx(p.x) + 8) << "\" y=\"" << num(sy(p.y) + 12) << "\" font-size=\"9\" fill=\"#000\">" << escape(p.label)
            << "</text>\n";
    }
    double ly = kTop + 10;
    for (const auto& [series, colour] : colours) {
        svg << "<circle cx=\"" << kLeft + pw + 20 << "\" cy=\"" << ly << "\" r=\"4\" fill=\"" << colour << "\"/><text x=\"" << kLeft + pw + 30
            << "\" y=\"" << ly + 4 << "\">" << escape(series) << "</text>\n";
        ly += 18;
    }
    std::vector<std::string> anchorSeries;
    for (const PlotPoint& p : plot.anchors)
        if (std::find(anchorSeries.begin(), anchorSeries.end(), p.series) == anchorSeries.end()) anchorSeries.push_back(p.series);
    for (const std::string& series : anchorSeries) {
        // Long entries (a quoted source) wrap at a parenthesis onto a second line.
        const size_t paren = series.find(" (");
        diamond(kLeft + pw + 20, ly);
        svg << "<text x=\"" << kLeft + pw + 30 << "\" y=\"" << ly + 4 << "\">" << escape(series.substr(0, paren)) << "</text>\n";
        if (paren != std::string::npos) {
            ly += 13;
            svg << "<text x=\"" << kLeft + pw + 30 << "\" y=\"" << ly + 4 << "\" font-size=\"9\">" << escape(series.substr(paren + 1)) << "</text>\n";
        }
        ly += 18;
    }
    svg << "<line x1=\"" << kLeft + pw + 12 << "\" y1=\"" << ly << "\" x2=\"" << kLeft + pw + 28 << "\" y2=\"" << ly
        << "\" stroke=\"#000\" stroke-dasharray=\"4 3\"/><text x=\"" << kLeft + pw + 30 << "\" y=\"" << ly + 4 << "\">non-dominated</text>\n";
    svg << "</svg>\n";
    return svg.str();
}

Status writeSvg(const std::string& path, const Plot& plot) {
    std::ofstream out(path);
    out << renderSvg(plot);
    return out ? Status::ok() : Status{StatusCode::FileError, path + ": cannot write"};
}

}  // namespace sfx::tools
