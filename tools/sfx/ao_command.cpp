#include "commands.hpp"

namespace sfx::cli {
// Placeholder until the AO effect lands (issue 3): the subcommand exists and says so.
Command addAoCommand(CLI::App& app) {
    Command c;
    c.app = app.add_subcommand("ao", "Ambient obscurance on G-buffer files (not built yet)");
    c.run = [] { return 1; };
    return c;
}
}  // namespace sfx::cli
