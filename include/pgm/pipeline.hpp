#pragma once
/// \file
/// Every header of pgm/pipeline/ in one include; target pgm::core. The pipeline sits above
/// learning and transfer and joins them: data in, counts, priors (transferred ones too), tables.

#include "pgm/pipeline/dynamic_fit_pipeline.hpp"
#include "pgm/pipeline/fit_pipeline.hpp"
