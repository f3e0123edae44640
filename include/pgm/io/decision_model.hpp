#pragma once
/// \file
/// A network read for decisions, with its success event settled: named by the user, else by a
/// JSON model's `"metadata": {"success": "onTop2=1"}`, else the default (the unique outcome
/// with a state "1"). `pgm predict`, `pgm prevent` and the Python `pgm.read_network` read
/// models this way.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "pgm/core/bayesian_network.hpp"
#include "pgm/core/compilation.hpp"
#include "pgm/core/error.hpp"
#include "pgm/core/file.hpp"
#include "pgm/core/success_event.hpp"
#include "pgm/io/network_file.hpp"

namespace pgm {

struct decision_model {
  bayesian_network network;
  success_event success;
};

/// A .json model's `/metadata/success` text, if it has one (a .bif file has none). The model
/// itself is read elsewhere; this looks only at the metadata. Throws data_error when the entry
/// is not a string.
[[nodiscard]] PGM_DECL std::optional<std::string> read_success_metadata(const std::filesystem::path& path);

/// The success event: `given` ("onTop2=1") if not empty, else `metadata` if any, else
/// default_success_event. Throws model_error for an event the network does not have.
[[nodiscard]] PGM_DECL success_event choose_success_event(const bayesian_network& network, std::string_view given,
                                                          const std::optional<std::string>& metadata);

/// Reads a network of any format (pgm/io/network_file.hpp) and settles its success event (see
/// choose_success_event).
[[nodiscard]] PGM_DECL decision_model read_decision_model(const std::filesystem::path& path,
                                                          std::string_view success_text,
                                                          const network_read_options& options = {});

}  // namespace pgm

#if !defined(PGM_SEPARATE_COMPILATION)
#include "pgm/io/impl/decision_model.ipp"
#endif
