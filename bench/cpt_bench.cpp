// The operations on one conditional probability table, swept over the child's cardinality C and
// the number of parents P (each parent of C states too: C^(P+1) cells; C = 5, P = 3 is the
// paper's 625-parameter table): count a family from 10^5 rows, estimate it (MLE), condition it
// on a parent's state, marginalise a parent out, combine it with a factor over its child, and
// transfer a prior of the same shape into it (Direct-Replacement). Beside each, the simple
// approach one would write by hand; each checks its result against the other's after the loop.
// Throughput in cells/s (rows/s for counting).

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "pgm/data/sufficient_statistics.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/transfer/replacement.hpp"

namespace cpt_bench {
namespace {

constexpr std::size_t rows = 100'000;

pgm::variable variable_of(const std::string& name, std::size_t states) {
  std::vector<std::string> labels;
  for (std::size_t s = 0; s < states; ++s) labels.push_back(std::to_string(s));
  return pgm::variable(name, labels);
}

std::vector<std::string> parent_names(std::size_t parents) {
  std::vector<std::string> names;
  for (std::size_t p = 0; p < parents; ++p) names.push_back("p" + std::to_string(p));
  return names;
}

std::size_t power(std::size_t base, std::size_t exponent) {
  std::size_t result = 1;
  for (std::size_t k = 0; k < exponent; ++k) result *= base;
  return result;
}

/// y and P parents p0, p1, …, each of C states, drawn uniformly.
template <std::size_t C, std::size_t P>
const pgm::dataset& family_data() {
  static const pgm::dataset data = [] {
    pgm::dataset d;
    std::mt19937_64 random(C * 100 + P);
    for (const auto& name : [] {
           auto names = parent_names(P);
           names.insert(names.begin(), "y");
           return names;
         }()) {
      std::vector<unsigned> codes(rows);
      for (auto& c : codes) c = static_cast<unsigned>(random() % C);
      d.add(pgm::discrete_column(variable_of(name, C), codes));
    }
    return d;
  }();
  return data;
}

template <std::size_t C, std::size_t P>
const pgm::cpt<double>& fitted_table() {
  static const pgm::cpt<double> table = pgm::estimate_mle(pgm::count_family(family_data<C, P>(), "y", parent_names(P)));
  return table;
}

/// The fitted table as a factor over (p0, …, y): ids 0 … P−1 for the parents, P for y.
template <std::size_t C, std::size_t P>
pgm::factor table_factor() {
  std::vector<pgm::variable_id> parents;
  for (std::size_t p = 0; p < P; ++p) parents.push_back(pgm::index_at<pgm::variable_id>(p));
  return pgm::factor::from_cpt(fitted_table<C, P>(), pgm::index_at<pgm::variable_id>(P), parents);
}

void set_cells(benchmark::State& state, std::size_t cells) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cells));
  state.counters["cells"] = static_cast<double>(cells);
}

void expect_near(benchmark::State& state, double a, double b) {
  if (std::abs(a - b) > 1e-9 * std::max(1.0, std::abs(b))) state.SkipWithError("the two approaches disagree");
}

// ---------------------------------------------------------------------------------------------
// Count: the family's counts from the rows.

template <std::size_t C, std::size_t P>
void count(benchmark::State& state) {
  const auto& data = family_data<C, P>();
  const auto names = parent_names(P);
  std::uint64_t total = 0;
  std::uint64_t first = 0;
  for (auto _ : state) {
    const auto counts = pgm::count_family(data, "y", names);
    total = counts.total();
    first = counts(pgm::state_index(0), pgm::config_index(0));
    benchmark::DoNotOptimize(counts);
  }
  std::uint64_t by_hand = 0;
  const auto& y = data.discrete("y");
  for (std::size_t r = 0; r < rows; ++r) {
    bool first_configuration = y.code(r) == 0;
    for (const auto& name : names) first_configuration = first_configuration && data.discrete(name).code(r) == 0;
    by_hand += first_configuration ? 1 : 0;
  }
  if (total != rows || first != by_hand) state.SkipWithError("the counts are wrong");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
}

// By hand: each row's configuration of codes, its column in a std::map.
template <std::size_t C, std::size_t P>
void count_by_hand(benchmark::State& state) {
  const auto& data = family_data<C, P>();
  std::vector<const pgm::discrete_column*> parents;
  for (const auto& name : parent_names(P)) parents.push_back(&data.discrete(name));
  const auto& child = data.discrete("y");
  std::uint64_t total = 0;
  for (auto _ : state) {
    std::map<std::vector<unsigned>, std::array<std::uint64_t, C>> counts;
    std::vector<unsigned> configuration(P);
    for (std::size_t r = 0; r < rows; ++r) {
      for (std::size_t p = 0; p < P; ++p) configuration[p] = parents[p]->code(r);
      ++counts[configuration][child.code(r)];
    }
    total = 0;
    for (const auto& [u, column] : counts) {
      for (auto n : column) total += n;
    }
    benchmark::DoNotOptimize(counts);
  }
  if (total != rows) state.SkipWithError("the counts are wrong");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
}

