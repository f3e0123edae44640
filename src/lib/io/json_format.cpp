// pgm's JSON model as a registered format (the reader and writer are pgm/io/json_model.hpp's).

#include <sstream>

#include "io/builtin_formats.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/structural_file.hpp"

namespace pgm {

network_format_codec detail::json_format() {
  return {
      .name = "json",
      .title = "pgm JSON",
      .extensions = {".json"},
      .read =
          [](std::string_view text, const std::string& source, const network_read_options& options) {
            // The token first: every network read would otherwise be parsed twice.
            if (text.find("\"structural\"") == std::string_view::npos || declared_model_kind(text) != "structural") {
              return parse_model_json(text, source);
            }
            // A structural model is read as the causal network it implies, for every command.
            const auto network = parse_structural_json(text, source).network();
            if (options.notes != nullptr) {
              options.notes->push_back("'" + source +
                                       "' holds a structural model: read as the causal network it implies");
            }
            return model_document{network.structure(), network.tables(), std::nullopt};
          },
      .write =
          [](const bayesian_network& network, const network_write_options& options) {
            std::ostringstream out;
            write_model_json(out, network, options.statistics);
            return out.str();
          },
      .write_to = [](std::ostream& out, const bayesian_network& network,
                     const network_write_options& options) { write_model_json(out, network, options.statistics); }};
}

}  // namespace pgm
