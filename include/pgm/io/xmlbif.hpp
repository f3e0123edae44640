#pragma once
/// \file
/// XMLBIF 0.3, the XML exchange format of pgmpy and aGrUM (and JavaBayes, Weka). Names and
/// states are XML text, so any name survives; pgm writes a variable's interval edges and
/// semantic tags as `<PROPERTY>key = value</PROPERTY>` elements, which pgmpy keeps as node
/// attributes and pgm reads back. Each `<TABLE>` lists, per configuration of the `<GIVEN>`
/// parents (the last parent changing fastest), the child's probabilities, as pgmpy writes it.
///
/// An influence diagram is XMLBIF as aGrUM's BIFXML writes one: a `<VARIABLE TYPE="decision">`
/// has OUTCOMEs (its actions) and a DEFINITION whose GIVENs are what is known when it is taken,
/// with no TABLE; a `<VARIABLE TYPE="utility">` has no OUTCOME (aGrUM's dummy one is ignored)
/// and a DEFINITION whose TABLE holds one value per configuration of its GIVENs.
///
/// Compiled into the library (src/lib/io/xmlbif.cpp, pgm::pgm) so that the XML parser
/// (pugixml) stays out of the headers. Errors name the file, line and column.

#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/influence_diagram.hpp"
#include "pgm/io/read_options.hpp"

namespace pgm {

/// Parses XMLBIF text; `source` names it in error messages (parse_error, model_error).
[[nodiscard]] bayesian_network parse_xmlbif(std::string_view text, const std::string& source,
                                            const network_read_options& options = {});

[[nodiscard]] bayesian_network read_xmlbif(const std::filesystem::path& path, const network_read_options& options = {});

struct xmlbif_write_options {
  /// Write interval edges and semantic tags as `<PROPERTY>` elements.
  bool properties = true;
  std::string network_name = "unknown";
  /// pgm's network-level properties, written `<PROPERTY>pgm.KEY = VALUE</PROPERTY>` in <NETWORK>.
  std::vector<std::pair<std::string, std::string>> network_properties;
};

/// Writes XMLBIF; throws model_error (before writing anything) for a tag that holds '=',
/// which pgmpy's property reader splits at.
void write_xmlbif(const bayesian_network& network, std::ostream& out, const xmlbif_write_options& options = {});

[[nodiscard]] std::string to_xmlbif(const bayesian_network& network, const xmlbif_write_options& options = {});

/// Writes an XMLBIF file atomically.
void write_xmlbif(const bayesian_network& network, const std::filesystem::path& path,
                  const xmlbif_write_options& options = {});

/// Reads an influence diagram; errors (parse_error) name the file, line and column: a utility
/// with children, a decision with a table, a cycle, a node without its definition.
[[nodiscard]] influence_diagram parse_xmlbif_influence_diagram(std::string_view text, const std::string& source);
[[nodiscard]] influence_diagram read_xmlbif_influence_diagram(const std::filesystem::path& path);

void write_xmlbif(const influence_diagram& diagram, std::ostream& out, const xmlbif_write_options& options = {});
[[nodiscard]] std::string to_xmlbif(const influence_diagram& diagram, const xmlbif_write_options& options = {});

}  // namespace pgm
