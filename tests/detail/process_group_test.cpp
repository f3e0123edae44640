// Jobs over several processes, played by threads (support/thread_processes.hpp), so the
// splitting, gathering, summing and agreeing of pgm/detail/parallel_for.hpp are tested without
// MPI (tests/mpi runs the program under mpirun).

#include "pgm/detail/process_group.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <barrier>
#include <cstdint>
#include <functional>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/detail/parallel_for.hpp"
#include "pgm/detail/splitmix.hpp"
#include "support/thread_processes.hpp"

namespace pgm::detail::process_group_tests {
namespace {

using pgm::testing::outcome;
using pgm::testing::run_group;
using ::testing::HasSubstr;

// Item i's value depends on i only.
std::vector<std::uint64_t> gathered_values(process_group& group, std::size_t n, unsigned threads) {
  std::vector<std::uint64_t> slots(n);
  parallel_for_on(group, n, {.threads = threads, .chunk = 3}, [&](item_range items) {
    for (auto i = items.begin; i < items.end; ++i) slots[i] = splitmix64_mix(i);
  });
  gather_slots(
      group, n, [&](byte_writer& out, std::size_t i) { out.put(slots[i]); },
      [&](byte_reader& in, std::size_t i) { slots[i] = in.get<std::uint64_t>(); });
  return slots;
}

TEST(process_group_test, shares_cover_every_item_once_in_contiguous_blocks) {
  for (std::size_t n : {0, 1, 7, 100, 1001}) {
    for (std::size_t ranks = 1; ranks <= 9; ++ranks) {
      std::size_t next = 0;
      for (std::size_t r = 0; r < ranks; ++r) {
        const auto block = process_share{r, ranks}.of(n);
        EXPECT_EQ(block.begin, next);
        EXPECT_LE(block.size(), n / ranks + 1);
        EXPECT_GE(block.size(), n / ranks);
        next = block.end;
      }
      EXPECT_EQ(next, n);
    }
  }
}

TEST(process_group_test, gathered_slots_are_in_item_order_for_any_split) {
  const auto expected = gathered_values(lone_process(), 200, 2);
  for (std::size_t ranks = 1; ranks <= 8; ++ranks) {
    for (unsigned threads : {1U, 3U}) {
      std::vector<std::uint64_t> on_first;
      run_group(ranks, [&](process_group& group) {
        auto slots = gathered_values(group, 200, threads);
        if (group.rank() == 0) on_first = std::move(slots);
      });
      EXPECT_EQ(on_first, expected) << ranks << " processes, " << threads << " threads";
    }
  }
}

TEST(process_group_test, a_process_runs_only_its_share) {
  run_group(3, [](process_group& group) {
    std::vector<int> ran(10, 0);
    parallel_for_on(group, 10, {.threads = 2}, [&](item_range items) {
      for (auto i = items.begin; i < items.end; ++i) ++ran[i];
    });
    const auto mine = process_share{group.rank(), 3}.of(10);
    for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(ran[i], mine.begin <= i && i < mine.end ? 1 : 0);
  });
}

TEST(process_group_test, count_tables_are_summed_over_processes) {
  run_group(4, [](process_group& group) {
    std::vector<std::uint64_t> counts{group.rank(), 1, 10 * group.rank()};
    sum_over_processes(group, counts);
    EXPECT_EQ(counts, (std::vector<std::uint64_t>{6, 4, 60}));
  });
}

TEST(process_group_test, a_process_that_failed_making_its_summands_fails_every_process_before_the_sum) {
  std::vector<std::string> steps;
  const auto outcomes = run_group(
      3,
      [](process_group& group) {
        std::vector<std::uint64_t> counts{1, 2};
        std::exception_ptr failure;
        if (group.rank() == 2) failure = std::make_exception_ptr(data_error("no counts on 2"));
        sum_over_processes(group, counts, failure);
      },
      &steps);
  for (const auto& o : outcomes) EXPECT_THAT(o.message, HasSubstr("no counts on 2"));
  EXPECT_EQ(steps, (std::vector<std::string>{"smallest", "broadcast"})) << "no sum after a failure";
}

TEST(process_group_test, every_process_throws_the_failure_of_the_lowest_item) {
  // Items 130 (rank 2 of 4) and 170 (rank 3) fail; each process sees item 130's message.
  const auto outcomes = run_group(4, [](process_group& group) {
    parallel_for_on(group, 200, {.threads = 2}, [](item_range items) {
      for (auto i = items.begin; i < items.end; ++i) {
        if (i == 130 || i == 170) throw data_error("bad item " + std::to_string(i));
      }
    });
  });
  for (std::size_t r = 0; r < 4; ++r) {
    EXPECT_THAT(outcomes[r].message, HasSubstr("bad item 130")) << r;
    EXPECT_EQ(outcomes[r].remote, r != 2) << "the process that failed rethrows its own exception";
    EXPECT_TRUE(outcomes[r].failed_flag);
  }
}

TEST(process_group_test, a_process_failing_before_a_job_meets_the_others_at_its_agreement) {
  // Rank 1 fails before the job and goes straight to its final agreement, as pgm's main does;
  // the others are in the job's agreement, the same collective step: nobody waits forever.
  std::vector<std::string> steps;
  const auto outcomes = run_group(
      3,
      [](process_group& group) {
        std::exception_ptr failure;
        try {
          if (group.rank() == 1) throw io_error("cannot open 'data.csv'");
          static_cast<void>(gathered_values(group, 30, 1));
        } catch (...) {
          failure = std::current_exception();
        }
        if (!group.failed()) {
          agree(group, failure);
        } else if (failure) {
          std::rethrow_exception(failure);
        }
      },
      &steps);
  for (const auto& o : outcomes) EXPECT_THAT(o.message, HasSubstr("cannot open 'data.csv'"));
  EXPECT_EQ(steps, (std::vector<std::string>{"smallest", "broadcast"})) << "no gather after a failure";
}

TEST(process_group_test, internal_errors_and_out_of_memory_keep_their_kind) {
  const auto internal = run_group(2, [](process_group& group) {
    agree(group, group.rank() == 1 ? std::make_exception_ptr(std::logic_error("broken invariant")) : nullptr);
  });
  EXPECT_EQ(internal[0].message, "broken invariant");
  EXPECT_FALSE(internal[0].remote) << "an internal error stays internal (exit code 3)";
  const auto memory = run_group(2, [](process_group& group) {
    agree(group, group.rank() == 1 ? std::make_exception_ptr(std::bad_alloc()) : nullptr);
  });
  EXPECT_EQ(memory[0].message, std::bad_alloc().what());
}

TEST(process_group_test, no_failure_means_no_broadcast) {
  std::vector<std::string> steps;
  const auto outcomes = run_group(
      3, [](process_group& group) { agree(group, nullptr); }, &steps);
  for (const auto& o : outcomes) EXPECT_EQ(o.message, "");
  EXPECT_EQ(steps, (std::vector<std::string>{"smallest"}));
}

TEST(process_group_test, one_process_rethrows_at_once_and_gathers_nothing) {
  EXPECT_THROW(agree(lone_process(), std::make_exception_ptr(data_error("x"))), data_error);
  EXPECT_NO_THROW(agree(lone_process(), nullptr));
  EXPECT_EQ(&processes(), &lone_process()) << "without a launcher pgm runs as one process";
}

TEST(process_group_test, bytes_read_back_as_written) {
  byte_writer out;
  out.put(std::uint64_t{42});
  out.put(std::string_view("two words"));
  out.put(-0.125);
  const std::vector<std::uint32_t> values{1, 2, 3};
  out.put_all(std::span<const std::uint32_t>(values));
  const auto bytes = out.take();
  byte_reader in(bytes);
  EXPECT_EQ(in.get<std::uint64_t>(), 42U);
  EXPECT_EQ(in.get_string(), "two words");
  EXPECT_EQ(in.get<double>(), -0.125);
  std::vector<std::uint32_t> back(3);
  in.get_all(std::span<std::uint32_t>(back));
  EXPECT_EQ(back, values);
  EXPECT_TRUE(in.at_end());
  EXPECT_THAT([&] { static_cast<void>(in.get<char>()); },
              ::testing::ThrowsMessage<std::logic_error>(HasSubstr("end early")));
}

}  // namespace
}  // namespace pgm::detail::process_group_tests
