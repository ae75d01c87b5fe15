// The subcommands of `sfx`; each lives in its own file and registers itself on the app.
#pragma once

#include <CLI/CLI.hpp>

namespace sfx::cli {

// Each adds its subcommand; `run` is set to the code that executes it after parsing.
struct Command {
    CLI::App* app = nullptr;
    std::function<int()> run;
};

Command addInfoCommand(CLI::App& app);        // info_command.cpp: backends, caps, tiers, plan
Command addAoCommand(CLI::App& app);          // ao_command.cpp
Command addMotionBlurCommand(CLI::App& app);  // motionblur_command.cpp
Command addTruthCommand(CLI::App& app);       // truth_command.cpp: ray-traced AO ground truth
Command addRenderCommand(CLI::App& app);      // render_command.cpp: scene files

}  // namespace sfx::cli
