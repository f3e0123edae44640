// A strategy that changes itself when asked for a prior is not a PriorTransfer (one object
// serves many nodes and threads): register_transfer refuses it.
#include <pgm/transfer/registry.hpp>

struct counting_strategy {
  [[nodiscard]] static std::string_view name() { return "counting"; }
#ifdef PGM_CONTROL
  pgm::transferred_prior operator()(const pgm::transfer_problem&) const;
#else
  pgm::transferred_prior operator()(const pgm::transfer_problem&);
#endif
};

static const pgm::register_transfer<counting_strategy> registered;
