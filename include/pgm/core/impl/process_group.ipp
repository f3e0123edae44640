#pragma once
// The definitions of pgm/core/process_group.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/core/process_group.hpp"

namespace pgm::detail {

PGM_DECL std::string describe_failure(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const error& e) {
    return static_cast<char>(failure_kind::error) + std::string(e.what());
  } catch (const std::bad_alloc&) {
    return static_cast<char>(failure_kind::out_of_memory) + std::string("out of memory");
  } catch (const std::exception& e) {
    return static_cast<char>(failure_kind::internal) + std::string(e.what());
  } catch (...) {
    return static_cast<char>(failure_kind::internal) + std::string("unknown exception");
  }
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL void agree(process_group& group, std::exception_ptr failure, std::size_t item) {
  if (group.size() == 1) {
    if (failure) std::rethrow_exception(failure);
    return;
  }
  constexpr auto none = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t ranks = group.size();
  const std::uint64_t largest_item = (none - 1) / ranks - 1;
  const std::uint64_t key = failure ? std::min<std::uint64_t>(item, largest_item) * ranks + group.rank() : none;
  const std::uint64_t lowest = group.smallest(key);
  if (lowest == none) return;
  const auto root = static_cast<std::size_t>(lowest % ranks);
  const std::string description = group.broadcast(group.rank() == root ? detail::describe_failure(failure) : "", root);
  group.mark_failed();
  if (group.rank() == root) std::rethrow_exception(failure);
  const std::string message = description.substr(1);
  switch (static_cast<detail::failure_kind>(description.at(0))) {
    case detail::failure_kind::error:
      throw remote_error(message);
    case detail::failure_kind::out_of_memory:
      throw std::bad_alloc();
    case detail::failure_kind::internal:
      break;
  }
  throw std::runtime_error(message);
}

}  // namespace pgm
