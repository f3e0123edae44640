#pragma once
// Several processes played by threads, for tests without MPI: each thread is one member of a
// pgm::process_group whose collective steps meet at a barrier.

#include <algorithm>
#include <barrier>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "pgm/core/process_group.hpp"

namespace pgm::testing {

// What the members of a thread group share.
struct meeting {
  explicit meeting(std::size_t size) : barrier(static_cast<std::ptrdiff_t>(size)), values(size), texts(size) {}
  std::barrier<> barrier;
  std::vector<std::uint64_t> values;
  std::vector<std::string> texts;
  std::vector<std::vector<std::uint64_t>> sums{values.size()};
  std::vector<std::string> steps;  // rank 0's record of the collective steps taken
};

class thread_member final : public process_group {
 public:
  thread_member(meeting& m, std::size_t rank) : m_(m), rank_(rank) {}
  [[nodiscard]] std::size_t rank() const noexcept override { return rank_; }
  [[nodiscard]] std::size_t size() const noexcept override { return m_.values.size(); }
  [[nodiscard]] std::uint64_t smallest(std::uint64_t value) override {
    record("smallest");
    m_.values[rank_] = value;
    m_.barrier.arrive_and_wait();
    const auto lowest = *std::min_element(m_.values.begin(), m_.values.end());
    m_.barrier.arrive_and_wait();
    return lowest;
  }
  [[nodiscard]] std::string broadcast(std::string bytes, std::size_t root) override {
    record("broadcast");
    if (rank_ == root) m_.texts[root] = bytes;
    m_.barrier.arrive_and_wait();
    auto result = m_.texts[root];
    m_.barrier.arrive_and_wait();
    return result;
  }
  [[nodiscard]] std::vector<std::string> gather(std::string_view bytes) override {
    record("gather");
    m_.texts[rank_] = std::string(bytes);
    m_.barrier.arrive_and_wait();
    std::vector<std::string> result;
    if (rank_ == 0) result = m_.texts;
    m_.barrier.arrive_and_wait();
    return result;
  }
  void sum(std::span<std::uint64_t> values) override {
    record("sum");
    m_.sums[rank_].assign(values.begin(), values.end());
    m_.barrier.arrive_and_wait();
    for (std::size_t i = 0; i < values.size(); ++i) {
      values[i] = 0;
      for (const auto& theirs : m_.sums) values[i] += theirs[i];
    }
    m_.barrier.arrive_and_wait();
  }

 private:
  void record(const char* step) {
    if (rank_ == 0) m_.steps.emplace_back(step);
  }
  meeting& m_;
  std::size_t rank_;
};

// What one member ended with: its exception's message and type, if any.
struct outcome {
  std::string message;
  bool remote = false;
  bool failed_flag = false;
};

// Runs `member(group)` on `size` threads, one member each; returns each one's outcome.
inline std::vector<outcome> run_group(std::size_t size, const std::function<void(process_group&)>& member,
                                      std::vector<std::string>* steps = nullptr) {
  meeting m(size);
  std::vector<outcome> outcomes(size);
  {
    std::vector<std::jthread> threads;
    for (std::size_t r = 0; r < size; ++r) {
      threads.emplace_back([&, r] {
        thread_member group(m, r);
        try {
          member(group);
        } catch (const remote_error& e) {
          outcomes[r] = {e.what(), true, group.failed()};
        } catch (const std::exception& e) {
          outcomes[r] = {e.what(), false, group.failed()};
        }
      });
    }
  }
  if (steps) *steps = m.steps;
  return outcomes;
}

}  // namespace pgm::testing
