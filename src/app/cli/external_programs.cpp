#include "cli/external_programs.hpp"

#include <cstdlib>

namespace pgm::cli {

std::string shell_quoted(std::string_view text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

bool gnuplot_available() { return std::system("gnuplot --version > /dev/null 2>&1") == 0; }

bool run_gnuplot(const std::filesystem::path& script) {
  const auto command = "gnuplot " + shell_quoted(script.string()) + " 2>&1";
  return std::system(command.c_str()) == 0;
}

plot_renderer gnuplot_renderer(const std::function<void(const std::string&)>& note) {
  if (gnuplot_available()) return run_gnuplot;
  if (note) note("gnuplot is not installed: writing the plot scripts (.gp) without rendering them");
  return {};
}

bool dot_available() { return std::system("dot -V > /dev/null 2>&1") == 0; }

bool run_dot(const std::string& format, const std::filesystem::path& input, const std::filesystem::path& output,
             const std::filesystem::path& messages) {
  const auto command = "dot -T" + format + " " + shell_quoted(input.string()) + " -o " + shell_quoted(output.string()) +
                       " 2> " + shell_quoted(messages.string());
  return std::system(command.c_str()) == 0;
}

}  // namespace pgm::cli
