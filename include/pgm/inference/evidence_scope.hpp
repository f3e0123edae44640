#pragma once
/// \file
/// `evidence_scope`: an engine's evidence set for as long as the scope lives, and what it held
/// before put back when the scope ends, by a return or by an exception, so that a function that
/// asks its own questions on a caller's engine leaves the engine as it found it.

#include <utility>

#include "pgm/inference/query.hpp"

namespace pgm {

template <class Engine>
class evidence_scope {
 public:
  /// Keeps the engine's evidence, to put back at the end; replace() sets other evidence.
  explicit evidence_scope(Engine& engine) : engine_(engine), before_(engine.evidence()) {}

  evidence_scope(Engine& engine, evidence_set observed) : evidence_scope(engine) {
    engine_.set_evidence(std::move(observed));
  }

  evidence_scope(const evidence_scope&) = delete;
  evidence_scope& operator=(const evidence_scope&) = delete;

  /// Puts the evidence the engine held before back; it was accepted once, so it is again (a
  /// failure to allocate while restoring leaves the engine with the scope's evidence).
  ~evidence_scope() {
    try {
      engine_.set_evidence(std::move(before_));
    } catch (...) {
    }
  }

  /// Other evidence for the rest of the scope.
  void replace(evidence_set observed) { engine_.set_evidence(std::move(observed)); }

 private:
  Engine& engine_;
  evidence_set before_;
};

}  // namespace pgm
