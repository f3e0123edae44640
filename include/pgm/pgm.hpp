#pragma once
/// \file
/// Everything pgm offers in one include. Include the module headers directly for faster
/// builds; docs/api.md lists which header gives what. The optional adapters
/// (pgm/adapters/eigen.hpp) are not included: they need their library on the include path.

#include "pgm/causal.hpp"
#include "pgm/core.hpp"
#include "pgm/data.hpp"
#include "pgm/decide.hpp"
#include "pgm/eval.hpp"
#include "pgm/inference.hpp"
#include "pgm/io.hpp"
#include "pgm/learn.hpp"
#include "pgm/pipeline.hpp"
#include "pgm/sim.hpp"
#include "pgm/transfer.hpp"
