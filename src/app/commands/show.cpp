// pgm show: a network's variables and tables as readable text.

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <span>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm::cli {
namespace {

struct show_arguments {
  std::string model;
  std::string variable;
  int digits = 4;
};

std::string state_text(const variable& v, std::size_t s) {
  std::string text = v.states()[s];
  if (v.has_intervals()) {
    text += " [" + text::format_short(v.edges()[s]) + ", " + text::format_short(v.edges()[s + 1]) +
            (s + 1 == v.cardinality() ? "]" : ")");
  }
  return text;
}

void print_variable(const variable& v, std::ostream& out) {
  out << "  " << v.name() << ": " << v.cardinality() << " states: ";
  for (std::size_t s = 0; s < v.cardinality(); ++s) out << (s ? ", " : "") << state_text(v, s);
  const auto& tags = v.tags();
  if (!tags.empty()) {
    std::vector<std::string> parts;
    if (!tags.quantity.empty()) parts.push_back("quantity " + tags.quantity);
    if (!tags.unit.empty()) parts.push_back("unit " + tags.unit);
    if (!tags.role.empty()) parts.push_back("role " + tags.role);
    out << "  (" << text::join(parts) << ")";
  }
  out << '\n';
}

std::string pad(const std::string& text, std::size_t width, bool right = false) {
  if (text.size() >= width) return text;
  const std::string fill(width - text.size(), ' ');
  return right ? fill + text : text + fill;
}

void print_table(const cpt<double>& table, int digits, std::ostream& out) {
  out << "P(" << table.child().name();
  for (std::size_t p = 0; p < table.parents().size(); ++p) {
    out << (p ? ", " : " | ") << table.parents()[p].name();
  }
  out << ")";
  if (table.is_sparse()) {
    out << ", stored sparse: " << table.stored_configurations().size() << " of " << table.configurations()
        << " parent configurations, the rest alike";
  }
  out << "\n";
  std::vector<std::size_t> widths;
  for (const auto& p : table.parents()) {
    std::size_t w = p.name().size();
    for (const auto& s : p.states()) w = std::max(w, s.size());
    widths.push_back(w);
  }
  const auto number_width = static_cast<std::size_t>(digits) + 2;
  std::vector<std::size_t> state_widths;
  for (const auto& s : table.child().states()) state_widths.push_back(std::max(number_width, s.size()));

  out << "  ";
  for (std::size_t p = 0; p < widths.size(); ++p) out << pad(table.parents()[p].name(), widths[p]) << "  ";
  out << (widths.empty() ? "" : "| ");
  for (std::size_t x = 0; x < state_widths.size(); ++x) {
    out << (x ? "  " : "") << pad(table.child().states()[x], state_widths[x], true);
  }
  out << '\n';
  char buffer[64];
  auto print_column = [&](std::span<const double> column) {
    for (std::size_t x = 0; x < column.size(); ++x) {
      std::snprintf(buffer, sizeof buffer, "%.*f", digits, column[x]);
      out << (x ? "  " : "") << pad(buffer, state_widths[x], true);
    }
    out << '\n';
  };
  auto print_configuration = [&](std::size_t u) {
    const auto codes = table.parent_codes(config_index(u));
    out << "  ";
    for (std::size_t p = 0; p < codes.size(); ++p) out << pad(table.parents()[p].states()[codes[p]], widths[p]) << "  ";
    out << (widths.empty() ? "" : "| ");
    print_column(table.column(config_index(u)));
  };
  if (!table.is_sparse()) {
    for (std::size_t u = 0; u < table.configurations(); ++u) print_configuration(u);
    return;
  }
  for (const auto u : table.stored_configurations()) print_configuration(u);
  std::size_t width = 0;
  for (const auto w : widths) width += w + 2;
  out << "  " << pad("any other", width) << "| ";
  print_column(table.rest());
}

/// A factor as a table: one row per configuration of its scope but the last variable, one
/// column per state of the last.
void print_factor(std::size_t f, const factor_table& table, const std::vector<variable>& variables, int digits,
                  std::ostream& out) {
  const auto& scope = table.scope();
  out << "factor " << f << " over (";
  for (std::size_t k = 0; k < scope.size(); ++k) out << (k ? ", " : "") << variables[scope[k].value()].name();
  out << ")\n";
  if (scope.empty()) {
    out << "  " << text::format_short(table.values().front()) << '\n';
    return;
  }
  const auto& last = variables[scope.back().value()];
  std::vector<std::size_t> widths;
  for (std::size_t k = 0; k + 1 < scope.size(); ++k) {
    const auto& v = variables[scope[k].value()];
    std::size_t w = v.name().size();
    for (const auto& state : v.states()) w = std::max(w, state.size());
    widths.push_back(w);
  }
  std::vector<std::string> cells;
  std::size_t number_width = 0;
  char buffer[64];
  for (const double value : table.values()) {
    std::snprintf(buffer, sizeof buffer, "%.*g", std::max(digits, 1), value);
    cells.emplace_back(buffer);
    number_width = std::max(number_width, cells.back().size());
  }
  std::vector<std::size_t> state_widths;
  for (const auto& state : last.states()) state_widths.push_back(std::max(number_width, state.size()));
  out << "  ";
  for (std::size_t k = 0; k < widths.size(); ++k) out << pad(variables[scope[k].value()].name(), widths[k]) << "  ";
  out << (widths.empty() ? "" : "| ");
  for (std::size_t x = 0; x < state_widths.size(); ++x)
    out << (x ? "  " : "") << pad(last.states()[x], state_widths[x], true);
  out << '\n';
  const auto rows = table.values().size() / last.cardinality();
  std::vector<std::size_t> codes(widths.size(), 0);
  for (std::size_t row = 0; row < rows; ++row) {
    out << "  ";
    for (std::size_t k = 0; k < widths.size(); ++k) {
      out << pad(variables[scope[k].value()].states()[codes[k]], widths[k]) << "  ";
    }
    out << (widths.empty() ? "" : "| ");
    for (std::size_t x = 0; x < last.cardinality(); ++x) {
      out << (x ? "  " : "") << pad(cells[row * last.cardinality() + x], state_widths[x], true);
    }
    out << '\n';
    for (std::size_t k = widths.size(); k-- > 0;) {  // the next configuration, the last fastest
      if (++codes[k] < table.cardinalities()[k]) break;
      codes[k] = 0;
    }
  }
}

void show_markov(const show_arguments& args, const markov_network& model) {
  auto& out = std::cout;
  variable_id only{};
  if (!args.variable.empty()) only = model.id(args.variable);  // unknown names fail here
  std::size_t cells = 0;
  for (const auto& f : model.factors()) cells += f.values().size();
  out << args.model << ": a Markov network of " << model.size() << " variables, " << model.factor_count()
      << " factors, " << cells << " values\n\nvariables\n";
  for (const auto& v : model.variables()) {
    if (args.variable.empty() || v.name() == args.variable) print_variable(v, out);
  }
  for (std::size_t f = 0; f < model.factor_count(); ++f) {
    const auto& scope = model.factor_scope(f);
    if (!args.variable.empty() && std::find(scope.begin(), scope.end(), only) == scope.end()) continue;
    out << '\n';
    print_factor(f, model.factor(f), model.variables(), args.digits, out);
  }
}

void run_show(const show_arguments& args) {
  if (const auto markov = read_markov_network_file(args.model)) {
    show_markov(args, *markov);
    return;
  }
  auto document = read_model_file(args.model);
  auto& structure = document.structure;
  auto& tables = document.tables;
  auto& out = std::cout;
  if (!args.variable.empty()) static_cast<void>(structure.id(args.variable));  // unknown names fail here
  out << args.model << ": " << structure.size() << " variables, " << structure.graph().edge_count() << " edges";
  if (tables) {
    std::size_t free = 0;
    for (const auto& t : *tables) free += (t.child_cardinality() - 1) * t.configurations();
    out << ", " << free << " free parameters";
  } else {
    out << ", no tables (a structure)";
  }
  out << "\n\nvariables\n";
  for (const auto& v : structure.variables()) {
    if (args.variable.empty() || v.name() == args.variable) print_variable(v, out);
  }
  if (!tables) {
    out << "\nedges\n";
    for (const auto& e : structure.edges()) out << "  " << e.from << " -> " << e.to << '\n';
    return;
  }
  for (const auto& table : *tables) {
    if (!args.variable.empty() && table.child().name() != args.variable) continue;
    out << '\n';
    print_table(table, args.digits, out);
  }
}

}  // namespace

void add_show_command(CLI::App& app) {
  auto args = std::make_shared<show_arguments>();
  auto* cmd = app.add_subcommand(
      "show",
      "Print a model's variables and tables (a Markov network's factors)\nExamples:\n  pgm show alarm.bif "
      "--variable HR\n  pgm show Grids_11.uai --variable 0");
  cmd->add_option("model", args->model,
                  "Network or structure file (" + network_file_kinds() + "; a MARKOV .uai is a Markov network)")
      ->required();
  cmd->add_option("--variable", args->variable,
                  "Show only this variable and its table (in a Markov network, the factors that hold it)");
  cmd->add_option("--digits", args->digits,
                  "Decimals of the probabilities (significant digits of a Markov network's factor values)")
      ->check(CLI::Range(0, 17))
      ->capture_default_str();
  cmd->callback([args] { run_show(*args); });
}

}  // namespace pgm::cli
