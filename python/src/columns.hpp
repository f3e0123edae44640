#pragma once
// Data frames in and out of the library: each column crosses as a NumPy buffer (integer values,
// integer codes with their labels, or doubles), never as one Python object per row. The pandas
// side (which dtype becomes which kind) is in pgm/_frame.py.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pgm/core/network_structure.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/family_counts.hpp"
#include "pgm/learn/count_values.hpp"

namespace pgm::python {

/// One column's buffer, read while holding the GIL and used without it.
struct column_buffer {
  std::string name;
  /// "int": integer values, whose states are the values seen; "coded": integer codes into
  /// `labels` (-1 for a missing value); "float": numbers, a continuous column.
  std::string kind;
  const void* data = nullptr;
  std::size_t size = 0;
  char type = 'i';  ///< NumPy's kind: 'i' signed, 'u' unsigned, 'f' floating
  std::size_t item_size = 0;
  /// Items from one value to the next: an "int" column may be a strided view (a column of a
  /// frame made from a row-major matrix); the other kinds are contiguous.
  std::ptrdiff_t stride = 1;
  std::vector<std::string> labels;
};

/// The columns pgm/_frame.py hands over as (name, kind, array, labels) tuples. `keep` holds the
/// arrays the buffers point into; it must outlive them.
[[nodiscard]] std::vector<column_buffer> read_column_buffers(const pybind11::list& columns,
                                                             std::vector<pybind11::array>& keep);

/// The data set of these columns, in this order, named `source` in messages. Needs no GIL.
[[nodiscard]] dataset make_dataset(const std::vector<column_buffer>& columns, const std::string& source);

/// NumPy columns as a family source (pgm/learn/family_source.hpp). Columns of small
/// non-negative integers are counted straight from their buffers (pgm/learn/count_values.hpp)
/// when nothing is asked of them (no known variables, no binning); otherwise, or when one is
/// not such a column, the source builds a data set once and counts as `dataset_source` does.
/// Needs no GIL; the buffers must outlive it.
class numpy_source {
 public:
  numpy_source(const std::vector<column_buffer>& columns, std::string name)
      : columns_(&columns), name_(std::move(name)) {}

  [[nodiscard]] std::vector<std::string> columns() const;
  [[nodiscard]] std::string name() const { return name_; }
  [[nodiscard]] static bool holds_counts() noexcept { return true; }
  [[nodiscard]] family_counts count(const family_count_request& request);
  /// The requested columns as a data set, missing values kept: what EM reads (row_source).
  [[nodiscard]] dataset read(const family_count_request& request, family_counts& result);

 private:
  [[nodiscard]] std::optional<family_counts> count_by_value(const family_count_request& request) const;

  const std::vector<column_buffer>* columns_;
  std::string name_;
  std::optional<dataset> data_;
};

/// Throws data_error naming the first missing column and listing `available`, unless every
/// name of `wanted` is among them.
void require_columns(const std::vector<std::string>& wanted, const std::vector<std::string>& available,
                     const std::string& source);

/// The data's column under the model's variable: each value's label becomes that state's code.
/// Throws data_error for a value that is no state of the model's.
[[nodiscard]] discrete_column with_model_states(const discrete_column& column, const variable& model);

/// A data set's columns for pgm/_frame.py: (name, "coded", codes, states) for a discrete
/// column, (name, "float", values, None) for a continuous one; each array a new NumPy buffer.
[[nodiscard]] pybind11::list dataset_columns(const dataset& data);

}  // namespace pgm::python
