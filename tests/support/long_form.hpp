#pragma once
// Episodes of a dynamic network in long form (episode,t,<variables>) for tests: sampled from the
// network unrolled over the longest episode, each episode cut at a random length, the rows in
// episode and step order or shuffled.

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "pgm/core/dynamic_network.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/inference/sampling.hpp"

namespace pgm::testing {

struct long_form {
  dataset data;
  /// codes[k][t][i]: template variable i at step t of episode k (`missing` where it has none).
  std::vector<std::vector<std::vector<std::uint32_t>>> codes;
  /// Each data row's (episode, t).
  std::vector<std::pair<std::size_t, std::size_t>> rows;
  static constexpr std::uint32_t missing = missing_code<std::uint32_t>;
};

inline long_form sample_long_form(const dynamic_network& model, std::size_t episodes, std::size_t max_length,
                                  std::uint64_t seed, bool shuffled = false) {
  const auto wide = sample(model.unroll(max_length), episodes, seed);
  std::mt19937_64 engine(seed + 1);
  long_form out{dataset("episodes.csv"), {}};
  auto& rows = out.rows;
  for (std::size_t k = 0; k < episodes; ++k) {
    const auto length = 1 + engine() % max_length;
    auto& episode = out.codes.emplace_back();
    for (std::size_t t = 0; t < length; ++t) {
      auto& step = episode.emplace_back();
      for (const auto& v : model.variables())
        step.push_back(wide.discrete(slice_name(v.name(), static_cast<long>(t))).code(k));
      rows.emplace_back(k, t);
    }
  }
  if (shuffled) std::shuffle(rows.begin(), rows.end(), engine);
  std::vector<std::string> names;
  for (std::size_t k = 0; k < episodes; ++k) names.push_back("e" + std::to_string(k));
  std::vector<std::uint32_t> episode_codes;
  std::vector<double> steps;
  for (const auto& [k, t] : rows) {
    episode_codes.push_back(static_cast<std::uint32_t>(k));
    steps.push_back(static_cast<double>(t));
  }
  out.data.add(discrete_column(variable("episode", names), episode_codes));
  out.data.add(continuous_column("t", steps));
  for (std::size_t i = 0; i < model.size(); ++i) {
    std::vector<std::uint32_t> codes;
    for (const auto& [k, t] : rows) codes.push_back(out.codes[k][t][i]);
    out.data.add(discrete_column(model.variables()[i], codes));
  }
  return out;
}

/// `data` with about one value in `one_in` of the template variables missing.
inline long_form with_gaps(long_form data, const dynamic_network& model, std::uint64_t seed, unsigned one_in) {
  std::mt19937_64 engine(seed);
  for (auto& episode : data.codes) {
    for (auto& step : episode) {
      for (auto& code : step) {
        if (engine() % one_in == 0) code = long_form::missing;
      }
    }
  }
  for (std::size_t i = 0; i < model.size(); ++i) {
    const auto& v = model.variables()[i];
    auto codes = make_code_vector(v.cardinality() + 1, data.rows.size());
    std::size_t missing = 0;
    std::visit(
        [&](auto& out) {
          using code = typename std::decay_t<decltype(out)>::value_type;
          for (std::size_t r = 0; r < data.rows.size(); ++r) {
            const auto value = data.codes[data.rows[r].first][data.rows[r].second][i];
            missing += value == long_form::missing;
            out[r] = value == long_form::missing ? missing_code<code> : static_cast<code>(value);
          }
        },
        codes);
    data.data.replace(discrete_column(v, std::move(codes), std::in_place, missing));
  }
  return data;
}

}  // namespace pgm::testing
