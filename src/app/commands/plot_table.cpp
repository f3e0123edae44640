// pgm plot-table: a table as a heat map over two of its parents (the paper's Fig. 5), drawn by
// gnuplot as PNG or SVG, or its gnuplot script.

#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "cli/external_programs.hpp"
#include "pgm/core/file.hpp"
#include "pgm/decide/assignment.hpp"
#include "pgm/decide/table_slice.hpp"
#include "pgm/eval/plot.hpp"
#include "pgm/io/decision_model.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm::cli {
namespace {

struct plot_table_arguments {
  std::string model;
  std::string node;
  std::string x, y;
  std::string given;
  bool average = false;
  std::string state;
  bool counts = false;
  std::string out;
};

/// An axis of the map: cells at the interval edges in the variable's units, or one unit per
/// state (labelled at its middle) for a categorical variable.
struct axis {
  std::vector<double> edges;
  std::string tics;
};

axis axis_of(const variable& v) {
  axis result;
  std::ostringstream tics;
  tics << '(';
  if (v.has_intervals()) {
    result.edges = v.edges();
    for (std::size_t e = 0; e < result.edges.size(); ++e) {
      tics << (e ? ", " : "") << gnuplot_quoted(text::format_short(result.edges[e])) << ' '
           << text::format_double(result.edges[e]);
    }
  } else {
    for (std::size_t s = 0; s <= v.cardinality(); ++s) result.edges.push_back(static_cast<double>(s));
    for (std::size_t s = 0; s < v.cardinality(); ++s) {
      tics << (s ? ", " : "") << gnuplot_quoted(v.states()[s]) << ' ' << static_cast<double>(s) + 0.5;
    }
  }
  tics << ')';
  result.tics = tics.str();
  return result;
}

std::string title_of(const table_slice& slice, const table_slice_request& request) {
  std::string title = "P(" + slice.node->name() + " = " + slice.node->states()[slice.state] + " | " + slice.x->name() +
                      ", " + slice.y->name();
  for (const auto& [name, value] : request.given) {
    title += ", " + name + " = " +
             (std::holds_alternative<double>(value) ? text::format_short(std::get<double>(value))
                                                    : std::get<std::string>(value));
  }
  return title + ")" + (request.average ? ", other parents averaged" : "");
}

/// The gnuplot script that draws `slice` into `output` with `terminal`.
std::string heat_map_script(const table_slice& slice, const table_slice_request& request, const std::string& terminal,
                            const std::filesystem::path& output) {
  const auto ax = axis_of(*slice.x), ay = axis_of(*slice.y);
  std::ostringstream g;
  g << "set terminal " << terminal << " size 820,680 font ',11'\nset output " << gnuplot_quoted(output.string())
    << "\n";
  g << "set title " << gnuplot_quoted(title_of(slice, request)) << " noenhanced\n";
  g << "set xlabel " << gnuplot_quoted(slice.x->name()) << " noenhanced\nset ylabel " << gnuplot_quoted(slice.y->name())
    << " noenhanced\n";
  g << "set xrange [" << text::format_double(ax.edges.front()) << ':' << text::format_double(ax.edges.back())
    << "]\nset yrange [" << text::format_double(ay.edges.front()) << ':' << text::format_double(ay.edges.back())
    << "]\n";
  g << "set xtics " << ax.tics << " out nomirror\nset ytics " << ay.tics << " out nomirror\n";
  g << "set cbrange [0:1]\nset cblabel "
    << gnuplot_quoted("P(" + slice.node->name() + " = " + slice.node->states()[slice.state] + ")") << " noenhanced\n";
  // viridis: dark for unlikely, yellow for likely, readable in grey too.
  g << "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', 1 '#fde725')\n";
  g << "set style fill solid 1.0 noborder\nset tics front\nunset key\n";
  g << "$cells << EOD\n";
  for (std::size_t j = 0; j < slice.y->cardinality(); ++j) {
    for (std::size_t i = 0; i < slice.x->cardinality(); ++i) {
      const double x0 = ax.edges[i], x1 = ax.edges[i + 1], y0 = ay.edges[j], y1 = ay.edges[j + 1];
      const double p = slice.at(i, j);
      g << text::format_double(0.5 * (x0 + x1)) << ' ' << text::format_double(0.5 * (y0 + y1)) << ' '
        << text::format_double(x0) << ' ' << text::format_double(x1) << ' ' << text::format_double(y0) << ' '
        << text::format_double(y1) << ' ' << text::format_double(p) << ' '
        << (slice.rows ? text::format_short((*slice.rows)[j * slice.x->cardinality() + i]) : "0") << '\n';
    }
  }
  g << "EOD\n";
  g << "plot $cells using 1:2:3:4:5:6:7 with boxxyerror fillcolor palette";
  if (slice.rows) {
    // The probability and the rows behind it, white on the dark half of the palette.
    g << ", \\\n     $cells using 1:2:(sprintf(\"%.2f\\n%s rows\", $7, stringcolumn(8))):($7 < 0.6 ? 0xffffff : 0) "
         "with labels textcolor rgb variable font ',9'";
  }
  g << "\n";
  return g.str();
}

void run_plot_table(const plot_table_arguments& args) {
  const std::filesystem::path out(args.out);
  const auto extension = pgm::lowercase_extension(out);
  if (extension != ".png" && extension != ".svg" && extension != ".gp") {
    throw error("--out '" + args.out + "': expected a .png or .svg picture, or .gp for the gnuplot script");
  }
  pgm::check_output_path(out);
  const auto model = read_model_file(args.model);
  const auto network = model.network();
  table_slice_request request{args.node, args.x, args.y, {}, args.average, std::nullopt};
  if (!args.given.empty()) request.given = parse_assignment(args.given, network);
  if (!args.state.empty()) {
    request.state = args.state;
  } else if (const auto event = read_success_metadata(args.model); event && event->starts_with(args.node + "=")) {
    request.state = event->substr(args.node.size() + 1);
  }
  if (args.counts && !model.statistics) {
    throw error("--counts: '" + args.model + "' carries no counts; fit it with pgm fit --keep-counts --out MODEL.json");
  }
  const auto slice = slice_table(network, request, args.counts ? &*model.statistics : nullptr);
  const auto summary =
      summary_before_replacing("drew P(" + args.node + " = " + slice.node->states()[slice.state] + ") over " +
                                   std::to_string(slice.x->cardinality()) + " x " +
                                   std::to_string(slice.y->cardinality()) + " cells -> " + args.out + "\n",
                               out);
  if (extension == ".gp") {
    const auto picture = std::filesystem::path(out).replace_extension(".png");
    pgm::write_file_atomically(
        out, [&](std::ostream& stream) { stream << heat_map_script(slice, request, "pngcairo", picture); }, summary);
  } else {
    if (!gnuplot_available()) {
      throw io_error("drawing " + extension +
                     " needs gnuplot (Debian: apt-get install gnuplot-nox); --out NAME.gp "
                     "writes the script without it");
    }
    // gnuplot draws beside the output and the picture is renamed into place: a failed run
    // leaves no half-written file.
    const auto stem = out.parent_path() / (".pgm-plot-" + std::to_string(std::random_device{}()));
    const auto picture = stem.string() + extension, script = stem.string() + ".gp";
    const auto terminal = extension == ".png" ? "pngcairo" : "svg";
    pgm::write_file_atomically(
        script, [&](std::ostream& stream) { stream << heat_map_script(slice, request, terminal, picture); });
    const bool drawn = run_gnuplot(script);
    std::filesystem::remove(script);
    std::error_code ignored;
    if (!drawn || !std::filesystem::exists(picture) || std::filesystem::file_size(picture, ignored) == 0) {
      std::filesystem::remove(picture, ignored);
      throw io_error("gnuplot could not draw '" + args.out + "' (its messages are above)");
    }
    try {
      summary();
    } catch (...) {
      std::filesystem::remove(picture, ignored);
      throw;
    }
    std::filesystem::rename(picture, out);
  }
}

}  // namespace