// ---------------------------------------------------------------------------------------------
// Estimate: maximum likelihood from the counts.

template <std::size_t C, std::size_t P>
void estimate(benchmark::State& state) {
  const auto counts = pgm::count_family(family_data<C, P>(), "y", parent_names(P));
  double first = 0.0;
  for (auto _ : state) {
    const auto table = pgm::estimate_mle(counts);
    first = table.values()[0];
    benchmark::DoNotOptimize(table);
  }
  const auto u0 = pgm::config_index(0);
  expect_near(state, first,
              static_cast<double>(counts(pgm::state_index(0), u0)) / static_cast<double>(counts.total(u0)));
  set_cells(state, power(C, P + 1));
}

// By hand: each column divided by its total.
template <std::size_t C, std::size_t P>
void estimate_by_hand(benchmark::State& state) {
  const auto counts = pgm::count_family(family_data<C, P>(), "y", parent_names(P));
  const auto cells = counts.counts();
  std::vector<double> values(cells.size());
  for (auto _ : state) {
    for (std::size_t start = 0; start < cells.size(); start += C) {
      double total = 0.0;
      for (std::size_t x = 0; x < C; ++x) total += static_cast<double>(cells[start + x]);
      for (std::size_t x = 0; x < C; ++x) {
        values[start + x] = total > 0 ? static_cast<double>(cells[start + x]) / total : 1.0 / C;
      }
    }
    benchmark::DoNotOptimize(values.data());
  }
  expect_near(state, values[0], fitted_table<C, P>().values()[0]);
  set_cells(state, power(C, P + 1));
}

// ---------------------------------------------------------------------------------------------
// Condition: the slice where the first parent is in its last state.

template <std::size_t C, std::size_t P>
void condition(benchmark::State& state) {
  const auto f = table_factor<C, P>();
  double sum = 0.0;
  for (auto _ : state) {
    const auto slice = f.reduce(pgm::variable_id(0), C - 1);
    sum = slice.sum();
    benchmark::DoNotOptimize(slice);
  }
  // Every column of the slice sums to one.
  expect_near(state, sum, static_cast<double>(power(C, P - 1)));
  set_cells(state, power(C, P + 1));
}

// By hand: every cell decoded into its states, kept where the first parent's is the last.
template <std::size_t C, std::size_t P>
void condition_by_hand(benchmark::State& state) {
  const auto values = fitted_table<C, P>().values();
  const std::size_t cells = power(C, P + 1);
  const std::size_t first_stride = power(C, P);
  std::vector<double> slice;
  for (auto _ : state) {
    slice.clear();
    for (std::size_t i = 0; i < cells; ++i) {
      if (i / first_stride % C == C - 1) slice.push_back(values[i]);
    }
    benchmark::DoNotOptimize(slice.data());
  }
  double sum = 0.0;
  for (auto v : slice) sum += v;
  expect_near(state, sum, static_cast<double>(power(C, P - 1)));
  set_cells(state, cells);
}

// ---------------------------------------------------------------------------------------------
// Marginalise: the first parent summed out.

template <std::size_t C, std::size_t P>
void marginalise(benchmark::State& state) {
  const auto f = table_factor<C, P>();
  double sum = 0.0;
  for (auto _ : state) {
    const auto rest = f.sum_out(pgm::variable_id(0));
    sum = rest.sum();
    benchmark::DoNotOptimize(rest);
  }
  expect_near(state, sum, static_cast<double>(power(C, P)));
  set_cells(state, power(C, P + 1));
}

// By hand: every cell decoded, its value added to the cell of the states without the first.
template <std::size_t C, std::size_t P>
void marginalise_by_hand(benchmark::State& state) {
  const auto values = fitted_table<C, P>().values();
  const std::size_t cells = power(C, P + 1);
  const std::size_t first_stride = power(C, P);
  std::vector<double> rest(first_stride);
  for (auto _ : state) {
    std::fill(rest.begin(), rest.end(), 0.0);
    for (std::size_t i = 0; i < cells; ++i) rest[i % first_stride] += values[i];
    benchmark::DoNotOptimize(rest.data());
  }
  double sum = 0.0;
  for (auto v : rest) sum += v;
  expect_near(state, sum, static_cast<double>(power(C, P)));
  set_cells(state, cells);
}

// ---------------------------------------------------------------------------------------------
// Combine: the product with a factor over the child (evidence weights on y).

template <std::size_t C>
std::vector<double> child_weights() {
  std::vector<double> w(C);
  for (std::size_t x = 0; x < C; ++x) w[x] = 1.0 / static_cast<double>(x + 1);
  return w;
}

