// pgm's JSON model as a registered format (the reader and writer are pgm/io/json_model.hpp's).

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
                return (options.statistics ? to_json(network, *options.statistics) : to_json(network)).dump(2) + "\n";
              }};
}

}  // namespace pgm
