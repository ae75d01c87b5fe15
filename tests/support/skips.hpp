// Honest skips for Catch2 v2, which has none of its own: a case that cannot run here (backend
// absent, fewer than two backends to compare, a host object missing) says why and returns;
// the run then exits with kSkipExitCode, which CTest reports as skipped (SKIP_RETURN_CODE),
// never as passed. With SFX_REQUIRE_ALL_BACKENDS=1 (CI) a skip fails the run instead.
#pragma once

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace sfx::test {

inline constexpr int kSkipExitCode = 77;

// True when SFX_REQUIRE_ALL_BACKENDS is set to anything but "" or "0".
bool requireAllBackends();

// Records that the running case could not run, and why.
void recordSkip(const std::string& testCase, const std::string& reason);
const std::vector<std::string>& skips();

// The process exit code after a Catch2 run that returned `catchResult`: a failure stays a
// failure; otherwise any recorded skip makes it kSkipExitCode, or 1 under
// SFX_REQUIRE_ALL_BACKENDS. Prints every skip.
int finishRun(int catchResult);

}  // namespace sfx::test

// Ends the running test case as skipped: `reason` (a stream expression) says why.
// clang-format off
#define SFX_SKIP(reason)                                                                          \
    do {                                                                                          \
        std::ostringstream sfx_skip_why_;                                                         \
        sfx_skip_why_ << reason;                                                                  \
        ::sfx::test::recordSkip(Catch::getResultCapture().getCurrentTestName(), sfx_skip_why_.str()); \
        WARN("SKIPPED: " << sfx_skip_why_.str());                                                 \
        return;                                                                                   \
    } while (0)
// clang-format on
