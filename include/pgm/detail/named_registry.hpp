#pragma once
// Internal: not part of pgm's API, may change without notice.
//
// `named_registry<T>`: the thread-safe name → value table behind the transfer-strategy and
// simulator back-end registries. Each registry words its own "unknown name" error, so
// `find` returns nothing rather than throwing.

#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"

namespace pgm::detail {

template <class T>
class named_registry {
 public:
  /// `kind` names an entry in error messages ("transfer strategy").
  explicit named_registry(std::string kind) : kind_(std::move(kind)) {}
  named_registry(named_registry&& other) noexcept
      : kind_(std::move(other.kind_)), entries_(std::move(other.entries_)) {}

  /// Adds `value` under `name`; an empty or taken name is a model_error.
  void add(std::string name, T value) {
    if (name.empty()) throw model_error("a " + kind_ + " needs a non-empty name");
    const std::lock_guard lock(mutex_);
    if (!entries_.emplace(name, std::move(value)).second) {
      throw model_error("a " + kind_ + " named '" + name + "' is registered already");
    }
  }

  [[nodiscard]] std::optional<T> find(std::string_view name) const {
    const std::lock_guard lock(mutex_);
    const auto it = entries_.find(name);
    if (it == entries_.end()) return std::nullopt;
    return it->second;
  }

  /// The names, sorted.
  [[nodiscard]] std::vector<std::string> names() const {
    const std::lock_guard lock(mutex_);
    std::vector<std::string> result;
    result.reserve(entries_.size());
    for (const auto& entry : entries_) result.push_back(entry.first);
    return result;
  }

 private:
  std::string kind_;
  mutable std::mutex mutex_;
  std::map<std::string, T, std::less<>> entries_;
};

}  // namespace pgm::detail
