#include "commands/decide_common.hpp"

#include "cli/common.hpp"
#include "pgm/core/text.hpp"

namespace pgm::cli {

decision_model read_decision_model(const std::string& path, const std::string& success_text) {
  require_network_extension(path);
  std::vector<std::string> notes;
  auto model = pgm::read_decision_model(path, success_text, {.notes = &notes});
  for (const auto& line : notes) note(line);
  return model;
}

std::string describe_state(const variable& v, std::size_t state) {
  std::string text = v.states()[state];
  if (v.has_intervals()) {
    text += " [" + text::format_short(v.edges()[state]) + ", " + text::format_short(v.edges()[state + 1]) + ")";
    if (!v.tags().unit.empty()) text += " " + v.tags().unit;
  }
  return text;
}

std::string with_unit(const variable& v, double value) {
  auto text = text::format_short(value);
  if (!v.tags().unit.empty()) text += " " + v.tags().unit;
  return text;
}

assignment read_assignment(const std::string& text, const bayesian_network& network) {
  auto planned = parse_assignment(text, network);
  for (const auto& [name, value] : planned) {
    const auto* number = std::get_if<double>(&value);
    const auto& v = network.at(name);
    if (!number || !v.has_intervals()) continue;
    if (*number < v.edges().front() || *number > v.edges().back()) {
      note(name + " = " + with_unit(v, *number) + " lies outside the range the model was fitted on [" +
           with_unit(v, v.edges().front()) + ", " + with_unit(v, v.edges().back()) +
           "]; it counts as the outer interval");
    }
  }
  return planned;
}

void add_decision_options(CLI::App& command, decision_arguments& args, bool assign_required) {
  command.add_option("--model", args.model, "The fitted network: " + network_file_kinds())->required();
  command
      .add_option("--assign", args.assign,
                  "Planned values, e.g. \"xOff1=0.3,yOff1=-1.2,colour=Red\": numbers are binned with an interval "
                  "variable's saved edges; '@2' names the state labelled 2" +
                      std::string(assign_required ? "" : " (required, except with --dynamic)"))
      ->required(assign_required);
  command.add_option("--success", args.success,
                     "The success event, e.g. onTop2=1 (default: a JSON model's metadata, else the unique outcome)");
  command.add_flag("--marginalize", args.marginalize,
                   "Sum out unassigned, non-controllable parents of the success variable (exact inference) instead "
                   "of failing");
}

}  // namespace pgm::cli
