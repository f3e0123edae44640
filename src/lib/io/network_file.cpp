// Reading and writing a network through the format registry, and the kept counts of the
// formats that keep them in a network-level property.

#include "pgm/io/network_file.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "io/builtin_formats.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/detail/base64.hpp"
#include "pgm/detail/json_reader.hpp"
#include "pgm/io/gzip.hpp"
#include "pgm/io/statistics_json.hpp"

namespace pgm {

std::string read_model_text(const std::filesystem::path& path) {
  auto bytes = read_file(path);
  auto extension = path.extension().string();
  std::ranges::transform(extension, extension.begin(),
                         [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (is_gzip(bytes) || extension == ".gz") return inflate_gzip(bytes, path.string(), max_file_bytes);
  return bytes;
}

model_document parse_model(std::string_view text, const network_format& format, const std::string& source,
                           const network_read_options& options) {
  return format.codec().read(text, source, options);
}

bayesian_network parse_network(std::string_view text, const network_format& format, const std::string& source,
                               const network_read_options& options) {
  auto document = parse_model(text, format, source, options);
  if (!document.tables) {
    throw model_error("'" + source + "': the model has a structure but no tables; fit it first");
  }
  return bayesian_network(std::move(document.structure), std::move(*document.tables));
}

model_document read_model(const std::filesystem::path& path, const network_read_options& options) {
  const auto format = format_to_read(path);
  return parse_model(read_model_text(path), format, path.string(), options);
}

bayesian_network read_network(const std::filesystem::path& path, const network_read_options& options) {
  const auto format = format_to_read(path);
  return parse_network(read_model_text(path), format, path.string(), options);
}

std::string to_text(const bayesian_network& network, const network_format& format,
                    const network_write_options& options) {
  return format.codec().write(network, options);
}

void write_network(const bayesian_network& network, const std::filesystem::path& path, const network_format& format,
                   const network_write_options& options) {
  if (const auto& stream = format.codec().write_to) {
    write_file_atomically(
        path, [&](std::ostream& out) { stream(out, network, options); }, options.before_replacing);
    return;
  }
  const auto text = to_text(network, format, options);
  write_file_atomically(
      path, [&](std::ostream& out) { out << text; }, options.before_replacing);
}

void write_network(const bayesian_network& network, const std::filesystem::path& path,
                   const network_write_options& options) {
  write_network(network, path, format_of(path), options);
}

namespace detail {

std::vector<std::pair<std::string, std::string>> kept_properties(const network_write_options& options) {
  if (!options.statistics) return {};
  auto text = base64_encode(to_json(*options.statistics).dump());
  text.erase(std::find(text.begin(), text.end(), '='), text.end());
  return {{statistics_property, std::move(text)}};
}

fit_statistics statistics_of_property(std::string value, const network_structure& structure,
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

}  // namespace pgm
