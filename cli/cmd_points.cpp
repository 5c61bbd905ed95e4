#include "cli/commands.h"
namespace candela::cli {
void addPointsCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("points", "illuminance at sensor points (CSV on stdout)");
  cmd->callback([&action] { action = [] { return 1; }; });
}
}  // namespace candela::cli
