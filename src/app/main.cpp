// The `pgm` program: each command lives in src/app/commands and only parses arguments, calls the
// library and prints. Errors in the input end the program with one line on stderr and exit
// code 1; usage errors with code 2.
//
// Started by mpirun or srun (src/app/cli/launch.hpp), the program joins the job's MPI processes:
// the commands that scale out split their work over them, only process 0 prints, and every
// process ends with the same exit code after agreeing on the failure, if any
// (pgm/core/process_group.hpp).

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <string>

#include "cli/common.hpp"
#include "cli/launch.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/process_group.hpp"
#include "pgm/core/text.hpp"
#include "pgm/version.hpp"
#ifdef PGM_WITH_MPI
#include "mpi/mpi_processes.hpp"
#endif

namespace {

/// Prints `failure` and returns the exit code it ends the program with.
int report(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const pgm::memory_limit_exceeded& e) {
    std::cerr << "pgm: error: " << pgm::text::printable(e.what()) << '\n';
    return 1;
  } catch (const pgm::table_too_large& e) {
    std::cerr << "pgm: error: " << pgm::text::printable(e.what()) << '\n';
    // A table made large by a variable's states ("5000 states × 5000 parent configurations"),
    // not by its number of parents: most often a continuous column read as labels.
    if (std::string_view(e.what()).find(" states × ") != std::string_view::npos) {
      std::cerr << "pgm: hint: a variable with that many states is usually a continuous column read as labels; bin "
                   "it with --discretization (or pgm discretize) first\n";
    }
    return 1;
  } catch (const pgm::missing_value_error& e) {
    std::cerr << "pgm: error: " << pgm::text::printable(e.what()) << '\n'
              << "pgm: hint: --missing drop leaves out the rows that have a missing value, --missing available counts "
                 "each table over the rows where its variables are present; --na names the texts read as missing "
                 "(default NA,,?: NA, the empty field and ?)\n";
    return 1;
  } catch (const pgm::error& e) {
    // A message may quote a bad file's bytes: shown escaped, never obeyed by the terminal.
    std::cerr << "pgm: error: " << pgm::text::printable(e.what()) << '\n';
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "pgm: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "pgm: internal error: " << pgm::text::printable(e.what()) << '\n';
    return 3;
  }
}

/// Flushes standard output and returns the error that kept it from being written, if any (a
/// full disk, a closed pipe, /dev/full): a command whose output is lost has not succeeded.
std::optional<std::string> standard_output_failure() {
  errno = 0;
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  if (!failed) return std::nullopt;
  return std::string("cannot write to standard output") + (errno != 0 ? std::string(": ") + std::strerror(errno) : "");
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
  auto& processes = pgm::processes();
  // Process 0 speaks for all: the others' output would repeat its own.
  if (processes.rank() != 0) {
    std::cout.rdbuf(nullptr);
    std::cerr.rdbuf(nullptr);
  }

  CLI::App app{"pgm: causal Bayesian networks for robot tasks, with priors transferred between tasks", "pgm"};
  app.require_subcommand(1, 1);
  app.set_version_flag("--version", std::string("pgm ") + pgm::version);
  pgm::cli::add_discretize_command(app);
  pgm::cli::add_fit_command(app);
  pgm::cli::add_update_command(app);
  pgm::cli::add_show_command(app);
  pgm::cli::add_draw_command(app);
  pgm::cli::add_plot_table_command(app);
  pgm::cli::add_convert_command(app);
  pgm::cli::add_transfer_command(app);
  pgm::cli::add_correspond_command(app);
  pgm::cli::add_learn_structure_command(app);
  pgm::cli::add_score_command(app);
  pgm::cli::add_experiment_command(app);
  pgm::cli::add_report_command(app);
  pgm::cli::add_simulate_command(app);
  pgm::cli::add_calibrate_command(app);
  pgm::cli::add_predict_command(app);
  pgm::cli::add_query_command(app);
  pgm::cli::add_solve_command(app);
  pgm::cli::add_prevent_command(app);
  pgm::cli::add_decide_command(app);
  pgm::cli::add_dsep_command(app);
  pgm::cli::add_counterfactual_command(app);
  pgm::cli::add_components_command(app);
  pgm::cli::add_check_command(app);
  pgm::cli::add_sample_command(app);
  pgm::cli::add_unroll_command(app);
  pgm::cli::add_filter_command(app);
  std::exception_ptr failure;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here with 0; every usage error exits with 2. Every process
    // parses the same arguments, so all end here alike, before any collective step.
    if (app.exit(e) != 0) return 2;
    if (const auto problem = standard_output_failure()) {  // --help > /dev/full
      std::cerr << "pgm: error: " << *problem << '\n';
      return 1;
    }
    return 0;
  } catch (...) {
    failure = std::current_exception();
  }
  // Output that did not reach standard output is a failure like any other (process 0 alone
  // prints: the others' standard output is closed on purpose).
  if (!failure && processes.rank() == 0) {
    if (auto problem = standard_output_failure()) failure = std::make_exception_ptr(pgm::io_error(std::move(*problem)));
  }
  // A process that failed outside an agreed phase meets the others here (or at their next
  // agreement, which is the same collective step).
  if (processes.size() > 1 && !processes.failed()) {
    try {
      pgm::agree(processes, failure);
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
