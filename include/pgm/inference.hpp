#pragma once
/// \file
/// Inference engines behind one seam: exact (variable elimination, junction tree) and sampling.
/// Every header of pgm/inference/ in one include; target pgm::core.

#include "pgm/inference/approximate_engines.hpp"
#include "pgm/inference/belief_propagation.hpp"
#include "pgm/inference/dynamic_inference.hpp"
#include "pgm/inference/engine_registry.hpp"
#include "pgm/inference/evidence_reduction.hpp"
#include "pgm/inference/evidence_scope.hpp"
#include "pgm/inference/exact.hpp"
#include "pgm/inference/factor.hpp"
#include "pgm/inference/factor_gibbs.hpp"
#include "pgm/inference/gibbs_sampling.hpp"
#include "pgm/inference/inference_engine.hpp"
#include "pgm/inference/junction_tree.hpp"
#include "pgm/inference/junction_tree_engine.hpp"
#include "pgm/inference/likelihood_weighting.hpp"
#include "pgm/inference/posterior_table.hpp"
#include "pgm/inference/propagation.hpp"
#include "pgm/inference/query.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/inference/sampling_options.hpp"
#include "pgm/inference/semiring.hpp"
#include "pgm/inference/solve.hpp"
#include "pgm/inference/table_walk.hpp"
#include "pgm/inference/triangulation.hpp"
#include "pgm/inference/variable_elimination.hpp"
