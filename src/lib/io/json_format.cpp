// pgm's JSON model as a registered format (the reader and writer are pgm/io/json_model.hpp's).

#include <sstream>

#include "io/builtin_formats.hpp"
#include "pgm/io/json_model.hpp"

namespace pgm {

network_format_codec detail::json_format() {
  return {.name = "json",
          .title = "pgm JSON",
          .extensions = {".json"},
          .read = [](std::string_view text, const std::string& source,
                     const network_read_options&) { return parse_model_json(text, source); },
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
