#pragma once
/// \file
/// The task simulators and the data they produce.
/// Every header of pgm/sim/ in one include; target pgm::core.

#include "pgm/sim/agreement.hpp"
#include "pgm/sim/analytic.hpp"
#include "pgm/sim/analytic_probability.hpp"
#include "pgm/sim/calibrate.hpp"
#include "pgm/sim/container.hpp"
#include "pgm/sim/distribution.hpp"
#include "pgm/sim/random.hpp"
#include "pgm/sim/registry.hpp"
#include "pgm/sim/run.hpp"
#include "pgm/sim/simulator.hpp"
#include "pgm/sim/simulator_concept.hpp"
#include "pgm/sim/task.hpp"
#include "pgm/sim/task_episodes.hpp"
#include "pgm/sim/task_file.hpp"
#include "pgm/sim/task_lookup.hpp"
#include "pgm/sim/task_variant.hpp"
