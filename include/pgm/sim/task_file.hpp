#pragma once
/// \file
/// Reading a task file (`"format": "pgm-task"`, tasks/README.md documents it) into a
/// `task_definition`. Errors name the file and either the line and column (JSON syntax) or the
/// JSON path of the offending value ("tasks/2-stack.json: /variables/3/distribution/sd:
/// expected a positive number").

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "pgm/core/compilation.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/text.hpp"
#include "pgm/detail/json_reader.hpp"
#include "pgm/sim/distribution.hpp"
#include "pgm/sim/task.hpp"

namespace pgm::sim {

namespace detail {

class task_reader : public pgm::detail::json_reader {
 public:
  using json_reader::json_reader;

  PGM_DECL task_definition read(const nlohmann::json& doc, const std::filesystem::path& path) const;

 private:
  PGM_DECL std::string optional_string(const nlohmann::json& object, const char* key, const std::string& path,
                                       std::string fallback) const;
  PGM_DECL double optional_number(const nlohmann::json& object, const char* key, const std::string& path,
                                  double fallback) const;
  PGM_DECL double positive(const nlohmann::json& object, const char* key, const std::string& path) const;
  PGM_DECL double non_negative(const nlohmann::json& object, const char* key, const std::string& path,
                               double fallback) const;

  PGM_DECL double time_step(const nlohmann::json& object, const std::string& path, double fallback) const;

  PGM_DECL task_variable read_task_variable(const nlohmann::json& value, const std::string& path) const;

  PGM_DECL distribution read_distribution(const nlohmann::json& value, const std::string& path,
                                          const task_variable& v) const;

  PGM_DECL void require(const task_definition& task, const std::string& name, variable_kind kind,
                        const std::string& model) const;

  PGM_DECL physics_parameters read_physics(const nlohmann::json& value, const task_definition& task) const;
};

}  // namespace detail

/// Reads a task from JSON text; `source` names it in error messages ("tasks/2-stack.json").
[[nodiscard]] inline task_definition parse_task(std::string_view text, const std::string& source) {
  detail::task_reader reader(source);
  return reader.read(reader.parse(text), source);
}

/// Reads a task file. Errors name the file and the JSON path of the offending key.
[[nodiscard]] inline task_definition load_task(const std::filesystem::path& path) {
  return parse_task(pgm::read_file(path), path.string());
}

}  // namespace pgm::sim

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/sim/impl/task_file.ipp"
#endif
