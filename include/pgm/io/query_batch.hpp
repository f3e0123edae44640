#pragma once
/// \file
/// Many queries in one file, answered in one process (`pgm query --queries FILE`): a CSV whose
/// header names a `query` column and optionally `evidence`, `soft`, `do` and `engine`, one query
/// per record, each field in the command line's form:
///
///     query,evidence,soft,do,engine
///     Akt,PKA=HIGH,,,
///     "Erk,Akt","PKC=LOW,Plcg=AVG",Raf=0.2:0.3:0.5,,ve
///     Erk,,,PKA=LOW,
///
/// `write_query_record` writes one output record per query, in order: a JSON object on one line
/// (JSON Lines), or a CSV row `line,query,evidence,soft,do,engine,evidence_probability,distribution`
/// whose distribution lists `state=p` for every joint state separated by `;` (the states of a
/// joint query joined by `&`, the last variable fastest). A query whose evidence is impossible
/// is answered too: P(evidence) = 0, no distribution, and (in JSON) the reason as "error".

#include <algorithm>
#include <cstddef>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/text.hpp"
#include "pgm/inference/posterior_table.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/io/csv.hpp"

namespace pgm {

/// One record of a query file.
struct query_request {
  std::size_t line = 0;
  std::vector<std::string> query;
  evidence observed;
  soft_evidence soft;
  intervention intervened;
  /// The engine named on the line; empty for the file's default.
  std::string engine;
  /// The texts as written, for the output.
  std::string query_text;
  std::string evidence_text;
  std::string soft_text;
  std::string do_text;
};

/// Reads a query file one record at a time, so that answering a long file holds one query in
/// memory, not all of them. Throws parse_error naming the line and column of a field that does
/// not parse, a header without `query` or with an unknown or repeated column, a record with too
/// many fields, or a file with no query.
class query_batch_reader {
 public:
  /// Reads the header of `text`, which must outlive the reader; `source` names it in messages.
  PGM_DECL query_batch_reader(std::string_view text, std::string source);

  /// Reads the next record into `request`; false at the end of the file.
  PGM_DECL bool next(query_request& request);

 private:
  enum class column { query, observed, soft, intervened, engine };
  detail::csv_scanner scanner_;
  std::vector<column> columns_;
  std::vector<detail::csv_field> fields_;
  std::size_t records_ = 0;
};

/// The records of a query file, all read (see query_batch_reader).
[[nodiscard]] PGM_DECL std::vector<query_request> parse_query_batch(std::string_view text, const std::string& source);

/// Writes the record of a query whose evidence is impossible: P(evidence) = 0 and `reason`.
PGM_DECL void write_impossible_record(std::ostream& out, const query_request& request, const std::string& engine,
                                      const std::string& reason, const posterior_table_options& options, bool header);

/// Writes the answer to `request` as one record (see the file comment); `header` first when
/// asked (CSV only).
PGM_DECL void write_query_record(std::ostream& out, const query_request& request, const posterior& answer,
                                 const posterior_table_options& options, bool header);

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/query_batch.ipp"
#endif
