#pragma once
// Internal to libpgm: the built-in network formats, each defined beside its reader and writer
// (bif.cpp, xmlbif.cpp, net.cpp, json_format.cpp, uai.cpp) and listed once, in network_format.cpp, and
// what the formats without a place for counts of their own share to keep a fit's counts.

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/io/network_format.hpp"

namespace pgm::detail {

[[nodiscard]] network_format_codec bif_format();
[[nodiscard]] network_format_codec xmlbif_format();
[[nodiscard]] network_format_codec net_format();
[[nodiscard]] network_format_codec json_format();
[[nodiscard]] network_format_codec uai_format();

/// BIF, XMLBIF and NET keep a fit's counts in a network-level property, pgm.statistics: the
/// counts as pgm's JSON (pgm/io/statistics_json.hpp), compact, in base64 without its '='
/// padding, which peers' property readers split at.
inline constexpr const char* statistics_property = "statistics";

/// The network-level properties to write for `options`: the kept counts, if any.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> kept_properties(const network_write_options& options);

/// A model read by `parse`, a reader of a format with network-level properties, with the counts
/// its statistics property keeps.
template <class Parse>
[[nodiscard]] model_document read_keeping_statistics(Parse&& parse, std::string_view text, const std::string& source,
                                                     const network_read_options& options);

[[nodiscard]] fit_statistics statistics_of_property(std::string value, const network_structure& structure,
                                                    const std::string& source);

template <class Parse>
model_document read_keeping_statistics(Parse&& parse, std::string_view text, const std::string& source,
                                       const network_read_options& options) {
  std::map<std::string, std::string> properties;
  auto reading = options;
  reading.properties = &properties;
  const auto network = parse(text, source, reading);
  model_document document{network.structure(), network.tables()};
  if (const auto kept = properties.find(statistics_property); kept != properties.end()) {
    document.statistics = statistics_of_property(kept->second, document.structure, source);
  }
  return document;
}

}  // namespace pgm::detail
