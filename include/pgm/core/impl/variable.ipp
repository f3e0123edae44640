#pragma once
// The definitions of pgm/core/variable.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/variable.hpp"

namespace pgm {

PGM_DECL variable variable::intervals(std::string name, std::vector<double> edges, semantic_tags tags) {
  if (edges.size() < 2) {
    throw model_error("variable '" + name + "': interval edges need at least two values");
  }
  std::vector<std::string> labels;
  labels.reserve(edges.size() - 1);
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) labels.push_back(std::to_string(i));
  return with_edges(std::move(name), std::move(labels), std::move(edges), std::move(tags));
}

PGM_DECL variable variable::with_edges(std::string name, std::vector<std::string> states, std::vector<double> edges,
                                       semantic_tags tags) {
  variable result(std::move(name), std::move(states), std::move(tags));
  result.set_edges(std::move(edges));
  return result;
}

PGM_DECL std::optional<state_index> variable::find_state(std::string_view label) const {
  const auto it = std::find(states_.begin(), states_.end(), label);
  if (it == states_.end()) return std::nullopt;
  return index_at<state_index>(it - states_.begin());
}

PGM_DECL state_index variable::state(std::string_view label) const {
  if (auto found = find_state(label)) return *found;
  throw model_error("variable '" + name_ + "' has no state '" + std::string(label) +
                    "' (states: " + text::list_for_message(states_) + ")");
}

PGM_DECL std::optional<double> variable::midpoint(state_index state) const {
  const auto i = state.value();
  if (has_intervals()) return 0.5 * (edges_[i] + edges_[i + 1]);
  auto value = text::parse_double(states_.at(i));
  if (value && std::isfinite(*value)) return value;
  return std::nullopt;
}

PGM_DECL variable variable::with_tags(semantic_tags tags) const {
  variable copy = *this;
  copy.tags_ = std::move(tags);
  return copy;
}

PGM_DECL void variable::set_edges(std::vector<double> edges) {
  if (!edges.empty()) {
    if (edges.size() != states_.size() + 1) {
      throw model_error("variable '" + name_ + "': " + std::to_string(states_.size()) + " states need " +
                        std::to_string(states_.size() + 1) + " interval edges, got " + std::to_string(edges.size()));
    }
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (!std::isfinite(edges[i]) || (i > 0 && !(edges[i - 1] < edges[i]))) {
        throw model_error("variable '" + name_ + "': interval edges must be finite and strictly increasing");
      }
    }
  }
  edges_ = std::move(edges);
}

PGM_DECL void variable::validate() const {
  if (name_.empty()) throw model_error("a variable needs a name");
  for (char c : name_) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',') {
      throw model_error("variable name '" + name_ + "' contains whitespace or a comma");
    }
  }
  if (states_.empty()) throw model_error("variable '" + name_ + "' has no states");
  std::vector<std::string_view> sorted(states_.begin(), states_.end());
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (sorted[i].empty()) throw model_error("variable '" + name_ + "' has an empty state label");
    if (i > 0 && sorted[i] == sorted[i - 1]) {
      throw model_error("variable '" + name_ + "' has the state '" + std::string(sorted[i]) + "' twice");
    }
  }
}

}  // namespace pgm
