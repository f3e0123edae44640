#pragma once
/// \file
/// Readers and writers (compiled into libpgm): CSV, BIF, XMLBIF, NET, JSON models, gzip, DOT.
/// Every header of pgm/io/ in one include; target pgm::pgm.

#include "pgm/io/bif.hpp"
#include "pgm/io/cpt_csv.hpp"
#include "pgm/io/csv.hpp"
#include "pgm/io/csv_counts.hpp"
#include "pgm/io/csv_source.hpp"
#include "pgm/io/dataset_file.hpp"
#include "pgm/io/decision_model.hpp"
#include "pgm/io/dot.hpp"
#include "pgm/io/gzip.hpp"
#include "pgm/io/influence_file.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/net.hpp"
#include "pgm/io/network_file.hpp"
#include "pgm/io/network_format.hpp"
#include "pgm/io/policy_csv.hpp"
#include "pgm/io/query_batch.hpp"
#include "pgm/io/read_options.hpp"
#include "pgm/io/statistics_json.hpp"
#include "pgm/io/structural_file.hpp"
#include "pgm/io/uai.hpp"
#include "pgm/io/xmlbif.hpp"
