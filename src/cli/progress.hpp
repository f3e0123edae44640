#pragma once
// A one-line progress bar on stderr, drawn only when stderr is a terminal and redrawn only when
// the percentage changes, so that logs and pipes stay clean.

#include <cstdio>
#include <string>

#include "cli/common.hpp"

namespace pgm::cli {

class progress_bar {
 public:
  explicit progress_bar(std::string label) : label_(std::move(label)), enabled_(stderr_is_terminal()) {}
  progress_bar(const progress_bar&) = delete;
  progress_bar& operator=(const progress_bar&) = delete;
  ~progress_bar() { finish(); }

  void update(std::size_t done, std::size_t total) {
    if (!enabled_) return;
    const int percent = total ? static_cast<int>(100 * done / total) : 100;
    if (percent == shown_) return;
    shown_ = percent;
    std::string bar(static_cast<std::size_t>(percent / 4), '#');
    bar.resize(25, '.');
    std::fprintf(stderr, "\r%s [%s] %3d%% %zu/%zu", label_.c_str(), bar.c_str(), percent, done, total);
    std::fflush(stderr);
  }
  /// Ends the line, once.
  void finish() {
    if (enabled_ && shown_ >= 0) std::fputc('\n', stderr);
    shown_ = -1;
    enabled_ = false;
  }

 private:
  std::string label_;
  bool enabled_;
  int shown_ = -1;
};

}  // namespace pgm::cli
