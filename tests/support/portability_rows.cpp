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
    out << "| " << driverName() << " | " << toString(backendConfig()) << " | " << toString(tier()) << " | " << effect << " | " << figures << " |\n";
}

}  // namespace sfx::test
