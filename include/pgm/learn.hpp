#pragma once
/// \file
/// Learning from data: counts, parameter estimation (MLE, Bayesian, EM), structure (PC, hill climbing).
/// Every header of pgm/learn/ in one include; target pgm::core.

#include "pgm/learn/background_knowledge.hpp"
#include "pgm/learn/bootstrap.hpp"
#include "pgm/learn/count_values.hpp"
#include "pgm/learn/cpdag.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/estimator_choice.hpp"
#include "pgm/learn/expectation_maximization.hpp"
#include "pgm/learn/family_score_cache.hpp"
#include "pgm/learn/family_source.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/fit_pipeline.hpp"
#include "pgm/learn/fit_statistics.hpp"
#include "pgm/learn/hill_climbing.hpp"
#include "pgm/learn/independence_test.hpp"
#include "pgm/learn/learn_structure.hpp"
#include "pgm/learn/log_gamma_ratio.hpp"
#include "pgm/learn/network_score.hpp"
#include "pgm/learn/orientation.hpp"
#include "pgm/learn/parameter_prior.hpp"
#include "pgm/learn/pc.hpp"
#include "pgm/learn/score.hpp"
#include "pgm/learn/structural_hamming_distance.hpp"
#include "pgm/learn/structure_prior.hpp"
#include "pgm/learn/sufficient_statistics.hpp"
