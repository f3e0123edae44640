// A brute-force inference engine (enumeration_engine.cpp): what pgm::InferenceEngine asks for.
#pragma once

#include <memory>
#include <pgm/inference/engine_registry.hpp>
#include <span>
#include <string_view>

class enumeration_engine {
 public:
  // The registry builds engines from a shared network and the options of `pgm query`.
  enumeration_engine(std::shared_ptr<const pgm::bayesian_network> network, const pgm::inference_options&)
      : network_(std::move(network)) {}

  [[nodiscard]] std::string_view name() const { return "enumerate"; }
  [[nodiscard]] const pgm::bayesian_network& network() const { return *network_; }
  [[nodiscard]] const pgm::evidence_set& evidence() const { return evidence_; }
  void set_evidence(pgm::evidence_set observed) { evidence_ = std::move(observed); }

  /// P(query | evidence), the joint over `query` in its order.
  [[nodiscard]] pgm::posterior joint(std::span<const pgm::variable_id> query);
  [[nodiscard]] double log_probability_of_evidence();

 private:
  std::shared_ptr<const pgm::bayesian_network> network_;
  pgm::evidence_set evidence_;
};

static_assert(pgm::InferenceEngine<enumeration_engine>);
