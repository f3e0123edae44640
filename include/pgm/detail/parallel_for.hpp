#pragma once
/// \file
/// Internal, do not depend on it: `parallel_for`, the one way pgm spreads work over threads
/// (simulation rows, counting rows, PC's edge tests, experiment repetitions).
///
/// A job is the items [0, n). They are handed out in chunks of consecutive items from one shared
/// counter, so a thread that finishes early takes more, and the calling thread works too. Every
/// result must depend on its item only: a caller writes it into a slot indexed by the item, or
/// into the worker's own state when the results add up exactly (integer counts, summed after
/// the job), and seeds randomness by the item. Then the output is the same for any number of
/// threads and any scheduling. Failures follow the same rule: when a chunk throws, no new chunks
/// are handed out, the chunks already taken finish, and the exception of the lowest failing item
/// is rethrown on the calling thread. Since chunks are handed out in increasing order, every
/// chunk before a failing one has been taken, so that is the same exception for any number of
/// threads.
///
/// Processes (the scale-out issue): `process_share` names the contiguous block of every job's
/// items that this process runs; by default one process owns them all. `parallel_for_on` runs a
/// job over a process group (pgm/detail/process_group.hpp): rank r of R runs only
/// [n·r/R, n·(r+1)/R) with its threads, and the failure rethrown on every rank is the one at the
/// lowest item over all ranks (a reduction of the failing index), so every rank reports the same
/// message. Results in item slots are then gathered to rank 0 in item order (`gather_slots`) and
/// integer sums (count tables) are summed over ranks by one reduction (`sum_over_processes`).
/// Items keep their global indices on every rank, which is why seeds and slots never depend on
/// how the work was split. Those steps belong here and nowhere else.

#include <algorithm>
#include <atomic>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "pgm/core/assert.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/detail/process_group.hpp"

namespace pgm::detail {

/// The items [begin, end) of a job, by their global indices.
struct item_range {
  std::size_t begin = 0;
  std::size_t end = 0;

  [[nodiscard]] constexpr std::size_t size() const noexcept { return end - begin; }
  [[nodiscard]] constexpr bool empty() const noexcept { return begin == end; }
  friend constexpr bool operator==(const item_range&, const item_range&) = default;
};

/// The part of every job this process runs: process `rank` of `ranks` owns one contiguous block.
struct process_share {
  std::size_t rank = 0;
  std::size_t ranks = 1;