void add_plot_table_command(CLI::App& app) {
  auto args = std::make_shared<plot_table_arguments>();
  auto* cmd = app.add_subcommand(
      "plot-table",
      "Draw a table as a heat map over two of its parents: the probability of one state in each cell (PNG or SVG "
      "through gnuplot, or the script).\n"
      "Example: pgm plot-table --model 2-stack.json --node onTop2 --x xOff2 --y yOff2 --given xOff1=@2,yOff1=@2 "
      "--out t.png");
  cmd->add_option("--model", args->model, "The fitted network: " + network_file_kinds() + " (.gz too)")->required();
  cmd->add_option("--node", args->node, "The variable whose table is drawn")->required();
  cmd->add_option("--x", args->x, "The parent across (its interval edges, in its units, as ticks)")->required();
  cmd->add_option("--y", args->y, "The parent up")->required();
  cmd->add_option("--given", args->given,
                  "The other parents' values, as pgm predict reads them: xOff1=0.3 (a number in the units, binned) "
                  "or xOff1=@2 (the state labelled 2)");
  cmd->add_flag("--average", args->average,
                "Sum the parents not given out under the network's joint distribution (by exact inference)");
  cmd->add_option("--state", args->state,
                  "The state whose probability is drawn (default: the model's success state for its success "
                  "variable, else the last state)");
  cmd->add_flag("--counts", args->counts,
                "Write each cell's probability and the rows behind it (needs a model fitted with --keep-counts)");
  cmd->add_option("--out", args->out, "The picture: .png or .svg, or .gp for the gnuplot script")->required();
  cmd->callback([args] { run_plot_table(*args); });
}

}  // namespace pgm::cli
