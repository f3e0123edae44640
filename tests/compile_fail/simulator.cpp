// A back-end without `static constexpr name` is not a Simulator: register_simulator refuses it.
#include <pgm/sim/registry.hpp>

struct nameless_backend {
#ifdef PGM_CONTROL
  static constexpr std::string_view name = "nameless";
#endif
  explicit nameless_backend(const pgm::sim::task_definition&) {}
  void run(std::span<double>, pgm::sim::random_stream&) {}
};

static const pgm::sim::register_simulator<nameless_backend> registered;
