// pgm draw: a network's structure as a picture (SVG, PNG, PDF through Graphviz's dot) or as
// DOT text.

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.hpp"
#include "cli/external_programs.hpp"
#include "pgm/core/file.hpp"
#include "pgm/io/decision_model.hpp"
#include "pgm/io/dot.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm::cli {
namespace {

struct draw_arguments {
  std::string model;
  std::string out;
  std::string success;
  std::string controllable;
};

/// What pgm learn-structure kept in a JSON structure file: the CPDAG's undirected edges and
/// the bootstrap strength of each edge.
void add_learned(const std::filesystem::path& path, dot_options& options) {
  if (format_to_read(path) != network_format("json")) return;
  const auto document = nlohmann::json::parse(read_model_text(path), nullptr, false);
  const auto learned = document.is_object() ? document.find("learned") : document.end();
  if (learned == document.end() || !learned->is_object()) return;
  if (const auto undirected = learned->find("undirected_in_cpdag");
      undirected != learned->end() && undirected->is_array()) {
    for (const auto& pair : *undirected) {
      if (pair.is_array() && pair.size() == 2 && pair[0].is_string() && pair[1].is_string()) {
        options.undirected.emplace_back(pair[0].get<std::string>(), pair[1].get<std::string>());
      }
    }
  }
  if (const auto strength = learned->find("strength"); strength != learned->end() && strength->is_array()) {
    for (const auto& arc : *strength) {
      if (arc.is_object() && arc.contains("from") && arc.contains("to") && arc.contains("strength") &&
          arc["from"].is_string() && arc["to"].is_string() && arc["strength"].is_number()) {
        options.strength[{arc["from"].get<std::string>(), arc["to"].get<std::string>()}] =
            arc["strength"].get<double>();
      }
    }
  }
}

/// Graphviz's dot renders `text` in `format` (svg, png, pdf); its bytes, or io_error with its message.
std::string render_with_dot(const std::string& text, const std::string& format) {
  if (!dot_available()) {
    throw io_error("drawing ." + format +
                   " needs Graphviz's dot (Debian: apt-get install graphviz); "
                   "--out NAME.dot writes the DOT text without it");
  }
  const auto folder = std::filesystem::temp_directory_path();
  const auto stem = folder / ("pgm-draw-" + std::to_string(std::random_device{}()));
  const auto input = stem.string() + ".dot", output = stem.string() + "." + format, messages = stem.string() + ".err";
  std::ofstream(input, std::ios::binary) << text;
  const bool drawn = run_dot(format, input, output, messages);
  std::string bytes, problem;
  if (drawn) bytes = pgm::read_file(output);
  if (std::filesystem::exists(messages)) problem = pgm::read_file(messages);
  for (const auto& file : {input, output, messages}) std::filesystem::remove(file);
  if (!drawn || bytes.empty()) throw io_error("Graphviz's dot could not draw the network: " + problem);
  return bytes;
}

void run_draw(const draw_arguments& args) {
  const std::filesystem::path out(args.out);
  const auto extension = pgm::lowercase_extension(out);
  if (extension != ".svg" && extension != ".png" && extension != ".pdf" && extension != ".dot") {
    throw error("--out '" + args.out + "': expected a .svg, .png, .pdf or .dot file");
  }
  pgm::check_output_path(out);
  const auto model = read_model_file(args.model);
  dot_options options;
  if (!args.success.empty()) {
    options.success.push_back(args.success);
  } else if (const auto event = read_success_metadata(args.model)) {
    options.success.push_back(event->substr(0, event->find('=')));
  }
  if (!args.controllable.empty()) options.controllable = text::split(args.controllable, ',');
  add_learned(args.model, options);
  const auto text = to_dot(model.structure, options);
  const auto bytes = extension == ".dot" ? text : render_with_dot(text, extension.substr(1));
  pgm::write_file_atomically(
      out, [&](std::ostream& stream) { stream << bytes; },
      summary_before_replacing("drew " + std::to_string(model.structure.size()) + " variables and " +
                                   std::to_string(model.structure.edges().size()) + " edges -> " + args.out + "\n",
                               out));
}

}  // namespace

void add_draw_command(CLI::App& app) {
  auto args = std::make_shared<draw_arguments>();
  auto* cmd =
      app.add_subcommand("draw",
                         "Draw a network's structure: SVG, PNG or PDF through Graphviz's dot, or the DOT text.\n"
                         "Example: pgm draw --model 2-stack.json --controllable xOff2,yOff2 --out 2-stack.svg");
  cmd->add_option("--model", args->model,
                  "The network or structure: " + network_file_kinds() +
                      " (a structure from pgm learn-structure draws "
                      "its undirected edges without arrowheads and its bootstrap strengths as widths)")
      ->required();
  cmd->add_option("--out", args->out, "The picture: .svg, .png, .pdf, or .dot for the text")->required();
  cmd->add_option("--success", args->success,
                  "The success variable, drawn bold on green (default: the model's metadata, if it names one)");
  cmd->add_option("--controllable", args->controllable,
                  "The variables the robot sets, drawn as blue boxes, e.g. xOff2,yOff2");
  cmd->callback([args] { run_draw(*args); });
}

}  // namespace pgm::cli
