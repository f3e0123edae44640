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

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/text.hpp"

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
  [[nodiscard]] PGM_DECL static variable intervals(std::string name, std::vector<double> edges,
                                                   semantic_tags tags = {});

  /// Intervals with labels of the caller's choosing (one fewer label than edges).
  [[nodiscard]] PGM_DECL static variable with_edges(std::string name, std::vector<std::string> states,
                                                    std::vector<double> edges, semantic_tags tags = {});

  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  [[nodiscard]] const std::vector<std::string>& states() const noexcept { return states_; }
  [[nodiscard]] std::size_t cardinality() const noexcept { return states_.size(); }
  [[nodiscard]] const semantic_tags& tags() const noexcept { return tags_; }
  [[nodiscard]] const std::string& label(state_index state) const { return states_.at(state.value()); }

  /// The interval edges (cardinality()+1 values), or empty for a purely categorical variable.
  [[nodiscard]] const std::vector<double>& edges() const noexcept { return edges_; }
  [[nodiscard]] bool has_intervals() const noexcept { return !edges_.empty(); }

  [[nodiscard]] PGM_DECL std::optional<state_index> find_state(std::string_view label) const;

  /// The state with this label; throws model_error naming the variable and its states.
  [[nodiscard]] PGM_DECL state_index state(std::string_view label) const;

  /// Where a state lies on the variable's scale: the midpoint of its interval, or its label
  /// read as a number. Nothing for a categorical state.
  [[nodiscard]] PGM_DECL std::optional<double> midpoint(state_index state) const;

  /// The state whose interval holds `value`; values outside the edges go to the outer states.
  /// Requires intervals. Intervals are closed on the left: [edges[i], edges[i+1]). In the header:
  /// it is called once per value.
  [[nodiscard]] state_index bin(double value) const {
    const auto inner_begin = edges_.begin() + 1;
    const auto inner_end = edges_.end() - 1;
    return index_at<state_index>(std::upper_bound(inner_begin, inner_end, value) - inner_begin);
  }

  [[nodiscard]] PGM_DECL variable with_tags(semantic_tags tags) const;

  /// The same states with interval edges attached (or removed, with an empty vector).
  PGM_DECL void set_edges(std::vector<double> edges);

  friend bool operator==(const variable&, const variable&) = default;

 private:
  PGM_DECL void validate() const;

  std::string name_;
  std::vector<std::string> states_;
  semantic_tags tags_;
  std::vector<double> edges_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/variable.ipp"
#endif
