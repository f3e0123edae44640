// The `pgm` program: each command lives in src/commands and only parses arguments, calls the
// library and prints. Errors in the input end the program with one line on stderr and exit
// code 1; usage errors with code 2.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <new>

#include "cli/common.hpp"
#include "pgm/core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"pgm: causal Bayesian networks for robot tasks, with priors transferred between tasks", "pgm"};
  app.require_subcommand(1, 1);
  app.set_version_flag("--version", "pgm 0.1.0");
  pgm::cli::add_discretize_command(app);
  pgm::cli::add_fit_command(app);
  pgm::cli::add_show_command(app);
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here with 0; every usage error exits with 2.
    return app.exit(e) == 0 ? 0 : 2;
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
  return 0;
}
