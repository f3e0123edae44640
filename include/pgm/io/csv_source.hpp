#pragma once
/// \file
/// A CSV input as a family source (pgm/learn/family_source.hpp): its families are counted as
/// the file streams by (count_csv), never held in memory, with the records split over the
/// processes of `group` (pgm::processes() under mpirun), every one of which opened the
/// same file. The group's first process gets the counts; the others count their part.

#include <string>
#include <vector>

#include "pgm/core/process_group.hpp"
#include "pgm/io/csv_counts.hpp"

namespace pgm {

class csv_source {
 public:
  explicit csv_source(csv_reader& input, process_group& group = lone_process()) : input_(&input), group_(&group) {}

  [[nodiscard]] std::vector<std::string> columns() const { return input_->header(); }
  [[nodiscard]] std::string name() const { return input_->source(); }
  [[nodiscard]] bool holds_counts() const noexcept { return group_->rank() == 0; }
  [[nodiscard]] process_group& group() const noexcept { return *group_; }

  /// Reads the rest of the input: a source counts once.
  [[nodiscard]] family_counts count(const family_count_request& request) {
    return count_csv(*input_, request, *group_);
  }

 private:
  csv_reader* input_;
  process_group* group_;
};

}  // namespace pgm
