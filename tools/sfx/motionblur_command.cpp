#include "commands.hpp"

namespace sfx::cli {
// Placeholder until the motion blur effect lands (issue 4): the subcommand exists and says so.
Command addMotionBlurCommand(CLI::App& app) {
    Command c;
    c.app = app.add_subcommand("motionblur", "Motion blur on colour, depth and velocity files (not built yet)");
    c.run = [] { return 1; };
    return c;
}
}  // namespace sfx::cli
