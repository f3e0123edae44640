// pgm's collective steps on MPI_COMM_WORLD. Byte counts travel as MPI_UINT64_T and bytes in
// pieces of at most INT_MAX, since MPI counts are int.

#include "mpi/mpi_processes.hpp"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>
#include <vector>

namespace pgm::mpi {
namespace {

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

constexpr std::size_t piece = INT_MAX;

class world_group final : public process_group {
 public:
  world_group() {
    int rank = 0;
    int size = 1;
    check(MPI_Comm_rank(MPI_COMM_WORLD, &rank), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &size), "MPI_Comm_size");
    rank_ = static_cast<std::size_t>(rank);
    size_ = static_cast<std::size_t>(size);
  }
  [[nodiscard]] std::size_t rank() const noexcept override { return rank_; }
  [[nodiscard]] std::size_t size() const noexcept override { return size_; }

  [[nodiscard]] std::uint64_t smallest(std::uint64_t value) override {
    std::uint64_t result = value;
    check(MPI_Allreduce(&value, &result, 1, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
    return result;
  }

  [[nodiscard]] std::string broadcast(std::string bytes, std::size_t root) override {
    std::uint64_t length = bytes.size();
    const int from = static_cast<int>(root);
    check(MPI_Bcast(&length, 1, MPI_UINT64_T, from, MPI_COMM_WORLD), "MPI_Bcast");
    bytes.resize(length);
    for (std::size_t at = 0; at < length; at += piece) {
      const auto n = static_cast<int>(std::min<std::size_t>(piece, length - at));
      check(MPI_Bcast(bytes.data() + at, n, MPI_CHAR, from, MPI_COMM_WORLD), "MPI_Bcast");
    }
    return bytes;
  }

  // Point to point from each rank to 0, in rank order: the parts need not fit one int count.
  [[nodiscard]] std::vector<std::string> gather(std::string_view bytes) override {
    const std::uint64_t length = bytes.size();
    std::vector<std::uint64_t> lengths(rank_ == 0 ? size_ : 0);
    check(MPI_Gather(&length, 1, MPI_UINT64_T, lengths.data(), 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Gather");
    if (rank_ != 0) {
      for (std::size_t at = 0; at < length; at += piece) {
        const auto n = static_cast<int>(std::min<std::size_t>(piece, length - at));
        check(MPI_Send(bytes.data() + at, n, MPI_CHAR, 0, 0, MPI_COMM_WORLD), "MPI_Send");
      }
      return {};
    }
    std::vector<std::string> parts(size_);
    parts[0] = std::string(bytes);
    for (std::size_t r = 1; r < size_; ++r) {
      parts[r].resize(lengths[r]);
      for (std::size_t at = 0; at < lengths[r]; at += piece) {
        const auto n = static_cast<int>(std::min<std::size_t>(piece, lengths[r] - at));
        check(MPI_Recv(parts[r].data() + at, n, MPI_CHAR, static_cast<int>(r), 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
              "MPI_Recv");
      }
    }
    return parts;
  }

  void sum(std::span<std::uint64_t> values) override {
    for (std::size_t at = 0; at < values.size(); at += piece) {
      const auto n = static_cast<int>(std::min<std::size_t>(piece, values.size() - at));
      check(MPI_Allreduce(MPI_IN_PLACE, values.data() + at, n, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
    }
  }

 private:
  std::size_t rank_ = 0;
  std::size_t size_ = 1;
};

}  // namespace

mpi_session::mpi_session(int& argc, char**& argv) {
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  group_ = std::make_unique<world_group>();
  install_processes(group_.get());
}

mpi_session::~mpi_session() {
  install_processes(nullptr);
  MPI_Finalize();
}

process_group& mpi_session::group() noexcept { return *group_; }

}  // namespace pgm::mpi
