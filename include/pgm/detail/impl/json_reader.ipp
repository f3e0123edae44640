#pragma once
// The definitions of pgm/detail/json_reader.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/detail/json_reader.hpp"

namespace pgm::detail {

PGM_DECL const nlohmann::json& json_reader::member(const nlohmann::json& object, const std::string& path,
                                                   const char* key) const {
  if (!object.is_object()) fail(path, "expected an object");
  const auto it = object.find(key);
  if (it == object.end()) fail(path, std::string("the key '") + key + "' is missing");
  return *it;
}

PGM_DECL void json_reader::only_keys(const nlohmann::json& object, const std::string& path,
                                     const std::vector<std::string_view>& known) const {
  if (!object.is_object()) return;
  for (const auto& item : object.items()) {
    const auto& key = item.key();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    const auto near = text::closest_name(key, known);
    fail(path + "/" + key, "unknown key '" + key + "'" + (near ? "; did you mean '" + *near + "'?" : "") +
                               " (the keys here: " + text::join(known) + ")");
  }
}

PGM_DECL std::vector<std::string> json_reader::strings(const nlohmann::json& value, const std::string& path) const {
  std::vector<std::string> result;
  std::size_t i = 0;
  for (const auto& item : array(value, path)) result.push_back(string(item, path + "/" + std::to_string(i++)));
  return result;
}

PGM_DECL std::vector<double> json_reader::numbers(const nlohmann::json& value, const std::string& path) const {
  std::vector<double> result;
  std::size_t i = 0;
  for (const auto& item : array(value, path)) result.push_back(number(item, path + "/" + std::to_string(i++)));
  return result;
}

PGM_DECL variable json_reader::read_variable(const nlohmann::json& value, const std::string& path) const {
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

PGM_DECL nlohmann::json json_reader::parse(std::string_view text) const {
  check_limits(text);
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

PGM_DECL void json_reader::check_format(const nlohmann::json& document, const char* expected) const {
  const auto format = string(member(document, "", "format"), "/format");
  if (format != expected) {
    fail("/format", "expected \"" + std::string(expected) + "\", found \"" + format + "\"");
  }
  const auto version = number(member(document, "", "version"), "/version");
  if (version != 1) fail("/version", "this pgm reads version 1, the file is version " + text::format_double(version));
}

PGM_DECL void json_reader::check_limits(std::string_view text) const {
  // The values counted so far in each open array (an object's are not: none is large).
  std::vector<std::size_t> open_arrays;
  std::vector<bool> is_array;
  std::size_t values = 0, line = 1, column = 1;
  bool in_string = false, escaped = false;
  const auto refuse = [&](const std::string& what) { throw parse_error(source_, line, column, what); };
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
      if (is_array.size() == json_max_depth) {
        refuse("arrays and objects nested deeper than " + std::to_string(json_max_depth) +
               " levels, pgm's limit (docs/limits.md)");
      }
      is_array.push_back(c == '[');
      if (c == '[') open_arrays.push_back(1);
      ++values;
    } else if ((c == ']' || c == '}') && !is_array.empty()) {
      if (is_array.back()) open_arrays.pop_back();
      is_array.pop_back();
    } else if (c == ',') {
      ++values;
      if (!is_array.empty() && is_array.back() && ++open_arrays.back() > max_table_cells) {
        refuse("an array of more than " + std::to_string(max_table_cells) +
               " values, pgm's limit of cells per table (docs/limits.md)");
      }
    }
    if (values > json_max_values) {
      refuse("more than " + std::to_string(json_max_values) + " values, pgm's limit of a JSON file (docs/limits.md)");
    }
    if (c == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
}

}  // namespace pgm::detail
