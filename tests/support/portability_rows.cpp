#include "portability_rows.hpp"

#include <cstdio>
#include <fstream>

#include "test_device.hpp"

namespace sfx::test {

void addPortabilityRow(const std::string& effect, double worstPixel, double meanAbsError) {
    static bool first = true;
    std::ofstream out(outputDir() + "/portability_rows.md", first ? std::ios::trunc : std::ios::app);
    first = false;
    char figures[64];
    std::snprintf(figures, sizeof figures, "%.2g | %.2g", worstPixel, meanAbsError);
    // The driver's name without its build details ("llvmpipe (LLVM 15.0.6, 256 bits)" is
    // "llvmpipe"): the vector width varies with the machine, the row's key must not.
    const std::string name = device().caps().deviceName;
    out << "| " << name.substr(0, name.find(" (")) << " | " << toString(backendConfig()) << " | " << toString(tier()) << " | " << effect << " | "
        << figures << " |\n";
}

}  // namespace sfx::test