  /// [n·rank/ranks, n·(rank+1)/ranks): blocks differ in size by at most one item.
  [[nodiscard]] constexpr item_range of(std::size_t n) const noexcept {
    PGM_ASSERT(rank < ranks, "a process share names a rank outside its processes");
    const auto edge = [&](std::size_t r) {
      // n·r/ranks without overflowing for any n.
      return n / ranks * r + n % ranks * r / ranks;
    };
    return {edge(rank), edge(rank + 1)};
  }
};

struct parallel_options {
  /// Threads, the calling one included; 0 uses every hardware thread.
  unsigned threads = 0;
  /// Consecutive items handed out at a time (at least 1).
  std::size_t chunk = 1;
  /// Each thread gets at least this many items, so small jobs use fewer threads: starting one
  /// must pay for itself.
  std::size_t min_items_per_thread = 1;
  process_share share;
  /// Called with the number of this process's items finished so far: one call at a time (from
  /// whichever thread finished a chunk), increasing, the last one with all of them (also when
  /// there are none). An exception thrown from it fails the chunk it reports.
  std::function<void(std::size_t done)> progress;
};

/// `threads`, or every hardware thread for 0.
[[nodiscard]] inline unsigned resolve_threads(unsigned threads) noexcept {
  return threads ? threads : std::max(1U, std::thread::hardware_concurrency());
}

/// The threads (the calling one included) that a job of `n` items gets: at most one per chunk,
/// at most `options.threads`, at least `options.min_items_per_thread` items each, and 0 when
/// this process owns no items.
[[nodiscard]] PGM_DECL unsigned worker_count(std::size_t n, const parallel_options& options) noexcept;

/// A callable that builds a thread's state: a value that can be moved out at the end.
template <class F>
concept StateFactory = std::invocable<F&> && std::move_constructible<std::invoke_result_t<F&>>;

template <StateFactory F>
using state_of = std::invoke_result_t<F&>;

/// A callable that runs one chunk of items with a thread's state.
template <class F, class State>
concept ChunkBody = std::invocable<F&, State&, item_range>;

/// Runs `body(state, chunk)` over this process's items of [0, n), chunk by chunk, on
/// worker_count(n, options) threads. Each thread builds its own state with `make_state()` just
/// before its first chunk (a thread that gets none builds none) and passes it to every chunk it
/// runs. Returns the states built, the calling thread's first. Rethrows the exception of the
/// lowest failing item (see the file comment).
template <StateFactory MakeState, ChunkBody<state_of<MakeState>> Body>
[[nodiscard]] std::vector<state_of<MakeState>> parallel_for(std::size_t n, const parallel_options& options,
                                                            MakeState&& make_state, Body&& body) {
  using state_type = state_of<MakeState>;
  const item_range owned = options.share.of(n);
  const std::size_t chunk = std::max<std::size_t>(1, options.chunk);
  const std::size_t chunks = owned.size() / chunk + (owned.size() % chunk != 0);
  const unsigned workers = worker_count(n, options);
  if (workers == 0) {
    if (options.progress) options.progress(0);
    return {};
  }

  std::vector<std::optional<state_type>> states(workers);
  std::atomic<std::size_t> next{0};
  std::mutex mutex;  // guards the three below and serializes progress calls
  std::exception_ptr failure;
  std::size_t failed_at = std::numeric_limits<std::size_t>::max();
  std::size_t done = 0;
  auto work = [&](unsigned worker) {
    for (;;) {
      const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
      if (c >= chunks) return;
      const item_range items{owned.begin + c * chunk, std::min(owned.end, owned.begin + (c + 1) * chunk)};
      try {
        auto& state = states[worker];
        if (!state) state.emplace(make_state());
        body(*state, items);
        if (options.progress) {
          const std::lock_guard lock(mutex);
          done += items.size();
          options.progress(done);
        }
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (items.begin < failed_at) {
          failed_at = items.begin;
          failure = std::current_exception();
        }
        next.store(chunks, std::memory_order_relaxed);  // hand out nothing more
        return;
      }
    }
  };
  {
    std::vector<std::jthread> helpers;
    helpers.reserve(workers - 1);
    for (unsigned w = 1; w < workers; ++w) helpers.emplace_back(work, w);
    work(0);
  }  // joins the helpers
  if (failure) std::rethrow_exception(failure);

  std::vector<state_type> built;
  for (auto& state : states) {
    if (state) built.push_back(std::move(*state));
  }
  return built;
}

/// Runs `body(chunk)` over this process's items of [0, n), as above but with no per-thread state.
template <std::invocable<item_range> Body>
void parallel_for(std::size_t n, const parallel_options& options, Body&& body) {
  struct no_state {};
  static_cast<void>(parallel_for(
      n, options, [] { return no_state{}; }, [&body](no_state&, item_range items) { body(items); }));
}

/// Runs a job over the processes of `group`: this process runs its share of [0, n) (rank r of
/// R: [n·r/R, n·(r+1)/R)) as parallel_for does, then every process agrees on the failure (see
/// pgm::agree): the lowest failing item over all processes is rethrown on every one.
/// Returns this process's states. `options.share` is replaced.
template <StateFactory MakeState, ChunkBody<state_of<MakeState>> Body>
[[nodiscard]] std::vector<state_of<MakeState>> parallel_for_on(process_group& group, std::size_t n,
                                                               parallel_options options, MakeState&& make_state,
                                                               Body&& body) {
  options.share = {group.rank(), group.size()};
  std::atomic<std::size_t> failed_at{std::numeric_limits<std::size_t>::max()};
  std::vector<state_of<MakeState>> states;
  std::exception_ptr failure;
  try {
    states = parallel_for(n, options, std::forward<MakeState>(make_state),
                          [&](state_of<MakeState>& state, item_range items) {
                            try {
                              body(state, items);
                            } catch (...) {
                              std::size_t seen = failed_at.load();
                              while (items.begin < seen && !failed_at.compare_exchange_weak(seen, items.begin)) {
                              }
                              throw;
                            }
                          });
  } catch (...) {
    failure = std::current_exception();
  }
  // A failure outside the body (a state's construction, progress) counts at the share's start.
  const std::size_t item =
      failed_at.load() == std::numeric_limits<std::size_t>::max() ? options.share.of(n).begin : failed_at.load();
  agree(group, failure, item);
  return states;
}

/// As above with no per-thread state.
template <std::invocable<item_range> Body>
void parallel_for_on(process_group& group, std::size_t n, const parallel_options& options, Body&& body) {
  struct no_state {};
  static_cast<void>(parallel_for_on(
      group, n, options, [] { return no_state{}; }, [&body](no_state&, item_range items) { body(items); }));
}

/// Collective: brings the slots [0, n) that each process filled for its share of a job
/// (parallel_for_on with the same n) to process 0, in item order. `write(writer, item)` puts
/// one slot's value into a byte_writer and `read(reader, item)` takes it back on process 0.
/// Like every collective step here it starts with an agreement (see agree), so a process that
/// failed before meets the others there.
template <class Write, class Read>
requires std::invocable<Write&, byte_writer&, std::size_t> && std::invocable<Read&, byte_reader&, std::size_t>
void gather_slots(process_group& group, std::size_t n, Write&& write, Read&& read) {
  if (group.size() == 1) return;
  agree(group, nullptr);
  const process_share mine{group.rank(), group.size()};
  byte_writer writer;
  const auto owned = mine.of(n);
  for (std::size_t item = owned.begin; item < owned.end; ++item) write(writer, item);
  const auto parts = group.gather(writer.take());
  for (std::size_t r = 1; r < parts.size(); ++r) {
    byte_reader reader(parts[r]);
    const auto theirs = process_share{r, group.size()}.of(n);
    for (std::size_t item = theirs.begin; item < theirs.end; ++item) read(reader, item);
    if (!reader.at_end()) throw std::logic_error("a process sent more than its share of a job");
  }
}

/// Collective: replaces `values` with their sum over all processes (count tables), after an
/// agreement that no process failed (`failure`: this process's, if it failed making them;
/// see agree). One process only rethrows its failure.
PGM_DECL void sum_over_processes(process_group& group, std::span<std::uint64_t> values,
                                 std::exception_ptr failure = nullptr);

}  // namespace pgm::detail

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/detail/impl/parallel_for.ipp"
#endif
