#pragma once
// Internal: not part of pgm's API, may change without notice.
//
// `json_reader`, the base of every JSON file reader (models, discretizations, tasks,
// scenarios): parsing with file:line:column for syntax errors, and typed access to members
// that names the JSON path of anything amiss ("tasks/x.json: /variables/2/kind: expected a
// string").

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/variable.hpp"

namespace pgm::detail {

/// Reads typed values out of a parsed document, naming the JSON path of anything amiss.
class json_reader {
 public:
  explicit json_reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw data_error(source_ + ": " + (path.empty() ? "/" : path) + ": " + what);
  }

  PGM_DECL const nlohmann::json& member(const nlohmann::json& object, const std::string& path, const char* key) const;
  /// Refuses a key of `object` that is none of `known`, naming it, the known key it was most
  /// likely meant to be and all of them: a misspelt optional key ("repetitons") would otherwise
  /// be ignored without a word.
  PGM_DECL void only_keys(const nlohmann::json& object, const std::string& path,
                          const std::vector<std::string_view>& known) const;
  const nlohmann::json* optional_member(const nlohmann::json& object, const char* key) const {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }
  std::string string(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, "expected a string");
    return value.get<std::string>();
  }
  double number(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, "expected a number");
    return value.get<double>();
  }
  const nlohmann::json& array(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_array()) fail(path, "expected an array");
    return value;
  }
  PGM_DECL std::vector<std::string> strings(const nlohmann::json& value, const std::string& path) const;
  PGM_DECL std::vector<double> numbers(const nlohmann::json& value, const std::string& path) const;

  PGM_DECL variable read_variable(const nlohmann::json& value, const std::string& path) const;

  PGM_DECL nlohmann::json parse(std::string_view text) const;

  PGM_DECL void check_format(const nlohmann::json& document, const char* expected) const;

 private:
  /// Refuses, before the document is built, nesting deeper than json_max_depth, an array of more
  /// than max_table_cells values and a document of more than json_max_values, naming where the
  /// limit is passed: a document costs some 16 bytes a value, 8 times its text at worst
  /// (strings are skipped; syntax is left to the parser).
  PGM_DECL void check_limits(std::string_view text) const;

  std::string source_;
};

}  // namespace pgm::detail

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/detail/impl/json_reader.ipp"
#endif
