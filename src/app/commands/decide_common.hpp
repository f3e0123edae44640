#pragma once
// Shared by `pgm predict` and `pgm prevent`: reading the model with its success event and
// describing states for people.

#include <CLI/CLI.hpp>
#include <string>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/decide/assignment.hpp"
#include "pgm/decide/predict.hpp"
#include "pgm/io/decision_model.hpp"

namespace pgm::cli {

/// The options `pgm predict` and `pgm prevent` share: the model, the plan, the success event and
/// what to do with unassigned parents.
struct decision_arguments {
  std::string model;
  std::string assign;
  std::string success;
  bool marginalize = false;
};

/// Adds --model, --assign (required unless the command checks it itself), --success and
/// --marginalize to `command`.
void add_decision_options(CLI::App& command, decision_arguments& args, bool assign_required = true);

/// Reads the model (any network format) and settles the success event (pgm::read_decision_model).
decision_model read_decision_model(const std::string& path, const std::string& success_text);

/// "2 [-0.4, 0.4) cm" for an interval state, the label otherwise.
std::string describe_state(const variable& v, std::size_t state);

/// Parses --assign, noting each number that lies outside its variable's fitted range (it
/// counts in the outer interval, which then misdescribes it).
assignment read_assignment(const std::string& text, const bayesian_network& network);

/// "0.3 cm" / "0.3": a number in a variable's unit.
std::string with_unit(const variable& v, double value);

}  // namespace pgm::cli
