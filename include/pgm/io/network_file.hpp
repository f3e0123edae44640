#pragma once
/// \file
/// Reading and writing a network in any registered format (pgm/io/network_format.hpp), chosen by
/// the file's extension, compressed with gzip or not. Every command that reads a model reads it
/// through `read_model` or `read_network`, so every command reads every format.
/// docs/formats.md says what each format carries.
///
/// Compiled into the library (src/lib/io/network_file.cpp, pgm::pgm).

#include <filesystem>
#include <string>
#include <string_view>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_format.hpp"
#include "pgm/io/read_options.hpp"

namespace pgm {

/// A model file's text, inflated when it is gzip data (known by its magic bytes, which a .gz
/// name requires); compressed or not, at most max_file_bytes.
[[nodiscard]] std::string read_model_text(const std::filesystem::path& path);

/// A model from text in `format`: a structure, with tables unless the format holds a structure
/// alone (pgm's JSON), and the kept counts; `source` names it in error messages.
[[nodiscard]] model_document parse_model(std::string_view text, const network_format& format, const std::string& source,
                                         const network_read_options& options = {});

/// A fitted network from text in `format`; `source` names it in error messages.
[[nodiscard]] bayesian_network parse_network(std::string_view text, const network_format& format,
                                             const std::string& source, const network_read_options& options = {});

/// A model file of any format, compressed with gzip or not: a structure, with tables unless it
/// is a JSON structure file (BIF, XMLBIF and NET files always hold tables), and the counts of
/// pgm fit --keep-counts when the file keeps them.
[[nodiscard]] model_document read_model(const std::filesystem::path& path, const network_read_options& options = {});

/// A fitted network from a file of any supported format, compressed with gzip or not.
[[nodiscard]] bayesian_network read_network(const std::filesystem::path& path,
                                            const network_read_options& options = {});

/// The text of `network` in `format`; throws model_error for what the format cannot hold.
[[nodiscard]] std::string to_text(const bayesian_network& network, const network_format& format,
                                  const network_write_options& options = {});

/// Writes a network in `format`, atomically; nothing is written if the format cannot hold it.
void write_network(const bayesian_network& network, const std::filesystem::path& path, const network_format& format,
                   const network_write_options& options = {});

/// Writes a network in the format of the path's extension, atomically.
void write_network(const bayesian_network& network, const std::filesystem::path& path,
                   const network_write_options& options = {});

}  // namespace pgm
