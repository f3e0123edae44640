// An inference engine of one's own: brute-force enumeration of the joint, exact by definition
// and fine for a handful of variables — a reference to check the built-in engines against.
// It models pgm::InferenceEngine with nothing to derive from, and registers itself by name
// from this file, so make_engine("enumerate", ...) and `pgm query --engine enumerate` (with
// this file among PGM_PLUGIN_SOURCES) find it.

#include "enumeration_engine.hpp"

#include <cmath>

namespace {

const pgm::register_engine<enumeration_engine> registered("enumerate");

}  // namespace

pgm::posterior enumeration_engine::joint(std::span<const pgm::variable_id> query) {
  const auto& net = *network_;
  const auto n = net.size();
  std::vector<std::size_t> state(n, 0);
  std::vector<std::size_t> cards;
  std::size_t cells = 1;
  pgm::posterior result;
  for (auto id : query) {
    result.variables.push_back(net.variables()[id.value()]);
    cards.push_back(result.variables.back().cardinality());
    cells *= cards.back();
  }
  std::vector<double> joint(cells, 0.0);
  for (;;) {
    bool consistent = true;
    for (const auto& o : evidence_.hard) consistent = consistent && state[o.variable.value()] == o.state.value();
    if (consistent) {
      double p = 1.0;
      for (std::size_t i = 0; i < n; ++i) {
        const auto& table = net.tables()[i];
        std::size_t u = 0;
        for (auto parent : net.graph().parents(pgm::index_at<pgm::variable_id>(i))) {
          u = u * net.variables()[parent.value()].cardinality() + state[parent.value()];
        }
        p *= table.values()[u * table.child_cardinality() + state[i]];
      }
      for (const auto& l : evidence_.soft) p *= l.weights[state[l.variable.value()]];
      std::size_t cell = 0;
      for (std::size_t k = 0; k < query.size(); ++k) cell = cell * cards[k] + state[query[k].value()];
      joint[cell] += p;
    }
    std::size_t k = n;
    while (k-- > 0 && ++state[k] == net.variables()[k].cardinality()) state[k] = 0;
    if (k == static_cast<std::size_t>(-1)) break;
  }
  result.table = pgm::factor(std::vector<pgm::variable_id>(query.begin(), query.end()), cards, std::move(joint));
  result.evidence_probability = result.table.normalize();
  if (!(result.evidence_probability > 0.0)) throw pgm::impossible_evidence("the evidence has probability 0");
  result.log_evidence_probability = std::log(result.evidence_probability);
  result.engine = "enumerate";
  return result;
}

double enumeration_engine::log_probability_of_evidence() { return joint({}).log_evidence_probability; }
