// The C++ side of bench/python/bench_fit.py: the same fit as pgm.fit, in process. Reads the
// columns the script wrote (codes 0..k-1 as 64-bit integers, one column after another) and times, `repeats`
// times, (a) the fit alone on a data set already built: structure_from_data + fit (MLE, one
// thread), and (b) the whole of what pgm.fit does from the same int64 codes in memory: the data
// set (states 0..k-1 from the largest code) and then (a), and (c) the fit counted straight from
// the same int64 codes (pgm/learn/count_values.hpp, as pgm.fit counts a frame of integer codes).
// Prints the three medians in seconds.
// Usage: bench_python_fit FILE ROWS REPEATS CHILD PARENT...

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "pgm/learn/count_values.hpp"
#include "pgm/learn/fit.hpp"

int main(int argc, char** argv) {
  if (argc < 6) {
    std::cerr << "usage: bench_python_fit FILE ROWS REPEATS CHILD PARENT...\n";
    return 2;
  }
  const std::size_t rows = std::stoul(argv[2]);
  const int repeats = std::stoi(argv[3]);
  const std::vector<std::string> names(argv + 4, argv + argc);
  std::ifstream in(argv[1], std::ios::binary);
  std::vector<std::vector<std::uint64_t>> columns(names.size(), std::vector<std::uint64_t>(rows));
  for (auto& values : columns) {
    if (!in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(rows * sizeof(std::uint64_t)))) {
      std::cerr << argv[1] << ": too short for " << rows << " rows of " << names.size() << " columns\n";
      return 1;
    }
  }
  auto make_dataset = [&] {
    pgm::dataset data;
    for (std::size_t c = 0; c < names.size(); ++c) {
      const auto cardinality = static_cast<std::size_t>(*std::max_element(columns[c].begin(), columns[c].end()) + 1);
      std::vector<std::string> states;
      for (std::size_t s = 0; s < cardinality; ++s) states.push_back(std::to_string(s));
      data.add(pgm::discrete_column(pgm::variable(names[c], std::move(states)), columns[c]));
    }
    return data;
  };
  std::vector<pgm::named_edge> edges;
  for (std::size_t p = 1; p < names.size(); ++p) edges.push_back({names[p], names[0]});
  pgm::fit_options options;
  options.counting.threads = 1;
  auto median = [&](auto&& work) {
    std::vector<double> seconds;
    for (int i = 0; i < repeats; ++i) {
      const auto start = std::chrono::steady_clock::now();
      const auto network = work();
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      if (network.variables().size() != names.size()) std::exit(1);
    }
    std::sort(seconds.begin(), seconds.end());
    return seconds[seconds.size() / 2];
  };
  const auto data = make_dataset();
  const double fit_only = median([&] { return pgm::fit(pgm::structure_from_data(data, edges), data, options); });
  const double from_codes = median([&] {
    const auto fresh = make_dataset();
    return pgm::fit(pgm::structure_from_data(fresh, edges), fresh, options);
  });
  const double counted_from_codes = median([&] {
    std::vector<pgm::named_value_column> values;
    for (std::size_t c = 0; c < names.size(); ++c) {
      values.push_back({names[c], pgm::value_span<std::uint64_t>{columns[c].data(), rows, 1}});
    }
    std::vector<pgm::value_family> families{{0, {}}};
    for (std::size_t p = 1; p < names.size(); ++p) {
      families[0].parents.push_back(p);
      families.push_back({p, {}});
    }
    auto counts = pgm::count_value_families(values, families, options.counting);
    if (!counts) std::exit(1);
    const pgm::network_structure structure(std::move(counts->variables), edges);
    return pgm::fit(structure, counts->tables, options);
  });
  std::cout << fit_only << ' ' << from_codes << ' ' << counted_from_codes << '\n';
}
