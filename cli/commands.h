// Each subcommand lives in its own cmd_*.cpp and registers itself on the app here.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace candela::cli {

// A subcommand's action: returns the process exit code (0 ok). Input errors are thrown as
// candela::InputError and become exit code 2 in main.cpp.
using Action = std::function<int()>;

void addPointsCommand(CLI::App& app, Action& action);
void addSunCommand(CLI::App& app, Action& action);
void addLuminaireCommand(CLI::App& app, Action& action);
void addRunCommand(CLI::App& app, Action& action);
void addValidateCommand(CLI::App& app, Action& action);
void addRenderCommand(CLI::App& app, Action& action);
void addMergeCommand(CLI::App& app, Action& action);

}  // namespace candela::cli
