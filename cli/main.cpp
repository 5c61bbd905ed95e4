// candela: wiring only. Picks the subcommand, maps errors to exit codes (architecture.md):
// 0 success, 2 bad input (one line "file:line: message" on stderr), 1 internal failure.
// Under mpirun every rank runs this program (docs/distributed.md); rank 0 prints.
#include "cli/commands.h"
#include "cli/processes.h"
#include "base/error.h"
#include "study/distributed/mpi_distribution.h"

#include <exception>
#include <iostream>
#include <memory>
#include <string>

namespace {

int run(int argc, char** argv, const candela::MpiSession& mpi) {
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
  candela::cli::addMergeCommand(app, action);
  // Under mpirun every rank parses the same command line: rank 0 says what is wrong.
  const int rank = mpi.distribution().rank();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return rank == 0 ? app.exit(e) : 0;
  } catch (const CLI::CallForAllHelp& e) {
    return rank == 0 ? app.exit(e) : 0;
  } catch (const CLI::CallForVersion& e) {
    return rank == 0 ? app.exit(e) : 0;
  } catch (const CLI::ParseError& e) {
    if (rank == 0) std::cerr << "candela: " << candela::printable(e.what()) << "\n";
    return 2;
  }
  // Under mpirun every rank runs the command: only those that share their work may.
  if (mpi.distribution().ranks() > 1)
    for (const char* one : {"sun", "luminaire", "validate", "merge"})
      if (app.got_subcommand(one)) {
        if (rank == 0)
          std::cerr << "command line: candela " << one
                    << " is one process: run it without mpirun (run, points and render share their work)\n";
        return 2;
      }
  try {
    return action ? action() : 1;
  } catch (const candela::InputError& e) {
    // Every rank reads the same input and finds the same error: rank 0 says it.
    if (rank == 0) std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "candela: internal error" << (mpi.active() ? " on rank " + std::to_string(rank) : "") << ": "
              << candela::printable(e.what()) << "\n";
    // The other ranks may be waiting for this one: end them all.
    mpi.abort(1);
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::unique_ptr<candela::MpiSession> mpi;
  try {
    mpi = std::make_unique<candela::MpiSession>(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "candela: " << candela::printable(e.what()) << "\n";
    return 1;
  }
  candela::cli::setProcesses(mpi->distribution());
  return run(argc, argv, *mpi);
}
