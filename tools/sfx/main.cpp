// sfx: the ScalableFX command-line tool. Runs the SDK's effects on image files with any
// backend and tier, and reports what the machine's devices can do.
#include <iostream>
#include <vector>

#include "commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{"sfx - ScalableFX effects on image files (ambient obscurance, motion blur) and scene files (render)", "sfx"};
    app.require_subcommand(1);
    std::vector<sfx::cli::Command> commands;
    commands.push_back(sfx::cli::addInfoCommand(app));
    commands.push_back(sfx::cli::addAoCommand(app));
    commands.push_back(sfx::cli::addMotionBlurCommand(app));
    commands.push_back(sfx::cli::addTruthCommand(app));
    commands.push_back(sfx::cli::addRenderCommand(app));
    CLI11_PARSE(app, argc, argv);
    for (auto& c : commands)
        if (c.app && c.app->parsed()) return c.run();
    return 2;
}
