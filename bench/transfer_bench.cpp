// Transferring a prior table (the paper's 25 → 625 and 125 → 125 shapes) and a whole fit with a
// transferred prior at 10⁶ rows. The simple approach for comparison: a per-configuration lookup
// that finds each prior column through the state labels, as one would write it by hand.

#include <benchmark/benchmark.h>

#include <random>

#include "check.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/transfer/network_transfer.hpp"
#include "pgm/transfer/replacement.hpp"

namespace {

using namespace pgm;

const std::vector<double> stack_edges{-3.0, -1.4, -0.4, 0.4, 1.4, 3.0};
const variable on1("onTop1", {"0", "1"}), on2("onTop2", {"0", "1"});

cpt<double> random_table(const variable& child, std::vector<variable> parents) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> p(0.0, 1.0);
  std::size_t n = 1;
  for (const auto& v : parents) n *= v.cardinality();
  std::vector<double> values;
  for (std::size_t u = 0; u < n; ++u) {
    const double s = p(random);
    values.push_back(1 - s);
    values.push_back(s);
  }
  return cpt<double>(child, std::move(parents), std::move(values));
}

struct stacking {
  variable x1 = variable::intervals("xOff1", stack_edges), y1 = variable::intervals("yOff1", stack_edges);
  variable x2 = variable::intervals("xOff2", stack_edges), y2 = variable::intervals("yOff2", stack_edges);
  cpt<double> prior = random_table(on1, {x1, y1});
  transfer_problem problem{prior, on2, {x1, y1, x2, y2}, parse_correspondence("onTop2=onTop1,xOff2~xOff1,yOff2~yOff1")};
};

template <class Strategy>
void transfer_25_to_625(benchmark::State& state) {
  const stacking s;
  std::size_t cells = 0;
  for (auto _ : state) {
    const auto transferred = Strategy{}(s.problem);
    cells = transferred.table().size();
    benchmark::DoNotOptimize(transferred);
  }
  pgm::bench::check(state, cells == 2 * 625, "the transferred table is not of the target's 625 configurations");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * 625));
}
BENCHMARK(transfer_25_to_625<direct_replacement>);
BENCHMARK(transfer_25_to_625<cross_replacement>);
BENCHMARK(transfer_25_to_625<minimal_replacement>);

// By hand: for each of the 625 configurations, look the prior column up by state labels.
void transfer_25_to_625_by_labels(benchmark::State& state) {
  const stacking s;
  const auto& target = s.problem.target_parents();
  std::vector<double> values;
  for (auto _ : state) {
    values.clear();
    for (std::size_t u = 0; u < 625; ++u) {
      const auto codes = cpt<double>(on2, target).parent_codes(index_at<config_index>(u));
      const std::vector<std::string> labels{target[0].states()[codes[0]], target[1].states()[codes[1]]};
      values.push_back(s.prior.probability("0", labels));
      values.push_back(s.prior.probability("1", labels));
    }
    benchmark::DoNotOptimize(values);
  }
  // Direct-Replacement gives the same columns.
  pgm::bench::check(state, values[0] == direct_replacement{}(s.problem).table().values()[0],
                    "the lookup by labels differs from Direct-Replacement");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * 625));
}
BENCHMARK(transfer_25_to_625_by_labels);

void transfer_125_to_125_identity(benchmark::State& state) {
  const std::vector<double> drop{-6, -3.6, -1.2, 1.2, 3.6, 6};
  const std::vector<variable> parents{variable::intervals("xOff", drop), variable::intervals("yOff", drop),
                                      variable::intervals("scalingFactor", {0.4, 0.52, 0.64, 0.76, 0.88, 1.0})};
  const variable inside("inside", {"0", "1"});
  const auto prior = random_table(inside, parents);
  const transfer_problem problem(prior, inside, parents, parse_correspondence("inside=inside"));
  std::vector<double> values;
  for (auto _ : state) {
    const auto transferred = direct_replacement{}(problem);
    values.assign(transferred.table().values().begin(), transferred.table().values().end());
    benchmark::DoNotOptimize(transferred);
  }
  // The identity map copies the prior.
  pgm::bench::check(state, values == std::vector<double>(prior.values().begin(), prior.values().end()),
                    "the identity transfer is not the prior");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * 125));
}
BENCHMARK(transfer_125_to_125_identity);

// Fit of the 2-Stack network (5 tables) at 10⁶ rows with onTop2's prior transferred (w = 5).
void fit_with_transferred_prior(benchmark::State& state) {
  const stacking s;
  const auto rows = static_cast<std::size_t>(state.range(0));
  std::mt19937_64 random(7);
  dataset data;
  for (const auto* v : {&s.x1, &s.y1, &s.x2, &s.y2}) {
    std::vector<unsigned> codes(rows);
    for (auto& c : codes) c = static_cast<unsigned>(random() % 5);
    data.add(discrete_column(*v, codes));
  }
  std::vector<unsigned> outcome(rows);
  for (auto& c : outcome) c = static_cast<unsigned>(random() & 1U);
  data.add(discrete_column(on2, outcome));
  const network_structure structure(
      {s.x1, s.y1, s.x2, s.y2, on2},
      {{"xOff1", "onTop2"}, {"yOff1", "onTop2"}, {"xOff2", "onTop2"}, {"yOff2", "onTop2"}});
  const auto prior_net = bayesian_network::from_tables({cpt<double>(s.x1, {}, std::vector<double>(5, 0.2)),
                                                        cpt<double>(s.y1, {}, std::vector<double>(5, 0.2)), s.prior});
  std::size_t tables = 0;
  for (auto _ : state) {
    fit_options options;
    options.counting.threads = static_cast<unsigned>(state.range(1));
    const auto priors = transfer_priors(prior_net, structure, s.problem.map(), minimal_replacement{});
    use_transferred_priors(options, priors, {{"onTop2", 5.0}});
    const auto network = fit(structure, data, options);
    tables = network.tables().size();
    benchmark::DoNotOptimize(network);
  }
  pgm::bench::check(state, tables == 5, "the fit does not have its five tables");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
  state.counters["ns/row"] = benchmark::Counter(static_cast<double>(state.iterations() * rows),
                                                benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(fit_with_transferred_prior)
    ->Args({1'000'000, 1})
    ->Args({1'000'000, 2})
    ->ArgNames({"rows", "threads"})
    ->UseRealTime();

}  // namespace
