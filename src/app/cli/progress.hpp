#pragma once
// A one-line progress bar on stderr, drawn only when stderr is a terminal and redrawn only when
// the percentage changes, so that logs and pipes stay clean. Once a second has passed it adds
// an estimate of the time left, from the mean pace so far.

#include <chrono>
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
    std::string left;
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
    if (done > 0 && done < total && elapsed.count() >= 1) {
      left = ", about " +
             duration_text(elapsed.count() * static_cast<double>(total - done) / static_cast<double>(done)) + " left";
    }
    std::fprintf(stderr, "\r%s [%s] %3d%% %zu/%zu%s   ", label_.c_str(), bar.c_str(), percent, done, total,
                 left.c_str());
    std::fflush(stderr);
  }
  /// Ends the line, once.
  void finish() {
    if (enabled_ && shown_ >= 0) std::fputc('\n', stderr);
    shown_ = -1;
    enabled_ = false;
  }

 private:
  /// "45 s", "3 min 12 s", "1 h 02 min".
  static std::string duration_text(double seconds) {
    const auto s = static_cast<long>(seconds + 0.5);
    char text[32];
    if (s < 60) {
      std::snprintf(text, sizeof text, "%ld s", s);
    } else if (s < 3600) {
      std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
    } else {
      std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, s / 60 % 60);
    }
    return text;
  }

  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::string label_;
  bool enabled_;
  int shown_ = -1;
};

}  // namespace pgm::cli
