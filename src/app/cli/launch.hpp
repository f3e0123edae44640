#pragma once
// Whether a launcher (mpirun, srun) started this process as one of several, read from the
// environment it sets, so that a program started on its own never initializes MPI.

#include <charconv>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string_view>

namespace pgm::cli {

struct launch {
  /// A launcher's variables are set: the program is one process of a parallel job.
  bool launched = false;
  /// The job's processes, when the launcher says (Open MPI, PMI, srun); PMIx alone does not.
  std::optional<std::size_t> processes;
};

/// Reads Open MPI's OMPI_COMM_WORLD_SIZE, PMI's PMI_SIZE, PMIx's PMIX_RANK and srun's
/// SLURM_PROCID with SLURM_STEP_NUM_TASKS (a batch script has SLURM_PROCID too, but no step).
[[nodiscard]] inline launch read_launch(const std::function<const char*(const char*)>& get = std::getenv) {
  auto number = [&](const char* name) -> std::optional<std::size_t> {
    const char* text = get(name);
    if (!text) return std::nullopt;
    const std::string_view view(text);
    std::size_t value = 0;
    const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), value);
    if (error != std::errc() || end != view.data() + view.size()) return std::nullopt;
    return value;
  };
  for (const char* size : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (auto n = number(size)) return {true, n};
  }
  if (get("SLURM_PROCID")) {
    if (auto n = number("SLURM_STEP_NUM_TASKS")) return {true, n};
  }
  if (get("PMIX_RANK")) return {true, std::nullopt};
  return {};
}

}  // namespace pgm::cli
