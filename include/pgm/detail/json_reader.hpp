#pragma once
// Internal: not part of pgm's API, may change without notice.
//
// `json_reader`, the base of every JSON file reader (models, discretizations, tasks,
// scenarios): parsing with file:line:column for syntax errors, and typed access to members
// that names the JSON path of anything amiss ("tasks/x.json: /variables/2/kind: expected a
// string").

#include <algorithm>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgm/core/error.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/detail/text.hpp"

namespace pgm::detail {

/// Reads typed values out of a parsed document, naming the JSON path of anything amiss.
class json_reader {
 public:
  explicit json_reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw data_error(source_ + ": " + (path.empty() ? "/" : path) + ": " + what);
  }

  const nlohmann::json& member(const nlohmann::json& object, const std::string& path, const char* key) const {
    if (!object.is_object()) fail(path, "expected an object");
    const auto it = object.find(key);
    if (it == object.end()) fail(path, std::string("the key '") + key + "' is missing");
    return *it;
  }
  /// Refuses a key of `object` that is none of `known`, naming it, the known key it was most
  /// likely meant to be and all of them: a misspelt optional key ("repetitons") would otherwise
  /// be ignored without a word.
  void only_keys(const nlohmann::json& object, const std::string& path,
                 std::initializer_list<std::string_view> known) const {
    if (!object.is_object()) return;
    for (const auto& item : object.items()) {
      const auto& key = item.key();
      if (std::find(known.begin(), known.end(), key) != known.end()) continue;
      const auto near = closest_name(key, known);
      fail(path + "/" + key, "unknown key '" + key + "'" + (near ? "; did you mean '" + *near + "'?" : "") +
                                 " (the keys here: " + join(known) + ")");
    }
  }
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
  std::vector<std::string> strings(const nlohmann::json& value, const std::string& path) const {
    std::vector<std::string> result;
    std::size_t i = 0;
    for (const auto& item : array(value, path)) result.push_back(string(item, path + "/" + std::to_string(i++)));
    return result;
  }
  std::vector<double> numbers(const nlohmann::json& value, const std::string& path) const {
    std::vector<double> result;
    std::size_t i = 0;
    for (const auto& item : array(value, path)) result.push_back(number(item, path + "/" + std::to_string(i++)));
    return result;
  }

  variable read_variable(const nlohmann::json& value, const std::string& path) const {
    const auto name = string(member(value, path, "name"), path + "/name");
    only_keys(value, path, {"name", "states", "edges", "tags"});
    auto states = strings(member(value, path, "states"), path + "/states");
    semantic_tags tags;
    if (const auto* t = optional_member(value, "tags")) {
      const auto tags_path = path + "/tags";
      if (!t->is_object()) fail(tags_path, "expected an object");
      only_keys(*t, tags_path, {"quantity", "unit", "role"});
      if (const auto* q = optional_member(*t, "quantity")) tags.quantity = string(*q, tags_path + "/quantity");
      if (const auto* u = optional_member(*t, "unit")) tags.unit = string(*u, tags_path + "/unit");
      if (const auto* r = optional_member(*t, "role")) tags.role = string(*r, tags_path + "/role");
    }
    try {
      variable result(name, std::move(states), std::move(tags));
      if (const auto* e = optional_member(value, "edges")) result.set_edges(numbers(*e, path + "/edges"));
      return result;
    } catch (const model_error& e) {
      fail(path, e.what());
    }
  }

  nlohmann::json parse(std::string_view text) const {
    check_depth(text);
    try {
      return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
      // e.byte is 1-based; turn it into a line and column.
      std::size_t line = 1;
      std::size_t column = 1;
      for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
          ++line;
          column = 1;
        } else {
          ++column;
        }
      }
      // "[json.exception.parse_error.101] parse error at line 3, column 2: syntax error while
      // parsing value - invalid literal; last read: '0,<U+000A> N'": the place is ours, the
      // reason and what was read are kept.
      std::string what = e.what();
      if (const auto at = what.find(", column "); at != std::string::npos) {
        if (const auto colon = what.find(": ", at); colon != std::string::npos) what = what.substr(colon + 2);
      } else if (const auto bracket = what.find("] "); bracket != std::string::npos) {
        what = what.substr(bracket + 2);
      }
      throw parse_error(source_, line, column, "invalid JSON: " + what);
    } catch (const nlohmann::json::out_of_range& e) {
      // A number too large for a double ("1e999"): nlohmann gives no position, so find the
      // number it names in the text.
      const std::string what = e.what();
      const auto open = what.find('\''), close = what.rfind('\'');
      const auto number =
          open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : std::string();
      const auto at = number.empty() ? std::string_view::npos : text.find(number);
      std::size_t line = 1, column = 1;
      for (std::size_t i = 0; at != std::string_view::npos && i < at; ++i) {
        if (text[i] == '\n') {
          ++line;
          column = 1;
        } else {
          ++column;
        }
      }
      throw parse_error(source_, line, column, "number out of range: '" + number + "'");
    }
  }

  void check_format(const nlohmann::json& document, const char* expected) const {
    const auto format = string(member(document, "", "format"), "/format");
    if (format != expected) {
      fail("/format", "expected \"" + std::string(expected) + "\", found \"" + format + "\"");
    }
    const auto version = number(member(document, "", "version"), "/version");
    if (version != 1) fail("/version", "this pgm reads version 1, the file is version " + format_double(version));
  }

 private:
  /// Refuses nesting deeper than json_max_depth before the document is built, naming where
  /// the limit is passed (strings are skipped; syntax is left to the parser).
  void check_depth(std::string_view text) const {
    std::size_t depth = 0, line = 1, column = 1;
    bool in_string = false, escaped = false;
    for (const char c : text) {
      if (in_string) {
        if (escaped) {
          escaped = false;
        } else if (c == '\\') {
          escaped = true;
        } else if (c == '"') {
          in_string = false;
        }
      } else if (c == '"') {
        in_string = true;
      } else if (c == '[' || c == '{') {
        if (++depth > json_max_depth) {
          throw parse_error(source_, line, column,
                            "arrays and objects nested deeper than " + std::to_string(json_max_depth) +
                                " levels, pgm's limit (docs/limits.md)");
        }
      } else if ((c == ']' || c == '}') && depth > 0) {
        --depth;
      }
      if (c == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
  }

  std::string source_;
};

}  // namespace pgm::detail
