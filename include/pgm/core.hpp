#pragma once
/// \file
/// Variables, tables, structures and networks, with the errors and limits every module shares.
/// Every header of pgm/core/ in one include; target pgm::core.

#include "pgm/core/assert.hpp"
#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/component_options.hpp"
#include "pgm/core/component_registry.hpp"
#include "pgm/core/correspondence.hpp"
#include "pgm/core/cpt.hpp"
#include "pgm/core/dag.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/factor_table.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/graphical_model.hpp"
#include "pgm/core/influence_diagram.hpp"
#include "pgm/core/limits.hpp"
#include "pgm/core/markov_network.hpp"
#include "pgm/core/mixed_radix.hpp"
#include "pgm/core/network_structure.hpp"
#include "pgm/core/process_group.hpp"
#include "pgm/core/strong_index.hpp"
#include "pgm/core/success_event.hpp"
#include "pgm/core/text.hpp"
#include "pgm/core/unknown_name.hpp"
#include "pgm/core/variable.hpp"
