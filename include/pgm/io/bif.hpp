#pragma once
/// \file
/// The Bayesian Interchange Format (BIF) that pgmpy, bnlearn and aGrUM read and write.
/// State names and their order are kept. pgm also writes a variable's interval edges and
/// semantic tags as `property` lines, which other tools ignore and pgm reads back.
///
/// Reading accepts `probability` blocks with one `(parent states) values;` line per
/// configuration, `default values;` for the rest, and `table values;` for nodes without
/// parents. (`table` for a node with parents is ordered differently by different tools, so
/// it is refused rather than guessed.)

///
/// Compiled into the library (src/lib/io/bif.cpp, pgm::pgm). Errors name the file, line and column.

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

namespace detail {

/// Why `name` cannot be written as a BIF variable or network name, or nothing. pgmpy reads
/// letters, digits, '_' and '-' everywhere (and '.' only in `variable` lines); BIF has no quoting
/// that pgmpy keeps, so nothing else can be written.
[[nodiscard]] std::optional<std::string> bif_name_problem(std::string_view text);

/// Why `state` cannot be written as a BIF state, or nothing. pgmpy splits states at spaces,
/// ',', '(' and ')' and turns '"' into a space; our reader also stops at ';', '|', '[', ']',
/// '{', '}' and comments.
[[nodiscard]] std::optional<std::string> bif_state_problem(std::string_view text);

}  // namespace detail

/// Parses BIF text; `source` names it in error messages.
[[nodiscard]] bayesian_network parse_bif(std::string_view text, const std::string& source,
                                         const network_read_options& options = {});

[[nodiscard]] bayesian_network read_bif(const std::filesystem::path& path, const network_read_options& options = {});

struct bif_write_options {
  /// Write interval edges and semantic tags as `property` lines.
  bool properties = true;
  std::string network_name = "unknown";
  /// When set, receives a line for anything written that a peer reads differently (a name
  /// with '.', which pgmpy 0.1.26 reads in `variable` lines but not in `probability` lines).
  std::vector<std::string>* notes = nullptr;
  /// pgm's network-level properties, written `property pgm.KEY = VALUE ;` in the network block
  /// (values of letters, digits, '+', '/', '=', '.', '-': base64 or numbers).
  std::vector<std::pair<std::string, std::string>> network_properties;
};

/// Writes BIF as pgmpy does: one `(parent states) probabilities;` line per configuration.
/// Throws model_error, before writing anything, for a name or state that pgmpy or bnlearn
/// could not read back (spaces, quotes, punctuation); docs/formats.md lists the rules.
void write_bif(const bayesian_network& network, std::ostream& out, const bif_write_options& options = {});

[[nodiscard]] std::string to_bif(const bayesian_network& network, const bif_write_options& options = {});

/// Writes a BIF file atomically.
void write_bif(const bayesian_network& network, const std::filesystem::path& path,
               const bif_write_options& options = {});

}  // namespace pgm
