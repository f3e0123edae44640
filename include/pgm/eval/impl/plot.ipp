#pragma once
// The definitions of pgm/eval/plot.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/eval/plot.hpp"

namespace pgm {

PGM_DECL std::string gnuplot_quoted(std::string_view text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

PGM_DECL std::string gnuplot_script(const scenario& s, const std::string& target,
                                    const std::vector<aggregated_point>& summary, const std::filesystem::path& stem) {
  // metric → line ("strategy|weight") → points, in the summary's order of |D|.
  std::map<std::string, std::map<std::string, std::vector<const aggregated_point*>>> lines;
  const std::vector<std::string>& columns = s.strategies;
  for (const auto& p : summary) {
    if (p.scenario != s.name || p.target != target || p.metric == experiment_metric::chosen_w) continue;
    lines[std::string(to_string(p.metric))][p.strategy + "|" + p.weight].push_back(&p);
  }
  std::ostringstream g;
  std::size_t block = 0;
  std::map<std::string, std::string> block_of;
  for (const auto& [metric, by_line] : lines) {
    for (const auto& [line, points] : by_line) {
      const std::string name = "$d" + std::to_string(block++);
      block_of[metric + "#" + line] = name;
      g << name << " << EOD\n";
      for (const auto* p : points) {
        g << p->rows << ' ' << text::format_double(p->mean) << ' ' << text::format_double(p->standard_deviation)
          << '\n';
      }
      g << "EOD\n";
    }
  }
  // The paper's colours by rank: the smallest weight green, then red, then yellow.
  std::map<std::string, std::string> colour{{"auto", "#000000"}};
  const std::vector<std::string> palette{"#2ca02c", "#d62728", "#e6b800", "#8c564b", "#17becf"};
  std::size_t rank = 0;
  for (double w : s.weights) {
    if (w > 0) colour.emplace(text::format_short(w), palette[std::min(rank++, palette.size() - 1)]);
  }
  const std::vector<std::pair<std::string, std::string>> metrics{{"max_difference", "Max-Difference"},
                                                                 {"mean_difference", "Mean-Difference"},
                                                                 {"failure_prevention", "success after prevention"}};
  const std::size_t panels = std::max<std::size_t>(1, columns.size());
  // 420 px per panel as before the legends moved out, plus room for the legend beside it.
  const auto width = panels * 600;
  auto render = [&](const std::string& terminal, const std::string& file) {
    g << "set terminal " << terminal << " size " << width << ",900\nset output " << gnuplot_quoted(file) << "\n";
    g << "set multiplot layout 3," << panels << " title " << gnuplot_quoted(s.title + ": " + target) << "\n";
    g << "set key outside right top vertical Left reverse samplen 2 font ',8'\nset grid\nset xlabel '|D|'\n";
    for (const auto& metric_label : metrics) {
      const auto& metric = metric_label.first;  // captured below: no structured binding (clang < 16)
      const auto& label = metric_label.second;
      for (const auto& column : columns) {
        g << "set title " << gnuplot_quoted(column) << "\nset ylabel " << gnuplot_quoted(label) << "\n";
        g << (metric == "failure_prevention" ? "set yrange [0:1]\n" : "set yrange [0:*]\n");
        std::vector<std::string> plots;
        auto add = [&](const std::string& line, const std::string& title, const std::string& style) {
          const auto it = block_of.find(metric + "#" + line);
          if (it != block_of.end()) {
            plots.push_back(it->second + " using 1:2 with lines " + style + " title " + gnuplot_quoted(title));
          }
        };
        add("mle|0", "MLE", "lw 2 lc rgb '#1f77b4'");
        for (const auto& [line, points] : lines[metric]) {
          const auto bar = line.find('|');
          const auto strategy = line.substr(0, bar), weight = line.substr(bar + 1);
          if (strategy == column) {
            const auto c = colour.find(weight);
            add(line, "w = " + weight,
                std::string("lw 2 ") + (weight == "auto" ? "dt 2 " : "") + "lc rgb '" +
                    (c == colour.end() ? std::string("#9467bd") : c->second) + "'");
          } else if (strategy == column + "+auto-map") {
            add(line, "auto map, w = " + weight, "lw 2 dt 3 lc rgb '#9467bd'");
          }
        }
        if (metric == "failure_prevention") add("oracle|0", "oracle", "lw 1 dt 4 lc rgb '#7f7f7f'");
        g << "plot " << text::join(plots, ", \\\n     ") << "\n";
      }
    }
    g << "unset multiplot\n";
  };
  render("pngcairo", stem.string() + ".png");
  render("svg", stem.string() + ".svg");
  return g.str();
}

}  // namespace pgm
