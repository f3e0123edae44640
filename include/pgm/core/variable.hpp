#pragma once
/// \file
/// `variable`: a named discrete random variable with ordered states. A discretized quantity
/// also keeps the interval edges of its states, so that new data is binned the same way and
/// states of two differently discretized variables can be matched by value.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/detail/text.hpp"

namespace pgm {

/// What a variable means, used to match variables of two tasks: the physical quantity it
/// measures ("x-offset"), its unit ("cm") and the object it belongs to ("cubeUp2").
struct semantic_tags {
  std::string quantity;
  std::string unit;
  std::string role;

  [[nodiscard]] bool empty() const noexcept { return quantity.empty() && unit.empty() && role.empty(); }
  friend bool operator==(const semantic_tags&, const semantic_tags&) = default;
};

class variable {
 public:
  /// A variable with the given state labels, in order. Throws model_error on an empty name,
  /// no states, an empty or a repeated label.
  variable(std::string name, std::vector<std::string> states, semantic_tags tags = {})
      : name_(std::move(name)), states_(std::move(states)), tags_(std::move(tags)) {
    validate();
  }

  /// A discretized quantity: state i is the interval [edges[i], edges[i+1]), labelled "i".
  /// Edges must be finite and strictly increasing.
  [[nodiscard]] static variable intervals(std::string name, std::vector<double> edges, semantic_tags tags = {}) {
    if (edges.size() < 2) {
      throw model_error("variable '" + name + "': interval edges need at least two values");
    }
    std::vector<std::string> labels;
    labels.reserve(edges.size() - 1);
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) labels.push_back(std::to_string(i));
    return with_edges(std::move(name), std::move(labels), std::move(edges), std::move(tags));
  }

  /// Intervals with labels of the caller's choosing (one fewer label than edges).
  [[nodiscard]] static variable with_edges(std::string name, std::vector<std::string> states, std::vector<double> edges,
                                           semantic_tags tags = {}) {
    variable result(std::move(name), std::move(states), std::move(tags));
    result.set_edges(std::move(edges));
    return result;
  }

  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  [[nodiscard]] const std::vector<std::string>& states() const noexcept { return states_; }
  [[nodiscard]] std::size_t cardinality() const noexcept { return states_.size(); }
  [[nodiscard]] const semantic_tags& tags() const noexcept { return tags_; }
  [[nodiscard]] const std::string& label(state_index state) const { return states_.at(state.value()); }

  /// The interval edges (cardinality()+1 values), or empty for a purely categorical variable.
  [[nodiscard]] const std::vector<double>& edges() const noexcept { return edges_; }
  [[nodiscard]] bool has_intervals() const noexcept { return !edges_.empty(); }

  [[nodiscard]] std::optional<state_index> find_state(std::string_view label) const {
    const auto it = std::find(states_.begin(), states_.end(), label);
    if (it == states_.end()) return std::nullopt;
    return state_index(static_cast<state_index::rep>(it - states_.begin()));
  }

  /// The state with this label; throws model_error naming the variable and its states.
  [[nodiscard]] state_index state(std::string_view label) const {
    if (auto found = find_state(label)) return *found;
    throw model_error("variable '" + name_ + "' has no state '" + std::string(label) +
                      "' (states: " + detail::list_for_message(states_) + ")");
  }

  /// Where a state lies on the variable's scale: the midpoint of its interval, or its label
  /// read as a number. Nothing for a categorical state.
  [[nodiscard]] std::optional<double> midpoint(state_index state) const {
    const auto i = state.value();
    if (has_intervals()) return 0.5 * (edges_[i] + edges_[i + 1]);
    auto value = detail::parse_double(states_.at(i));
    if (value && std::isfinite(*value)) return value;
    return std::nullopt;
  }

  /// The state whose interval holds `value`; values outside the edges go to the outer states.
  /// Requires intervals. Intervals are closed on the left: [edges[i], edges[i+1]).
  [[nodiscard]] state_index bin(double value) const {
    const auto inner_begin = edges_.begin() + 1;
    const auto inner_end = edges_.end() - 1;
    return state_index(static_cast<state_index::rep>(std::upper_bound(inner_begin, inner_end, value) - inner_begin));
  }

  [[nodiscard]] variable with_tags(semantic_tags tags) const {
    variable copy = *this;
    copy.tags_ = std::move(tags);
    return copy;
  }

  /// The same states with interval edges attached (or removed, with an empty vector).
  void set_edges(std::vector<double> edges) {
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

  friend bool operator==(const variable&, const variable&) = default;

 private:
  void validate() const {
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

  std::string name_;
  std::vector<std::string> states_;
  semantic_tags tags_;
  std::vector<double> edges_;
};

}  // namespace pgm
