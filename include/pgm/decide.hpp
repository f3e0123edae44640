#pragma once
/// \file
/// Decisions from a network: predicting success and choosing the actions that prevent failure.
/// Every header of pgm/decide/ in one include; target pgm::core.

#include "pgm/decide/assignment.hpp"
#include "pgm/decide/counterfactual_success.hpp"
#include "pgm/decide/explain.hpp"
#include "pgm/decide/predict.hpp"
#include "pgm/decide/prevent.hpp"
#include "pgm/decide/prevent_by_utility.hpp"
#include "pgm/decide/prevent_over_time.hpp"
#include "pgm/decide/solve_decisions.hpp"
#include "pgm/decide/success_table.hpp"
#include "pgm/decide/table_slice.hpp"
