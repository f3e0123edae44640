#pragma once
// The definitions of pgm/io/decision_model.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/io/decision_model.hpp"

namespace pgm {

PGM_DECL std::optional<std::string> read_success_metadata(const std::filesystem::path& path) {
  if (format_to_read(path) != network_format("json")) return std::nullopt;
  const auto document = nlohmann::json::parse(read_model_text(path), nullptr, false);
  if (!document.is_object()) return std::nullopt;
  const auto metadata = document.find("metadata");
  if (metadata == document.end() || !metadata->is_object()) return std::nullopt;
  const auto success = metadata->find("success");
  if (success == metadata->end()) return std::nullopt;
  if (!success->is_string()) {
    throw data_error(path.string() + ": /metadata/success: expected a string such as \"onTop2=1\"");
  }
  return success->get<std::string>();
}

PGM_DECL success_event choose_success_event(const bayesian_network& network, std::string_view given,
                                            const std::optional<std::string>& metadata) {
  if (!given.empty()) return parse_success_event(given, network);
  if (metadata) return parse_success_event(*metadata, network);
  return default_success_event(network);
}

PGM_DECL decision_model read_decision_model(const std::filesystem::path& path, std::string_view success_text,
                                            const network_read_options& options) {
  auto network = read_network(path, options);
  auto success =
      choose_success_event(network, success_text, success_text.empty() ? read_success_metadata(path) : std::nullopt);
  return {std::move(network), std::move(success)};
}

}  // namespace pgm
