// Entry point of the Catch2 test programs that can meet a case unable to run here (cross
// backend, Vulkan host objects): a recorded skip makes the exit code CTest's "skipped".
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "skips.hpp"

int main(int argc, char** argv) { return sfx::test::finishRun(Catch::Session().run(argc, argv)); }
