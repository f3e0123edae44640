#include "pgm/detail/parallel_for.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <mutex>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "pgm/detail/splitmix.hpp"

namespace pgm::detail::parallel_for_tests {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// Slot results: item i's value depends on i only.
std::vector<std::uint64_t> mixed_values(std::size_t n, parallel_options options) {
  std::vector<std::uint64_t> slots(n);
  parallel_for(n, options, [&](item_range items) {
    for (auto i = items.begin; i < items.end; ++i) slots[i] = splitmix64_mix(i);
  });
  return slots;
}

TEST(parallel_for_test, slots_are_the_same_for_any_thread_count_and_chunk) {
  const std::size_t n = 10'007;
  std::vector<std::uint64_t> expected(n);
  for (std::size_t i = 0; i < n; ++i) expected[i] = splitmix64_mix(i);
  for (unsigned threads : {1U, 2U, 3U, 8U}) {
    for (std::size_t chunk : {1U, 7U, 4096U, 20'000U}) {
      EXPECT_EQ(mixed_values(n, {.threads = threads, .chunk = chunk}), expected)
          << threads << " threads, chunk " << chunk;
    }
  }
}

TEST(parallel_for_test, per_thread_sums_add_up_to_the_same_total) {
  const std::size_t n = 100'000;
  std::uint64_t reference = 0;
  for (std::size_t i = 0; i < n; ++i) reference += i * i;
  for (unsigned threads : {1U, 2U, 3U, 8U}) {
    const auto sums = parallel_for(
        n, {.threads = threads, .chunk = 1000}, [] { return std::uint64_t{0}; },
        [](std::uint64_t& sum, item_range items) {
          for (auto i = items.begin; i < items.end; ++i) sum += i * i;
        });
    EXPECT_LE(sums.size(), threads);
    EXPECT_GE(sums.size(), 1U);
    EXPECT_EQ(std::accumulate(sums.begin(), sums.end(), std::uint64_t{0}), reference) << threads << " threads";
  }
}

TEST(parallel_for_test, zero_items_run_nothing_and_report_zero) {
  std::vector<std::size_t> reports;
  bool ran = false;
  bool built = false;
  parallel_options options{.threads = 4};
  options.progress = [&](std::size_t done) { reports.push_back(done); };
  const auto states = parallel_for(
      0, options,
      [&] {
        built = true;
        return 0;
      },
      [&](int&, item_range) { ran = true; });
  EXPECT_TRUE(states.empty());
  EXPECT_FALSE(ran);
  EXPECT_FALSE(built);
  EXPECT_EQ(reports, std::vector<std::size_t>{0});
  EXPECT_EQ(worker_count(0, options), 0U);
}

TEST(parallel_for_test, fewer_items_than_threads_run_each_item_once) {
  std::vector<std::atomic<int>> runs(3);
  std::mutex mutex;
  std::set<std::thread::id> threads;
  const parallel_options options{.threads = 8};
  EXPECT_EQ(worker_count(3, options), 3U);
  parallel_for(3, options, [&](item_range items) {
    EXPECT_EQ(items.size(), 1U);
    for (auto i = items.begin; i < items.end; ++i) ++runs[i];
    const std::lock_guard lock(mutex);
    threads.insert(std::this_thread::get_id());
  });
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
  EXPECT_LE(threads.size(), 3U);
}

TEST(parallel_for_test, a_failure_is_rethrown_and_stops_handing_out_work) {
  const std::size_t n = 100'000;
  for (unsigned threads : {1U, 2U, 3U, 8U}) {
    std::atomic<std::size_t> ran{0};
    std::atomic<bool> failing{false};
    auto body = [&](item_range items) {
      for (auto i = items.begin; i < items.end; ++i) {
        if (i == 10) {
          failing = true;
          throw std::runtime_error("item 10 failed");
        }
        // Later items wait until item 10 is failing, so they cannot all finish before it, and
        // then take a while, so that the others cannot run them all while it is being recorded.
        if (i > 10) {
          while (!failing) std::this_thread::yield();
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        ++ran;
      }
    };
    EXPECT_THAT([&] { parallel_for(n, {.threads = threads}, body); },
                ThrowsMessage<std::runtime_error>(HasSubstr("item 10 failed")))
        << threads << " threads";
    if (threads == 1) {
      EXPECT_EQ(ran.load(), 10U);
    } else {
      EXPECT_LT(ran.load(), n / 2) << threads << " threads";
    }
  }
}

TEST(parallel_for_test, the_lowest_failing_item_wins) {
  for (unsigned threads : {1U, 2U, 3U, 8U}) {
    for (std::size_t chunk : {1U, 4U}) {
      for (int round = 0; round < 10; ++round) {
        auto body = [&](item_range items) {
          for (auto i = items.begin; i < items.end; ++i) {
            // Item 50 fails at once, item 5 only after a while: by time, 50 would come first.
            if (i == 5) {
              std::this_thread::sleep_for(std::chrono::milliseconds(1));
              throw std::runtime_error("the fifth item failed");
            }
            if (i == 50) throw std::runtime_error("the fiftieth item failed");
          }
        };
        EXPECT_THAT([&] { parallel_for(1000, {.threads = threads, .chunk = chunk}, body); },
                    ThrowsMessage<std::runtime_error>(HasSubstr("the fifth item")))
            << threads << " threads, chunk " << chunk;
      }
    }
  }
}

TEST(parallel_for_test, a_failure_while_building_a_state_is_rethrown) {
  auto run = [] {
    static_cast<void>(parallel_for(
        100, {.threads = 3}, []() -> int { throw std::invalid_argument("no physics world"); },
        [](int&, item_range) {}));
  };
  EXPECT_THAT(run, ThrowsMessage<std::invalid_argument>(HasSubstr("no physics world")));
}

TEST(parallel_for_test, progress_is_serial_increasing_and_ends_at_n) {
  const std::size_t n = 1000;
  for (unsigned threads : {1U, 2U, 3U, 8U}) {
    std::vector<std::size_t> reports;
    std::atomic<int> inside{0};
    bool overlapped = false;
    parallel_options options{.threads = threads, .chunk = 7};
    options.progress = [&](std::size_t done) {
      overlapped = overlapped || inside.fetch_add(1) != 0;
      reports.push_back(done);
      std::this_thread::yield();
      inside.fetch_sub(1);
    };
    parallel_for(n, options, [](item_range) {});
    EXPECT_FALSE(overlapped) << threads << " threads";
    ASSERT_FALSE(reports.empty());
    EXPECT_EQ(reports.back(), n);
    EXPECT_EQ(reports.size(), (n + 6) / 7) << "one report per chunk";
    for (std::size_t k = 1; k < reports.size(); ++k) EXPECT_LT(reports[k - 1], reports[k]);
  }
}

TEST(parallel_for_test, a_failing_progress_callback_fails_the_job) {
  parallel_options options{.threads = 2};
  options.progress = [](std::size_t done) {
    if (done >= 3) throw std::runtime_error("cancelled");
  };
  EXPECT_THAT([&] { parallel_for(100, options, [](item_range) {}); },
              ThrowsMessage<std::runtime_error>(HasSubstr("cancelled")));
}

struct thread_state {
  std::thread::id owner = std::this_thread::get_id();
  std::size_t items = 0;
};

TEST(parallel_for_test, each_thread_builds_its_state_once_and_keeps_it) {
  const std::size_t n = 20'000;
  for (unsigned threads : {1U, 2U, 3U, 8U}) {
    std::atomic<unsigned> built{0};
    std::atomic<bool> foreign{false};
    const auto states = parallel_for(
        n, {.threads = threads, .chunk = 16},
        [&] {
          ++built;
          return thread_state{};
        },
        [&](thread_state& state, item_range items) {
          if (state.owner != std::this_thread::get_id()) foreign = true;
          state.items += items.size();
        });
    EXPECT_EQ(states.size(), built.load());
    EXPECT_LE(built.load(), threads);
    EXPECT_FALSE(foreign) << "a state was used by another thread";
    std::set<std::thread::id> owners;
    std::size_t items = 0;
    for (const auto& s : states) {
      owners.insert(s.owner);
      items += s.items;
    }
    EXPECT_EQ(owners.size(), states.size()) << "one state per thread";
    EXPECT_EQ(items, n);
  }
  // One thread: the calling thread does the work.
  const auto states = parallel_for(
      10, {.threads = 1}, [] { return thread_state{}; },
      [](thread_state& s, item_range items) { s.items += items.size(); });
  ASSERT_EQ(states.size(), 1U);
  EXPECT_EQ(states[0].owner, std::this_thread::get_id());
  EXPECT_EQ(states[0].items, 10U);
}

TEST(parallel_for_test, small_jobs_use_fewer_threads) {
  EXPECT_EQ(worker_count(100, {.threads = 8, .min_items_per_thread = 64}), 1U);
  EXPECT_EQ(worker_count(200, {.threads = 8, .min_items_per_thread = 64}), 3U);
  EXPECT_EQ(worker_count(100'000, {.threads = 8, .min_items_per_thread = 64}), 8U);
  EXPECT_EQ(worker_count(100, {.threads = 8, .chunk = 40}), 3U);  // one per chunk at most
  EXPECT_EQ(worker_count(100'000, {.threads = 0}), resolve_threads(0));
  EXPECT_GE(resolve_threads(0), 1U);
  EXPECT_EQ(resolve_threads(5), 5U);

  std::mutex mutex;
  std::set<std::thread::id> threads;
  parallel_for(100, {.threads = 8, .min_items_per_thread = 64}, [&](item_range) {
    const std::lock_guard lock(mutex);
    threads.insert(std::this_thread::get_id());
  });
  EXPECT_EQ(threads, std::set<std::thread::id>{std::this_thread::get_id()});
}

TEST(parallel_for_test, process_shares_tile_the_job) {
  for (std::size_t n : {0U, 1U, 7U, 100U, 1001U}) {
    for (std::size_t ranks : {1U, 2U, 3U, 8U}) {
      std::size_t expected_begin = 0;
      for (std::size_t rank = 0; rank < ranks; ++rank) {
        const auto block = process_share{rank, ranks}.of(n);
        EXPECT_EQ(block.begin, expected_begin);
        EXPECT_LE(block.size(), n / ranks + 1);
        EXPECT_GE(block.size(), n / ranks);
        expected_begin = block.end;
      }
      EXPECT_EQ(expected_begin, n);
    }
  }
  // No overflow for the largest jobs.
  const auto last = process_share{2, 3}.of(std::numeric_limits<std::size_t>::max());
  EXPECT_EQ(last.end, std::numeric_limits<std::size_t>::max());
}

TEST(parallel_for_test, shares_run_separately_give_the_whole_job) {
  const std::size_t n = 5003;
  const auto whole = mixed_values(n, {.threads = 2, .chunk = 64});
  std::vector<std::uint64_t> combined(n);
  for (std::size_t rank = 0; rank < 3; ++rank) {
    parallel_options options{.threads = 2, .chunk = 64, .share = {rank, 3}};
    std::size_t last_report = 0;
    options.progress = [&](std::size_t done) { last_report = done; };
    const auto owned = options.share.of(n);
    std::atomic<bool> outside{false};
    parallel_for(n, options, [&](item_range items) {
      if (items.begin < owned.begin || items.end > owned.end) outside = true;
      for (auto i = items.begin; i < items.end; ++i) combined[i] = splitmix64_mix(i);
    });
    EXPECT_FALSE(outside) << "rank " << rank << " ran another rank's items";
    EXPECT_EQ(last_report, owned.size());
  }
  EXPECT_EQ(combined, whole);
}

}  // namespace
}  // namespace pgm::detail::parallel_for_tests
