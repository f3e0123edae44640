#pragma once
// The programs the commands draw with, run through the shell: gnuplot for plots and Graphviz's
// dot for networks. Kept out of the library, which writes scripts but never spawns a process.

#include <filesystem>
#include <string>
#include <string_view>

#include "pgm/eval/report_writer.hpp"

namespace pgm::cli {

/// A POSIX shell single-quoted word.
[[nodiscard]] std::string shell_quoted(std::string_view text);

/// Whether `gnuplot` can be run.
[[nodiscard]] bool gnuplot_available();

/// Runs gnuplot on a script file (its messages go to standard output); false if it failed.
bool run_gnuplot(const std::filesystem::path& script);

/// What `pgm experiment` renders its plots with: gnuplot when it is installed, and otherwise
/// nothing (the scripts alone are written) after telling `note` so.
[[nodiscard]] plot_renderer gnuplot_renderer(const std::function<void(const std::string&)>& note);

/// Whether Graphviz's `dot` can be run.
[[nodiscard]] bool dot_available();

/// Runs `dot -T<format> input -o output`, its messages into `messages`; false if it failed.
bool run_dot(const std::string& format, const std::filesystem::path& input, const std::filesystem::path& output,
             const std::filesystem::path& messages);

}  // namespace pgm::cli
