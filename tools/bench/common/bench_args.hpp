// What the hand-parsed benchmarks (bench_ao, bench_oit) share: comma lists on the command line
// and the median of their timed runs.
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

// The upper median (the middle element after sorting; 0 for none).
inline double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace sfx::tools
