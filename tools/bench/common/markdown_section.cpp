#include "markdown_section.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

namespace sfx::tools {

Status replaceMarkdownSection(const std::string& path, const std::string& name, const std::string& table) {
    const std::string begin = "<!-- " + name + ": begin -->\n", end = "<!-- " + name + ": end -->";
    std::string text;
    if (std::ifstream in(path); in) text.assign(std::istreambuf_iterator<char>(in), {});
    const size_t b = text.find(begin), e = text.find(end);
    if (b == std::string::npos || e == std::string::npos || e < b)
        text += "\n" + begin + table + end + "\n";
    else
        text = text.substr(0, b + begin.size()) + table + text.substr(e);
    std::ofstream out(path);
    out << text;
    return out ? Status::ok() : Status{StatusCode::FileError, path + ": cannot write"};
}

std::string fixed(double v, int digits) {
    if (std::isinf(v)) return "inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string fixedOrDash(double v, int digits) { return std::isnan(v) ? "-" : fixed(v, digits); }

std::string signedFixed(double v, int digits) {
    if (!std::isfinite(v)) return "-";
    const double scale = std::pow(10.0, digits);
    const double r = std::round(v * scale) / scale + 0.0;  // + 0.0: -0 -> +0
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.*f", digits, r);
    return buf;
}

std::string compactNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace sfx::tools
