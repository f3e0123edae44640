#pragma once
/// \file
/// Data sets in memory: columns of states, missing values, discretization.
/// Every header of pgm/data/ in one include; target pgm::core.

#include "pgm/data/bin_columns.hpp"
#include "pgm/data/dataset.hpp"
#include "pgm/data/discretizer.hpp"
#include "pgm/data/episodes.hpp"
#include "pgm/data/family_counts.hpp"
#include "pgm/data/missing.hpp"
#include "pgm/data/state_order.hpp"
#include "pgm/data/sufficient_statistics.hpp"
