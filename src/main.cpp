// The `pgm` program: each command lives in src/commands and only parses arguments, calls the
// library and prints. Errors in the input end the program with one line on stderr and exit
// code 1; usage errors with code 2.
//
// Started by mpirun or srun (src/cli/launch.hpp), the program joins the job's MPI processes:
// the commands that scale out split their work over them, only process 0 prints, and every
// process ends with the same exit code after agreeing on the failure, if any
// (pgm/detail/process_group.hpp).

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <new>
#include <optional>

#include "cli/common.hpp"
#include "cli/launch.hpp"
#include "pgm/core/error.hpp"
#include "pgm/detail/process_group.hpp"
#ifdef PGM_WITH_MPI
#include "mpi/mpi_processes.hpp"
#endif

namespace {

/// Prints `failure` and returns the exit code it ends the program with.
int report(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const pgm::table_too_large& e) {
    std::cerr << "pgm: error: " << e.what() << '\n'
              << "pgm: hint: a variable with that many states is usually a continuous column read as labels; bin it "
                 "with --discretization (or pgm discretize) first\n";
    return 1;
  } catch (const pgm::error& e) {
    std::cerr << "pgm: error: " << e.what() << '\n';
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "pgm: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "pgm: internal error: " << e.what() << '\n';
    return 3;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const auto launch = pgm::cli::read_launch();
#ifdef PGM_WITH_MPI
  std::optional<pgm::mpi::mpi_session> mpi;
  if (launch.launched) mpi.emplace(argc, argv);
#else
  if (launch.launched && launch.processes.value_or(1) > 1) {
    std::cerr << "pgm: error: started as one of " << *launch.processes
              << " processes (mpirun or srun), but this pgm was built without MPI (-DPGM_WITH_MPI=ON)\n";
    return 1;
  }
#endif
  auto& processes = pgm::detail::processes();
  // Process 0 speaks for all: the others' output would repeat its own.
  if (processes.rank() != 0) {
    std::cout.rdbuf(nullptr);
    std::cerr.rdbuf(nullptr);
  }

  CLI::App app{"pgm: causal Bayesian networks for robot tasks, with priors transferred between tasks", "pgm"};
  app.require_subcommand(1, 1);
  app.set_version_flag("--version", "pgm 0.1.0");
  pgm::cli::add_discretize_command(app);
  pgm::cli::add_fit_command(app);
  pgm::cli::add_show_command(app);
  pgm::cli::add_convert_command(app);
  pgm::cli::add_transfer_command(app);
  pgm::cli::add_correspond_command(app);
  pgm::cli::add_learn_structure_command(app);
  pgm::cli::add_experiment_command(app);
  pgm::cli::add_report_command(app);
  pgm::cli::add_simulate_command(app);
  pgm::cli::add_calibrate_command(app);
  pgm::cli::add_predict_command(app);
  pgm::cli::add_query_command(app);
  pgm::cli::add_prevent_command(app);
  std::exception_ptr failure;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here with 0; every usage error exits with 2. Every process
    // parses the same arguments, so all end here alike, before any collective step.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (...) {
    failure = std::current_exception();
  }
  // A process that failed outside an agreed phase meets the others here (or at their next
  // agreement, which is the same collective step).
  if (processes.size() > 1 && !processes.failed()) {
    try {
      pgm::detail::agree(processes, failure);
    } catch (...) {
      failure = std::current_exception();
    }
  }
  if (failure) return report(failure);
  if (launch.launched) {
    std::cerr << "pgm: " << app.get_subcommands().front()->get_name() << " ran on " << processes.size()
              << (processes.size() == 1 ? " process\n" : " processes\n");
  }
  return 0;
}
