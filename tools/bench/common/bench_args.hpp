// What the benchmarks share: comma lists on the command line and the median of their timed runs.
#pragma once

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace sfx::tools {

// "a,b,,c" -> {"a", "b", "c"}: empty items are dropped.
inline std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    for (std::string item; std::getline(ss, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

// "0.5,2,,6" -> {0.5, 2, 6}: numbers, empty items dropped.
inline std::vector<double> splitNumberList(const std::string& text) {
    std::vector<double> out;
    for (const std::string& item : splitList(text)) out.push_back(std::stod(item));
    return out;
}

// Whether `name` is one of the comma list's items.
inline bool inList(const std::string& list, const std::string& name) { return ("," + list + ",").find("," + name + ",") != std::string::npos; }

// The upper median (the middle element after sorting; 0 for none).
inline double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace sfx::tools
