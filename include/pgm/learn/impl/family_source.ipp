#pragma once
// The definitions of pgm/learn/family_source.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/learn/family_source.hpp"

namespace pgm::detail {

PGM_DECL discrete_column recode_to(const discrete_column& column, const variable& known, const std::string& source) {
  if (column.var().states() == known.states()) return column.with_variable(known);
  std::vector<std::uint32_t> index_of;
  for (const auto& label : column.var().states()) {
    const auto found = known.find_state(label);
    if (!found) {
      throw data_error((source.empty() ? std::string() : source + ": ") + "column '" + column.name() +
                       "' holds the value '" + text::printable(label) + "', which is not a state of '" + known.name() +
                       "' {" + text::list_for_message(known.states()) + "}");
    }
    index_of.push_back(static_cast<std::uint32_t>(found->value()));
  }
  auto codes = make_code_vector(known.cardinality(), column.size());
  std::visit(
      [&](const auto& from, auto& to) {
        using from_code = typename std::decay_t<decltype(from)>::value_type;
        using to_code = typename std::decay_t<decltype(to)>::value_type;
        for (std::size_t row = 0; row < from.size(); ++row) {
          to[row] = from[row] == missing_code<from_code> && column.missing() != 0
                        ? missing_code<to_code>
                        : static_cast<to_code>(index_of[from[row]]);
        }
      },
      column.codes(), codes);
  return discrete_column(known, std::move(codes), std::in_place, column.missing());
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL family_counts dataset_source::count(const family_count_request& request) const {
  family_counts result;
  auto read = this->read(request, result);
  if (request.missing.policy != missing_policy::available) read = without_missing(std::move(read), request, result);
  for (const auto& name : read.names()) result.variables.push_back(read.discrete(name).var());
  const count_options counting{.threads = request.threads};
  for (const auto& family : request.families) {
    result.families.push_back(count_family(read, family.child, family.parents, counting));
  }
  return result;
}

PGM_DECL dataset dataset_source::read(const family_count_request& request, family_counts& result) const {
  dataset read(data_->source());
  for (const auto& column : data_->names()) {
    if (std::find(request.columns.begin(), request.columns.end(), column) == request.columns.end()) continue;
    read.add(read_column(column, request, result));
  }
  for (const auto& column : request.columns) static_cast<void>(data_->at(column));  // each exists
  result.rows = read.rows();
  return read;
}

PGM_DECL data_column dataset_source::read_column(const std::string& name, const family_count_request& request,
                                                 family_counts& result) const {
  const auto& column = data_->at(name);
  if (const auto binned = request.intervals.find(name); binned != request.intervals.end()) {
    if (const auto* values = std::get_if<continuous_column>(&column)) {
      const auto& edges = binned->second.edges();
      std::size_t outside = 0;
      for (double v : values->values()) outside += v < edges.front() || v > edges.back();  // NaN never is
      result.outside[name] = outside;
      return discretize(*values, binned->second);
    }
    return detail::recode_to(std::get<discrete_column>(column), binned->second, data_->source());
  }
  if (const auto known = request.variables.find(name); known != request.variables.end()) {
    return detail::recode_to(data_->discrete(name), known->second, data_->source());
  }
  return data_->discrete(name);
}

PGM_DECL dataset dataset_source::without_missing(dataset read, const family_count_request& request,
                                                 family_counts& result) const {
  std::vector<std::size_t> kept;
  kept.reserve(read.rows());
  for (std::size_t row = 0; row < read.rows(); ++row) {
    bool present = true;
    for (const auto& name : read.names()) {
      if (!read.discrete(name).is_missing(row)) continue;
      if (request.missing.policy == missing_policy::error) {
        throw data_error((data_->source().empty() ? std::string() : data_->source() + ": ") + "row " +
                         std::to_string(row + 1) + ": the value of '" + name + "' is missing");
      }
      present = false;
      break;
    }
    if (present) kept.push_back(row);
  }
  if (kept.size() == read.rows()) return read;
  result.dropped = read.rows() - kept.size();
  result.rows = kept.size();
  return read.select_rows(kept);
}

}  // namespace pgm
