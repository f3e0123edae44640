// An engine that cannot give ln P(evidence) is not an InferenceEngine: register_engine refuses it.
#include <pgm/inference/engine_registry.hpp>

class partial_engine {
 public:
  partial_engine(std::shared_ptr<const pgm::bayesian_network> network, const pgm::inference_options&)
      : network_(std::move(network)) {}
  [[nodiscard]] std::string_view name() const { return "partial"; }
  [[nodiscard]] const pgm::bayesian_network& network() const { return *network_; }
  [[nodiscard]] const pgm::evidence_set& evidence() const { return evidence_; }
  void set_evidence(pgm::evidence_set observed) { evidence_ = std::move(observed); }
  [[nodiscard]] pgm::posterior joint(std::span<const pgm::variable_id> query);
#ifdef PGM_CONTROL
  [[nodiscard]] double log_probability_of_evidence();
#endif

 private:
  std::shared_ptr<const pgm::bayesian_network> network_;
  pgm::evidence_set evidence_;
};

static const pgm::register_engine<partial_engine> registered("partial");
