#pragma once
/// \file
/// Everything pgm offers in one include. Include the module headers directly for faster
/// builds; docs/api.md lists which header gives what.

#include "pgm/core/assert.hpp"
#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/variable.hpp"
#include "pgm/data/csv.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/inference/sampling.hpp"
#include "pgm/io/bif.hpp"
#include "pgm/io/cpt_csv.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/learn/estimate.hpp"
#include "pgm/learn/fit.hpp"
#include "pgm/learn/parameter_prior.hpp"
#include "pgm/learn/sufficient_statistics.hpp"
