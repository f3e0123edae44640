// pgm._core's dynamic networks (dynamic.hpp).

#include "dynamic.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>
#include <vector>

#include "network_handle.hpp"
#include "pgm/core/dynamic_network.hpp"
#include "pgm/core/file.hpp"
#include "pgm/io/json_model.hpp"
#include "pgm/io/network_file.hpp"

namespace py = pybind11;

namespace pgm::python {
namespace {

/// The dynamic network of a pgm JSON model of "kind": "dynamic", or None for another model.
py::object read_dynamic_json(const std::filesystem::path& path) {
  const auto text = read_model_text(path);
  if (declared_model_kind(text) != "dynamic") return py::none();
  return py::cast(parse_dynamic_json(text, path.string()));
}

}  // namespace

void add_dynamic(py::module_& m) {
  py::class_<dynamic_network>(m, "DynamicNetwork")
      .def_property_readonly("variables",
                             [](const dynamic_network& d) {
                               std::vector<std::string> names;
                               for (const auto& v : d.variables()) names.push_back(v.name());
                               return names;
                             })
      .def("states", [](const dynamic_network& d, const std::string& name) { return d.initial().at(name).states(); })
      .def_property_readonly("initial",
                             [](const dynamic_network& d) {
                               return network_handle{d.initial(), {}, {}, {}};
                             })
      .def_property_readonly("transition_edges",
                             [](const dynamic_network& d) {
                               std::vector<std::pair<std::string, std::string>> edges;
                               for (const auto& e : d.transition_structure().edges()) edges.emplace_back(e.from, e.to);
                               return edges;
                             })
      .def("unroll",
           [](const dynamic_network& d, std::size_t slices) {
             return network_handle{d.unroll(slices), {}, {}, {}};
           })
      .def("to_json", [](const dynamic_network& d) { return to_json(d).dump(2); })
      .def("write", [](const dynamic_network& d, const std::filesystem::path& path) {
        const auto text = to_json(d).dump(2) + "\n";
        write_file_atomically(path, [&](std::ostream& out) { out << text; });
      });
  m.def("read_dynamic_json", &read_dynamic_json);
}

}  // namespace pgm::python
