#pragma once
/// \file
/// The processes a job is spread over, as the few collective steps pgm needs: the smallest of
/// a number, a broadcast, a gather to process 0 in rank order and a sum of integers. One
/// process, as started without a launcher, is the default and does no communication; the
/// program installs an MPI group when mpirun or srun started it (src/app/mpi), and a test can
/// install threads as processes. Whatever scales out takes its group as an argument
/// (csv_source, count_csv) or chooses between processes() and lone_process() (sim/run.hpp,
/// eval/experiment.hpp, run_scenarios.hpp); jobs are split into blocks of items in
/// pgm/detail/parallel_for.hpp.
///
/// Failures are agreed on, not aborted: after each phase every process calls `agree` with its
/// failure (or none), which is itself a collective step, so a process that failed before a
/// phase meets the others at the next agreement, never inside another collective. Every
/// process then throws the same failure: that of the lowest failing item over all processes
/// (the lowest rank among equals), its message sent by the process that had it.

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"

namespace pgm {

/// The processes that run a job together. Every member calls each collective step in the same
/// order; a step that is not collective says so.
class process_group {
 public:
  virtual ~process_group() = default;

  /// This process: 0 to size() - 1. Not collective.
  [[nodiscard]] virtual std::size_t rank() const noexcept = 0;
  /// The number of processes. Not collective.
  [[nodiscard]] virtual std::size_t size() const noexcept = 0;
  /// The smallest `value` over all processes, on every process.
  [[nodiscard]] virtual std::uint64_t smallest(std::uint64_t value) = 0;
  /// The `bytes` of process `root`, on every process (the others' argument is ignored).
  [[nodiscard]] virtual std::string broadcast(std::string bytes, std::size_t root) = 0;
  /// Every process's `bytes` on process 0, in rank order; empty on the others.
  [[nodiscard]] virtual std::vector<std::string> gather(std::string_view bytes) = 0;
  /// Replaces `values` with their element-wise sum over all processes, on every process.
  virtual void sum(std::span<std::uint64_t> values) = 0;

  /// Whether an agreement has found a failure: there are no collective steps after it.
  [[nodiscard]] bool failed() const noexcept { return failed_; }
  void mark_failed() noexcept { failed_ = true; }

 private:
  bool failed_ = false;
};

/// One process: every step is local.
class single_process final : public process_group {
 public:
  [[nodiscard]] std::size_t rank() const noexcept override { return 0; }
  [[nodiscard]] std::size_t size() const noexcept override { return 1; }
  [[nodiscard]] std::uint64_t smallest(std::uint64_t value) override { return value; }
  [[nodiscard]] std::string broadcast(std::string bytes, std::size_t) override { return bytes; }
  [[nodiscard]] std::vector<std::string> gather(std::string_view bytes) override { return {std::string(bytes)}; }
  void sum(std::span<std::uint64_t>) override {}
};

namespace detail {
inline process_group*& installed_process_group() {
  static process_group* group = nullptr;
  return group;
}
}  // namespace detail

/// A group of one process, for work that is not spread (whatever processes() is).
[[nodiscard]] inline process_group& lone_process() {
  static single_process alone;
  return alone;
}

/// The group this program runs in: one process unless a launcher's group was installed.
[[nodiscard]] inline process_group& processes() {
  auto* group = detail::installed_process_group();
  return group ? *group : lone_process();
}

/// Installs `group` (null: back to one process); it must outlive its use.
inline void install_processes(process_group* group) noexcept { detail::installed_process_group() = group; }

/// A failure that happened on another process, rethrown here with its message.
class remote_error : public error {
 public:
  explicit remote_error(const std::string& message) : error(message) {}
};

namespace detail {

/// What kind of failure crossed between processes, for the exit code.
enum class failure_kind : char { error = 'E', out_of_memory = 'M', internal = 'I' };

/// The kind and message of `failure`.
[[nodiscard]] PGM_DECL std::string describe_failure(const std::exception_ptr& failure);

}  // namespace detail

/// Collective: every process says whether its phase failed (`failure`, at item `item` of the
/// phase's job; 0 for a failure that belongs to no item). Returns when none did; otherwise
/// every process throws the failure of the lowest item (lowest rank among equals): the process
/// that had it rethrows its own exception, the others a remote_error (or bad_alloc, or
/// std::runtime_error for an internal error) with its message. One process only rethrows.
PGM_DECL void agree(process_group& group, std::exception_ptr failure, std::size_t item = 0);

/// Runs `phase` on every process and agrees on its failure (see agree).
template <std::invocable Phase>
void run_agreed(process_group& group, Phase&& phase) {
  std::exception_ptr failure;
  try {
    phase();
  } catch (...) {
    failure = std::current_exception();
  }
  agree(group, failure);
}

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/core/impl/process_group.ipp"
#endif
