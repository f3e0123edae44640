#pragma once
/// \file
/// Prior transfer between tasks: the paper's Direct-, Cross- and Minimal-Replacement (eq. 7-9) and their seam.
/// Every header of pgm/transfer/ in one include; target pgm::core.

#include "pgm/transfer/dynamic_transfer.hpp"
#include "pgm/transfer/network_transfer.hpp"
#include "pgm/transfer/prior_transfer.hpp"
#include "pgm/transfer/prior_weight.hpp"
#include "pgm/transfer/propose.hpp"
#include "pgm/transfer/registry.hpp"
#include "pgm/transfer/replacement.hpp"
#include "pgm/transfer/replacement_plan.hpp"
#include "pgm/transfer/state_map.hpp"
#include "pgm/transfer/transfer_problem.hpp"
#include "pgm/transfer/transfer_settings.hpp"
