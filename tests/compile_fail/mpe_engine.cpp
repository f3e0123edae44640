// An engine without mpe() is not an MpeEngine: most_probable refuses it.
#include <pgm/inference/inference_engine.hpp>

class marginal_engine {
 public:
  [[nodiscard]] std::string_view name() const { return "marginal"; }
  [[nodiscard]] const pgm::bayesian_network& network() const;
  [[nodiscard]] const pgm::evidence_set& evidence() const;
  void set_evidence(pgm::evidence_set observed);
  [[nodiscard]] pgm::posterior joint(std::span<const pgm::variable_id> query);
  [[nodiscard]] double log_probability_of_evidence();
#ifdef PGM_CONTROL
  [[nodiscard]] pgm::mpe_result mpe(std::span<const pgm::variable_id> variables);
#endif
};

pgm::mpe_result most_probable_of(marginal_engine& engine) { return pgm::most_probable(engine); }
