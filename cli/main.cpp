// candela: wiring only. Picks the subcommand, maps errors to exit codes (architecture.md):
// 0 success, 2 bad input (one line "file:line: message" on stderr), 1 internal failure.
#include "cli/commands.h"
#include "base/error.h"

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"candela: lighting analysis by backward ray tracing"};
  app.set_version_flag("--version", std::string("candela ") + CANDELA_VERSION);
  app.require_subcommand(1);
  candela::cli::Action action;
  candela::cli::addPointsCommand(app, action);
  candela::cli::addSunCommand(app, action);
  candela::cli::addLuminaireCommand(app, action);
  candela::cli::addRunCommand(app, action);
  candela::cli::addValidateCommand(app, action);
  candela::cli::addRenderCommand(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "candela: " << candela::printable(e.what()) << "\n";
    return 2;
  }
  try {
    return action ? action() : 1;
  } catch (const candela::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "candela: internal error: " << candela::printable(e.what()) << "\n";
    return 1;
  }
}
