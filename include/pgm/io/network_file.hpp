#pragma once
/// \file
/// Reading and writing a network in any supported format, chosen by the file's extension:
/// BIF (`.bif`), XMLBIF (`.xml`, `.xmlbif`, `.bifxml`), Hugin NET (`.net`) and pgm's JSON model
/// (`.json`). Every command that reads a model reads it through `read_model` or `read_network`,
/// so every command reads every format. docs/formats.md says what each format carries.

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/detail/base64.hpp"
#include "pgm/detail/file.hpp"
#include "pgm/detail/json_reader.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/gzip.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/net.hpp"
#include "pgm/io/read_options.hpp"
#include "pgm/io/xmlbif.hpp"

namespace pgm {

enum class network_format { bif, json, xmlbif, net };

namespace detail {

struct network_format_entry {
  network_format format;
  std::string_view name;  // for --to
  std::string_view extensions[3];
};

inline constexpr std::array<network_format_entry, 4> network_formats{{
    {network_format::bif, "bif", {".bif"}},
    {network_format::xmlbif, "xmlbif", {".xml", ".xmlbif", ".bifxml"}},
    {network_format::net, "net", {".net"}},
    {network_format::json, "json", {".json"}},
}};

}  // namespace detail

/// Every extension a network file may have, in the order the formats are listed.
[[nodiscard]] inline std::vector<std::string> network_file_extensions() {
  std::vector<std::string> extensions;
  for (const auto& entry : detail::network_formats) {
    for (const auto extension : entry.extensions) {
      if (!extension.empty()) extensions.emplace_back(extension);
    }
  }
  return extensions;
}

/// The format's name, as `--to` takes it: bif, xmlbif, net or json.
[[nodiscard]] inline std::string_view name_of(network_format format) {
  for (const auto& entry : detail::network_formats) {
    if (entry.format == format) return entry.name;
  }
  return {};
}

/// The formats' names (bif, xmlbif, net, json), for messages and the command line's allowed
/// values.
[[nodiscard]] inline std::vector<std::string> known_network_formats() {
  std::vector<std::string> names;
  for (const auto& entry : detail::network_formats) names.emplace_back(entry.name);
  return names;
}

/// The format a name (bif, xmlbif, net, json) stands for; throws unknown_name for any other.
[[nodiscard]] inline network_format network_format_named(std::string_view name) {
  for (const auto& entry : detail::network_formats) {
    if (entry.name == name) return entry.format;
  }
  throw unknown_name("network format", std::string(name), known_network_formats());
}

namespace detail {

/// A path's extension in lower case (".BIF" -> ".bif").
[[nodiscard]] inline std::string lowercase_extension(const std::filesystem::path& path) {
  auto extension = path.extension().string();
  for (auto& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace detail

/// The format a path's extension names (case-insensitive), or nothing.
[[nodiscard]] inline std::optional<network_format> find_format_of(const std::filesystem::path& path) {
  const auto extension = detail::lowercase_extension(path);
  for (const auto& entry : detail::network_formats) {
    for (const auto known : entry.extensions) {
      if (!known.empty() && extension == known) return entry.format;
    }
  }
  return std::nullopt;
}

/// The format a path's extension names; throws io_error listing the supported extensions.
[[nodiscard]] inline network_format format_of(const std::filesystem::path& path) {
  if (const auto format = find_format_of(path)) return *format;
  throw io_error("'" + path.string() + "': not a network file; expected one of " +
                 detail::join(network_file_extensions()) + " (BIF, XMLBIF, Hugin NET, pgm JSON)");
}

/// A fitted network from text in `format`; `source` names it in error messages.
[[nodiscard]] inline bayesian_network parse_network(std::string_view text, network_format format,
                                                    const std::string& source,
                                                    const network_read_options& options = {}) {
  switch (format) {
    case network_format::bif:
      return parse_bif(text, source, options);
    case network_format::xmlbif:
      return parse_xmlbif(text, source, options);
    case network_format::net:
      return parse_net(text, source, options);
    case network_format::json:
      break;
  }
  try {
    return parse_model_json(text, source).network();
  } catch (const model_error& e) {
    throw model_error("'" + source + "': " + e.what());
  }
}

/// The format of a model file to read: its extension's, or for a compressed file (`.bif.gz`,
/// `.xml.gz`, `.net.gz`, `.json.gz`) that of the name without `.gz`.
[[nodiscard]] inline network_format format_to_read(const std::filesystem::path& path) {
  const auto format = find_format_of(detail::lowercase_extension(path) == ".gz" ? path.stem() : path);
  if (format) return *format;
  throw io_error("'" + path.string() + "': not a network file; expected one of " +
                 detail::join(network_file_extensions()) +
                 " (BIF, XMLBIF, Hugin NET, pgm JSON), or one of them compressed with gzip (.bif.gz, ...)");
}

namespace detail {

/// A model file's text, inflated when it is gzip data (known by its magic bytes, which a .gz
/// name requires); compressed or not, at most max_file_bytes.
[[nodiscard]] inline std::string read_model_text(const std::filesystem::path& path) {
  auto bytes = read_file(path);
  if (is_gzip(bytes) || lowercase_extension(path) == ".gz") return inflate_gzip(bytes, path.string(), max_file_bytes);
  return bytes;
}

}  // namespace detail

namespace detail {

/// The property a fit's counts are kept in, in BIF, XMLBIF and NET files: the counts as
/// pgm's JSON (pgm/io/statistics_json.hpp), compact, in base64 without its '=' padding, which
/// peers' property readers split at.
inline constexpr const char* statistics_property = "statistics";

[[nodiscard]] inline std::string statistics_property_value(const fit_statistics& statistics) {
  auto text = base64_encode(to_json(statistics).dump());
  text.erase(std::find(text.begin(), text.end(), '='), text.end());
  return text;
}

/// The counts a BIF, XMLBIF or NET file keeps in its statistics property, for `structure`.
[[nodiscard]] inline fit_statistics statistics_of_property(std::string value, const network_structure& structure,
                                                           const std::string& source) {
  value.append((4 - value.size() % 4) % 4, '=');
  const auto bytes = base64_decode(value);
  const auto document = bytes ? nlohmann::json::parse(*bytes, nullptr, false) : nlohmann::json();
  if (!bytes || document.is_discarded()) {
    throw model_error("'" + source + "': the property pgm." + statistics_property +
                      " (the counts of pgm fit --keep-counts) is damaged: not base64 of JSON");
  }
  return parse_statistics_json(json_reader(source + " (property pgm." + statistics_property + ")"), document,
                               structure);
}

}  // namespace detail

/// A model file of any format, compressed with gzip or not: a structure, with tables unless it
/// is a JSON structure file (BIF, XMLBIF and NET files always hold tables), and the counts of
/// pgm fit --keep-counts when the file keeps them.
[[nodiscard]] inline model_document read_model(const std::filesystem::path& path,
                                               const network_read_options& options = {}) {
  const auto format = format_to_read(path);
  if (format == network_format::json) return parse_model_json(detail::read_model_text(path), path.string());
  std::map<std::string, std::string> properties;
  auto reading = options;
  reading.properties = &properties;
  auto network = parse_network(detail::read_model_text(path), format, path.string(), reading);
  model_document document{network.structure(), network.tables()};
  if (const auto kept = properties.find(detail::statistics_property); kept != properties.end()) {
    document.statistics = detail::statistics_of_property(kept->second, document.structure, path.string());
  }
  return document;
}

/// A fitted network from a file of any supported format, compressed with gzip or not.
[[nodiscard]] inline bayesian_network read_network(const std::filesystem::path& path,
                                                   const network_read_options& options = {}) {
  const auto format = format_to_read(path);
  return parse_network(detail::read_model_text(path), format, path.string(), options);
}

struct network_write_options {
  /// Write interval edges and semantic tags where the format allows (all four do).
  bool properties = true;
  /// Receives a line for anything written that a peer would read differently.
  std::vector<std::string>* notes = nullptr;
  /// The counts and priors to keep with the network, for `pgm update`: under "statistics" in
  /// JSON, in a network-level property pgm.statistics elsewhere (which peers ignore).
  const fit_statistics* statistics = nullptr;
};

/// The text of `network` in `format`; throws model_error for what the format cannot hold.
[[nodiscard]] inline std::string to_text(const bayesian_network& network, network_format format,
                                         const network_write_options& options = {}) {
  std::vector<std::pair<std::string, std::string>> kept;
  if (options.statistics && format != network_format::json) {
    kept.emplace_back(detail::statistics_property, detail::statistics_property_value(*options.statistics));
  }
  switch (format) {
    case network_format::bif:
      return to_bif(network, {.properties = options.properties, .notes = options.notes, .network_properties = kept});
    case network_format::xmlbif:
      return to_xmlbif(network, {.properties = options.properties, .network_properties = kept});
    case network_format::net:
      return to_net(network, {.properties = options.properties, .network_properties = kept});
    case network_format::json:
      break;
  }
  return (options.statistics ? to_json(network, *options.statistics) : to_json(network)).dump(2) + "\n";
}

/// Writes a network in `format`, atomically; nothing is written if the format cannot hold it.
inline void write_network(const bayesian_network& network, const std::filesystem::path& path, network_format format,
                          const network_write_options& options = {}) {
  if (format == network_format::json) {
    write_model_json(options.statistics ? to_json(network, *options.statistics) : to_json(network), path);
    return;
  }
  const auto text = to_text(network, format, options);
  detail::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

/// Writes a network in the format of the path's extension, atomically.
inline void write_network(const bayesian_network& network, const std::filesystem::path& path,
                          const network_write_options& options = {}) {
  write_network(network, path, format_of(path), options);
}

}  // namespace pgm
