#include "skips.hpp"

#include <cstdlib>
#include <iostream>
#include <string_view>

namespace sfx::test {
namespace {
std::vector<std::string> gSkips;
}  // namespace

bool requireAllBackends() {
    const char* env = std::getenv("SFX_REQUIRE_ALL_BACKENDS");
    return env && std::string_view(env) != "" && std::string_view(env) != "0";
}

void recordSkip(const std::string& testCase, const std::string& reason) { gSkips.push_back(testCase + ": " + reason); }

const std::vector<std::string>& skips() { return gSkips; }

int finishRun(int catchResult) {
    if (gSkips.empty()) return catchResult;
    const bool required = requireAllBackends();
    std::cerr << (required ? "FAILED (SFX_REQUIRE_ALL_BACKENDS is set): " : "SKIPPED: ") << gSkips.size() << " test case(s) could not run:\n";
    for (const std::string& s : gSkips) std::cerr << "  " << s << "\n";
    if (catchResult != 0) return catchResult;
    return required ? 1 : kSkipExitCode;
}

}  // namespace sfx::test
