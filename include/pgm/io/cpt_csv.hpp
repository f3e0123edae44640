#pragma once
/// \file
/// A table as CSV, one row per parent configuration and child state:
/// `parent_1,…,parent_k,child,probability`, configurations in table order.

#include <filesystem>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/io/csv.hpp"

namespace pgm {

/// Writes `table`; `value_header` names the last column.
PGM_DECL void write_cpt_csv(const cpt<double>& table, std::ostream& out,
                            const std::string& value_header = "probability");

inline void write_cpt_csv(const cpt<double>& table, const std::filesystem::path& path,
                          const std::string& value_header = "probability") {
  pgm::write_file_atomically(path, [&](std::ostream& out) { write_cpt_csv(table, out, value_header); });
}

/// Reads a table written by write_cpt_csv for known variables. Every configuration and state
/// must appear exactly once.
[[nodiscard]] PGM_DECL cpt<double> parse_cpt_csv(std::string_view text, const std::string& source,
                                                 const variable& child, const std::vector<variable>& parents);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/cpt_csv.ipp"
#endif