template <std::size_t C, std::size_t P>
void combine(benchmark::State& state) {
  const auto f = table_factor<C, P>();
  const pgm::factor weights({pgm::index_at<pgm::variable_id>(P)}, {C}, child_weights<C>());
  double sum = 0.0;
  for (auto _ : state) {
    const auto product = f * weights;
    sum = product.sum();
    benchmark::DoNotOptimize(product);
  }
  double expected = 0.0;
  const auto values = fitted_table<C, P>().values();
  for (std::size_t i = 0; i < values.size(); ++i) expected += values[i] * child_weights<C>()[i % C];
  expect_near(state, sum, expected);
  set_cells(state, power(C, P + 1));
}

// By hand: every cell times the weight of its child's state.
template <std::size_t C, std::size_t P>
void combine_by_hand(benchmark::State& state) {
  const auto values = fitted_table<C, P>().values();
  const auto w = child_weights<C>();
  std::vector<double> product(values.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < values.size(); ++i) product[i] = values[i] * w[i % C];
    benchmark::DoNotOptimize(product.data());
  }
  double sum = 0.0;
  for (auto v : product) sum += v;
  double expected = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) expected += values[i] * w[i % C];
  expect_near(state, sum, expected);
  set_cells(state, values.size());
}

// ---------------------------------------------------------------------------------------------
// Transfer: a prior table of the same shape (another task's y given its q0, q1, …) as the prior
// of y given p0, p1, …, by Direct-Replacement (eq. 7's prior: the prior's column for each
// configuration mapped across).

template <std::size_t C, std::size_t P>
struct transfer_shape {
  std::vector<pgm::variable> target_parents;
  pgm::cpt<double> prior;
  pgm::transfer_problem problem;
  transfer_shape() : target_parents(parents_named("p")), prior(prior_table()), problem(make_problem()) {}

  static std::vector<pgm::variable> parents_named(const std::string& prefix) {
    std::vector<pgm::variable> parents;
    for (std::size_t p = 0; p < P; ++p) parents.push_back(variable_of(prefix + std::to_string(p), C));
    return parents;
  }
  static pgm::cpt<double> prior_table() {
    const auto& fitted = fitted_table<C, P>();
    return pgm::cpt<double>(variable_of("z", C), parents_named("q"),
                            std::vector<double>(fitted.values().begin(), fitted.values().end()));
  }
  pgm::transfer_problem make_problem() const {
    std::string map = "y=z";
    for (std::size_t p = 0; p < P; ++p) map += ",p" + std::to_string(p) + "==q" + std::to_string(p);
    return pgm::transfer_problem(prior, variable_of("y", C), target_parents, pgm::parse_correspondence(map));
  }
};

template <std::size_t C, std::size_t P>
void transfer(benchmark::State& state) {
  const transfer_shape<C, P> shape;
  double first = 0.0;
  for (auto _ : state) {
    const auto transferred = pgm::direct_replacement{}(shape.problem);
    first = transferred.table().values()[0];
    benchmark::DoNotOptimize(transferred);
  }
  expect_near(state, first, shape.prior.values()[0]);
  set_cells(state, power(C, P + 1));
}

// By hand: for each configuration of the target's parents, the prior's column found by the
// parents' state labels.
template <std::size_t C, std::size_t P>
void transfer_by_hand(benchmark::State& state) {
  const transfer_shape<C, P> shape;
  const auto& target = shape.target_parents;
  const pgm::cpt<double> layout(variable_of("y", C), target);
  std::vector<double> values;
  for (auto _ : state) {
    values.clear();
    for (std::size_t u = 0; u < layout.configurations(); ++u) {
      const auto codes = layout.parent_codes(pgm::index_at<pgm::config_index>(u));
      std::vector<std::string> labels;
      for (std::size_t p = 0; p < P; ++p) labels.push_back(target[p].states()[codes[p]]);
      for (std::size_t x = 0; x < C; ++x) values.push_back(shape.prior.probability(std::to_string(x), labels));
    }
    benchmark::DoNotOptimize(values.data());
  }
  expect_near(state, values[0], shape.prior.values()[0]);
  set_cells(state, power(C, P + 1));
}

// The sweep: binary and ternary families, the paper's 625-parameter table (C = 5, P = 3), and a
// wide one of 5^5 = 3125 cells.
#define PGM_CPT_SWEEP(operation)                 \
  BENCHMARK_TEMPLATE(operation, 2, 2);           \
  BENCHMARK_TEMPLATE(operation##_by_hand, 2, 2); \
  BENCHMARK_TEMPLATE(operation, 3, 3);           \
  BENCHMARK_TEMPLATE(operation##_by_hand, 3, 3); \
  BENCHMARK_TEMPLATE(operation, 5, 3);           \
  BENCHMARK_TEMPLATE(operation##_by_hand, 5, 3); \
  BENCHMARK_TEMPLATE(operation, 5, 4);           \
  BENCHMARK_TEMPLATE(operation##_by_hand, 5, 4)

PGM_CPT_SWEEP(count);
PGM_CPT_SWEEP(estimate);
PGM_CPT_SWEEP(condition);
PGM_CPT_SWEEP(marginalise);
PGM_CPT_SWEEP(combine);
PGM_CPT_SWEEP(transfer);

}  // namespace
}  // namespace cpt_bench
