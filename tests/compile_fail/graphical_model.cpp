// A model whose factors do not say their variables is not a GraphicalModel: variable_elimination
// refuses it.
#include <pgm/inference/variable_elimination.hpp>

struct scopeless_model {
  [[nodiscard]] const std::vector<pgm::variable>& variables() const;
  [[nodiscard]] std::size_t size() const;
  [[nodiscard]] pgm::variable_id id(std::string_view name) const;
  [[nodiscard]] std::size_t factor_count() const;
#ifdef PGM_CONTROL
  [[nodiscard]] std::vector<pgm::variable_id> factor_scope(std::size_t f) const;
#endif
  [[nodiscard]] pgm::factor_table factor(std::size_t f) const;
};

template class pgm::variable_elimination<scopeless_model>;
