#pragma once
// The MPI process group (built when PGM_WITH_MPI is on): MPI is initialized for the life of an
// mpi_session, and its MPI_COMM_WORLD serves as pgm's process group.

#include <memory>

#include "pgm/core/process_group.hpp"

namespace pgm::mpi {

/// Initializes MPI (only the calling thread makes MPI calls) and installs MPI_COMM_WORLD as
/// pgm::processes(); finalizes and uninstalls it when destroyed.
class mpi_session {
 public:
  mpi_session(int& argc, char**& argv);
  ~mpi_session();
  mpi_session(const mpi_session&) = delete;
  mpi_session& operator=(const mpi_session&) = delete;

  [[nodiscard]] process_group& group() noexcept;

 private:
  std::unique_ptr<process_group> group_;
};

}  // namespace pgm::mpi
