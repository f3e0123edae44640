#pragma once
/// \file
/// `markov_network`: an undirected graphical model, or factor graph: named discrete variables and
/// any number of non-negative factors over any scopes. P(x) = Π_f φ_f(x_f) / Z, Z the partition
/// function. A variable may be in no factor (it is then uniform). What the UAI competitions'
/// `MARKOV` files hold, and what libDAI's `FactorGraph` and pgmpy's `MarkovNetwork` hold.

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/factor_table.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/variable.hpp"

namespace pgm {

class markov_network {
 public:
  /// The empty model: no variables, no factors.
  markov_network() = default;

  /// Throws model_error for two variables of one name, or a factor whose scope names a variable
  /// that does not exist or disagrees with a variable's cardinality (naming the factor).
  PGM_DECL markov_network(std::vector<variable> variables, std::vector<factor_table> factors);

  [[nodiscard]] const std::vector<variable>& variables() const noexcept { return variables_; }
  [[nodiscard]] std::size_t size() const noexcept { return variables_.size(); }
  /// The id of a variable; throws model_error naming the unknown one and the known ones.
  [[nodiscard]] PGM_DECL variable_id id(std::string_view name) const;
  [[nodiscard]] const variable& at(std::string_view name) const { return variables_[id(name).value()]; }

  [[nodiscard]] std::size_t factor_count() const noexcept { return factors_.size(); }
  [[nodiscard]] const std::vector<factor_table>& factors() const noexcept { return factors_; }
  [[nodiscard]] const factor_table& factor(std::size_t f) const { return factors_.at(f); }
  [[nodiscard]] const std::vector<variable_id>& factor_scope(std::size_t f) const { return factors_.at(f).scope(); }

  friend bool operator==(const markov_network& a, const markov_network& b) {
    return a.variables_ == b.variables_ && a.factors_ == b.factors_;
  }

 private:
  std::vector<variable> variables_;
  std::vector<factor_table> factors_;
  std::map<std::string, variable_id, std::less<>> index_;
};

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/markov_network.ipp"
#endif
