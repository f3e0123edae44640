#pragma once
/// \file
/// The paper's experiment: scenarios, repetitions, metrics, result tables, plots and reports (reads and writes files).
/// Every header of pgm/eval/ in one include; target pgm::pgm.

#include "pgm/eval/cached_source.hpp"
#include "pgm/eval/disk_cache.hpp"
#include "pgm/eval/experiment.hpp"
#include "pgm/eval/family_data.hpp"
#include "pgm/eval/headline.hpp"
#include "pgm/eval/metrics.hpp"
#include "pgm/eval/plot.hpp"
#include "pgm/eval/report_writer.hpp"
#include "pgm/eval/result_tables.hpp"
#include "pgm/eval/run_scenarios.hpp"
#include "pgm/eval/scenario.hpp"
#include "pgm/eval/scenario_catalog.hpp"
#include "pgm/eval/simulated_source.hpp"
