#pragma once
/// \file
/// Eigen views of pgm's tables, for linear algebra on them without a copy. Optional: the
/// library itself does not need Eigen; a project that includes this header finds Eigen
/// (`find_package(Eigen3 3.3 NO_MODULE)`) and links `Eigen3::Eigen` beside `pgm::pgm`.

#include <Eigen/Core>

#include "pgm/core/cpt.hpp"

namespace pgm {

/// A read-only J × |Val(Pa)| view of a table: column u is the distribution of the child given
/// parent configuration u (the table's own configuration-major layout is Eigen's column-major
/// one). Valid while the table lives and is not assigned to.
template <class T>
[[nodiscard]] Eigen::Map<const Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>> as_eigen(const cpt<T>& table) {
  return {table.values().data(), static_cast<Eigen::Index>(table.child_cardinality()),
          static_cast<Eigen::Index>(table.configurations())};
}

}  // namespace pgm
