#pragma once
/// \file
/// Causal questions on a network: d-separation, adjustment sets, interventions (do).
/// Every header of pgm/causal/ in one include; target pgm::core.

#include "pgm/causal/adjustment.hpp"
#include "pgm/causal/counterfactual.hpp"
#include "pgm/causal/d_separation.hpp"
#include "pgm/causal/dag_check.hpp"
#include "pgm/causal/intervention.hpp"
#include "pgm/causal/probability_of_causation.hpp"
