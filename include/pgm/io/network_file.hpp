#pragma once
/// \file
/// Reading and writing a network by file extension: `.bif` or `.json`.

#include <filesystem>
#include <string>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/json_model.hpp"

namespace pgm {

enum class network_format { bif, json };

/// The format a path's extension names; throws io_error for any other extension.
[[nodiscard]] inline network_format format_of(const std::filesystem::path& path) {
  const auto extension = path.extension().string();
  if (extension == ".bif") return network_format::bif;
  if (extension == ".json") return network_format::json;
  throw io_error("'" + path.string() + "': expected a .bif or .json file");
}

/// A fitted network from a .bif or .json file.
[[nodiscard]] inline bayesian_network read_network(const std::filesystem::path& path) {
  if (format_of(path) == network_format::bif) return read_bif(path);
  try {
    return read_model_json(path).network();
  } catch (const model_error& e) {
    throw model_error("'" + path.string() + "': " + e.what());
  }
}

/// Writes a network as .bif or .json, atomically.
inline void write_network(const bayesian_network& network, const std::filesystem::path& path) {
  if (format_of(path) == network_format::bif) {
    write_bif(network, path);
  } else {
    write_model_json(to_json(network), path);
  }
}

}  // namespace pgm
