#pragma once
/// \file
/// Hugin's NET format, read and written by Hugin, bnlearn (read.net, write.net), aGrUM and
/// SamIam. A `node` lists its `states` as quoted strings; a `potential ( child | parents )`
/// holds `data`, nested parentheses with the first parent outermost and the child's states
/// innermost. pgm writes a variable's interval edges and semantic tags as node attributes
/// `pgm_edges`, `pgm_quantity`, `pgm_unit` and `pgm_role`, which Hugin keeps and others ignore.
///
/// Names must be NET identifiers (a letter or '_', then letters, digits and '_'): a variable
/// named otherwise is refused when writing, with the reason. Continuous, decision and utility
/// nodes and object-oriented `class` files are refused when reading. Compiled into the library
/// (src/lib/io/net.cpp, pgm::pgm); errors name the file, line and column.

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/io/read_options.hpp"

namespace pgm {

/// Parses Hugin NET text; `source` names it in error messages (parse_error, model_error).
[[nodiscard]] bayesian_network parse_net(std::string_view text, const std::string& source,
                                         const network_read_options& options = {});

[[nodiscard]] bayesian_network read_net(const std::filesystem::path& path, const network_read_options& options = {});

struct net_write_options {
  /// Write interval edges and semantic tags as `pgm_*` node attributes.
  bool properties = true;
  /// pgm's network-level properties, written `pgm_KEY = "VALUE";` in the net block.
  std::vector<std::pair<std::string, std::string>> network_properties;
};

/// Why `name` cannot be a NET node name, or nothing.
[[nodiscard]] std::optional<std::string> net_name_problem(std::string_view name);

/// Writes NET; throws model_error (before writing anything) for a variable name that is not a
/// NET identifier or a state or tag holding a line break.
void write_net(const bayesian_network& network, std::ostream& out, const net_write_options& options = {});

[[nodiscard]] std::string to_net(const bayesian_network& network, const net_write_options& options = {});

/// Writes a NET file atomically.
void write_net(const bayesian_network& network, const std::filesystem::path& path,
               const net_write_options& options = {});

}  // namespace pgm
