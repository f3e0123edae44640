#pragma once
// The definitions of pgm/io/policy_csv.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/text.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/policy_csv.hpp"

namespace pgm {

namespace detail {

/// What each decision may observe: its parents and the evidence, and with perfect recall every
/// earlier decision and what that one could observe.
inline std::map<variable_id, std::set<variable_id>> known_at_decisions(const influence_diagram& diagram,
                                                                       const evidence& observed, bool limited_memory) {
  std::set<variable_id> earlier;
  for (const auto& [name, state] : observed) {
    if (diagram.contains(name)) earlier.insert(diagram.id(name));
  }
  std::map<variable_id, std::set<variable_id>> known;
  for (const auto d : diagram.decision_order()) {
    auto here = earlier;
    for (const auto parent : diagram.parents(d)) here.insert(parent);
    known[d] = here;
    if (!limited_memory) {
      earlier = std::move(here);
      earlier.insert(d);
    }
  }
  return known;
}

/// One decision's rows as read: the variables its rows name, and the action and line of each
/// configuration given.
struct policy_rows {
  std::vector<variable_id> observed;
  std::size_t first_line = 0;
  std::map<std::size_t, std::pair<std::size_t, std::size_t>> actions;  // configuration -> (action, line)
};

}  // namespace detail

PGM_DECL std::vector<decision_policy> parse_policy_csv(std::string_view text, const std::string& source,
                                                       const influence_diagram& diagram, const evidence& observed,
                                                       bool limited_memory) {
  detail::csv_scanner scanner(text, source, ',');
  std::vector<detail::csv_field> fields;
  const auto fail = [&](const detail::csv_field& field, const std::string& what) -> parse_error {
    return parse_error(source, field.line, field.column, what);
  };
  if (!scanner.next(fields)) throw parse_error(source, 1, 1, "expected the header decision,observed,action");
  if (fields.size() != 3 || fields[0].text != "decision" || fields[1].text != "observed" ||
      fields[2].text != "action") {
    throw fail(fields[0], "expected the header decision,observed,action");
  }
  std::vector<std::string> decision_names;
  for (const auto d : diagram.decision_order()) decision_names.push_back(diagram.at(d).name());
  const auto known = detail::known_at_decisions(diagram, observed, limited_memory);
  std::map<variable_id, detail::policy_rows> read;
  while (scanner.next(fields)) {
    if (fields.size() != 3) {
      throw fail(fields.back(),
                 "expected 3 fields (decision, observed, action), found " + std::to_string(fields.size()));
    }
    const std::string name(fields[0].text);
    if (!diagram.contains(name) || !diagram.is_decision(diagram.id(name))) {
      throw fail(fields[0], "'" + text::printable(name) +
                                "' is not a decision of the diagram (decisions: " + text::join(decision_names) + ")");
    }
    const auto d = diagram.id(name);
    // The observed variables and their states, "A=a,B=b".
    std::vector<variable_id> variables;
    std::vector<std::size_t> states;
    for (const auto& pair : text::split(fields[1].text, ',')) {
      const auto equals = pair.find('=');
      if (equals == std::string::npos) {
        throw fail(fields[1], "expected VARIABLE=STATE, found '" + text::printable(pair) + "'");
      }
      const auto variable_name = std::string(text::trim(std::string_view(pair).substr(0, equals)));
      const auto state = std::string(text::trim(std::string_view(pair).substr(equals + 1)));
      if (!diagram.contains(variable_name)) {
        throw fail(fields[1], "no variable '" + text::printable(variable_name) + "' in the diagram");
      }
      const auto id = diagram.id(variable_name);
      if (!known.at(d).contains(id)) {
        std::vector<std::string> names;
        for (const auto k : known.at(d)) names.push_back(diagram.at(k).name());
        throw fail(fields[1], "'" + variable_name + "' is not known when '" + name +
                                  "' is taken (known then: " + (names.empty() ? "nothing" : text::join(names)) + ")");
      }
      if (std::find(variables.begin(), variables.end(), id) != variables.end()) {
        throw fail(fields[1], "'" + variable_name + "' is named twice");
      }
      const auto& labels = diagram.at(id).states();
      const auto at = std::find(labels.begin(), labels.end(), state);
      if (at == labels.end()) {
        throw fail(fields[1], "'" + variable_name + "' has no state '" + text::printable(state) +
                                  "' (states: " + text::join(labels) + ")");
      }
      variables.push_back(id);
      states.push_back(static_cast<std::size_t>(at - labels.begin()));
    }
    const auto& actions = diagram.at(d).states();
    const auto action = std::find(actions.begin(), actions.end(), fields[2].text);
    if (action == actions.end()) {
      throw fail(fields[2], "'" + name + "' has no action '" + text::printable(fields[2].text) +
                                "' (actions: " + text::join(actions) + ")");
    }
    auto [entry, first] = read.try_emplace(d);
    auto& rows = entry->second;
    if (first) {
      rows.observed = variables;
      rows.first_line = scanner.record_line();
    } else if (variables != rows.observed) {
      std::vector<std::string> names;
      for (const auto id : rows.observed) names.push_back(diagram.at(id).name());
      throw fail(fields[1], "every row of '" + name + "' names the variables its first (line " +
                                std::to_string(rows.first_line) +
                                ") names: " + (names.empty() ? std::string("none") : text::join(names)));
    }
    std::vector<std::size_t> cards;
    std::size_t configurations = 1;
    for (const auto id : variables) {
      cards.push_back(diagram.at(id).cardinality());
      configurations = detail::saturating_multiply(configurations, cards.back());
    }
    if (configurations > max_table_cells) {
      throw fail(fields[1], "a policy of '" + name + "' over these variables has more than " +
                                std::to_string(max_table_cells) + " configurations");
    }
    const auto configuration = mixed_radix(cards).encode(states);
    const auto [given, fresh] = rows.actions.try_emplace(
        configuration, static_cast<std::size_t>(action - actions.begin()), scanner.record_line());
    if (!fresh) {
      throw fail(fields[1], "'" + name + "' already has a row for '" + text::printable(fields[1].text) + "' (line " +
                                std::to_string(given->second.second) + ")");
    }
  }
  std::vector<decision_policy> policies;
  for (const auto d : diagram.decision_order()) {
    const auto& name = diagram.at(d).name();
    const auto it = read.find(d);
    if (it == read.end()) {
      throw parse_error(source, scanner.line(), 1, "no policy for the decision '" + name + "'");
    }
    const auto& rows = it->second;
    std::vector<std::size_t> cards;
    for (const auto id : rows.observed) cards.push_back(diagram.at(id).cardinality());
    const mixed_radix configurations(cards);
    decision_policy policy{d, rows.observed, std::vector<std::size_t>(configurations.size(), 0)};
    std::vector<std::size_t> states(cards.size());
    for (std::size_t c = 0; c < configurations.size(); ++c) {
      const auto given = rows.actions.find(c);
      if (given != rows.actions.end()) {
        policy.actions[c] = given->second.first;
        continue;
      }
      // A configuration the evidence rules out never happens: its action is never taken.
      configurations.decode(c, states);
      bool ruled_out = false;
      std::vector<std::string> setting;
      for (std::size_t k = 0; k < states.size(); ++k) {
        const auto& v = diagram.at(rows.observed[k]);
        const auto seen = observed.find(v.name());
        if (seen != observed.end() && seen->second != v.states()[states[k]]) ruled_out = true;
        setting.push_back(v.name() + "=" + v.states()[states[k]]);
      }
      if (!ruled_out) {
        throw parse_error(source, rows.first_line, 1, "no row for '" + name + "' given " + text::join(setting, ","));
      }
    }
    policies.push_back(std::move(policy));
  }
  return policies;
}

PGM_DECL std::vector<decision_policy> read_policy_csv(const std::filesystem::path& path,
                                                      const influence_diagram& diagram, const evidence& observed,
                                                      bool limited_memory) {
  return parse_policy_csv(read_file(path), path.string(), diagram, observed, limited_memory);
}

}  // namespace pgm
