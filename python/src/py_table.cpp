// asperity.CurveSet and asperity.Table (asperity/table.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "helpers.hpp"
#include "paths.hpp"
#include "asperity/table.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

void bind_table(py::module_& m) {
  // ---- tables (asperity/table.hpp) ----
  py::class_<CurveSet>(m, "CurveSet", "One (distribution, side) group of a table file.")
      .def_readonly("distribution", &CurveSet::distribution)
      .def_readonly("side", &CurveSet::side)
      .def_property_readonly("shapes", [](const CurveSet& set) { return to_array(set.shapes); },
                             "The grid shapes (ascending; a few run past the served range).")
      .def_readonly("shape_min", &CurveSet::shape_min, "The smallest shape served.")
      .def_readonly("shape_max", &CurveSet::shape_max, "The largest shape served.")
      .def_property_readonly(
          "max_rel_error",
          [](const CurveSet& set) {
            py::array_t<double> out = to_array(set.max_rel_error);
            if (!set.max_rel_error.empty()) out.resize({static_cast<py::ssize_t>(set.shapes.size()), py::ssize_t(order_count)});
            return out;
          },
          "The generator's measured error per [shape, twice_order].")
      .def("__repr__", [](const CurveSet& set) {
        return std::string("<asperity.CurveSet ") + to_string(set.distribution) + " " + to_string(set.side) + ", " +
               std::to_string(set.shapes.size()) + " shapes>";
      });

  py::class_<Table>(m, "Table",
                    "A loaded table file: its curve sets, and curves resolved from them. Opening validates "
                    "everything and raises asperity.Error naming the file and the problem.")
      .def_static("open", [](const PathName& path) { return Table::open(to_path(path.object)); }, "path"_a,
                  "Opens and validates a table file (HDF5).")
      .def_static("open_default", &Table::open_default,
                  "The default table: $ASPERITY_TABLE if set, else the one installed with the library\n"
                  "(share/asperity/asperity-default.h5), else the build tree's. The error names every place looked at.")
      .def_static("default_path", [] { return path_text(Table::default_path()); },
                  "The file open_default() would open; raises asperity.Error naming every place looked at.")
      .def_static("default_search_paths", [] {
                    py::list paths;
                    for (const std::string& path : Table::default_search_paths()) paths.append(path_text(path));
                    return paths;
                  },
                  "Where default_path() looks, in order ($ASPERITY_TABLE alone when it is set).")
      .def(
          "curve",
          [](const Table& table, const DistributionName& distribution, const SideName& side, std::optional<double> shape,
             unsigned order_mask, const std::optional<CurveOptions>& options) {
            const Distribution d = to_distribution(distribution.object);
            if (!shape && d == Distribution::weibull) throw py::value_error("a Weibull curve needs its shape");
            if (options) return table.curve(d, to_side(side.object), shape.value_or(2.0), order_mask, *options);
            return table.curve(d, to_side(side.object), shape.value_or(2.0), order_mask);
          },
          "distribution"_a, "side"_a = "tail", "shape"_a = py::none(), "order_mask"_a = Curve::all_orders,
          py::kw_only(), "options"_a = py::none(),
          "The curve of a distribution ('weibull' or 'gaussian'), a side ('tail' or 'bounded') and a Weibull\n"
          "shape (ignored for the Gaussian). A shape between grid nodes is resolved here, once. order_mask\n"
          "(bit 1 << twice_order) keeps only the orders needed (less memory; NaN for the others). options: a\n"
          "CurveOptions for the lookup grid (None: the table's, 1e-13 over the whole range or a scene table's).\n"
          "Raises asperity.Error for a shape outside the table, a missing set or bad options.")
      .def(
          "direct_curve",
          [](const Table& table, const DistributionName& distribution, const SideName& side, std::optional<double> shape,
             unsigned order_mask) {
            const Distribution d = to_distribution(distribution.object);
            if (!shape && d == Distribution::weibull) throw py::value_error("a Weibull curve needs its shape");
            return table.direct_curve(d, to_side(side.object), shape.value_or(2.0), order_mask);
          },
          "distribution"_a, "side"_a = "tail", "shape"_a = py::none(), "order_mask"_a = Curve::all_orders,
          "The same curve as curve() answered from the table's shape nodes directly, without a lookup grid:\n"
          "made in microseconds where curve() between grid nodes takes 2-60 ms, each query about a microsecond\n"
          "instead of nanoseconds, the same answers within curve()'s grid tolerance (2e-13 of ln X). For many\n"
          "distinct shapes with a few queries each; curve() for many queries at one shape.")
      .def_property_readonly(
          "sets",
          [](const py::object& self) {
            py::list sets;  // views into the table (the knots are not copied), which they keep alive
            for (const CurveSet& set : self.cast<const Table&>().data().sets)
              sets.append(py::cast(&set, py::return_value_policy::reference_internal, self));
            return sets;
          },
          "The (distribution, side) groups of the file.")
      .def_property_readonly("generator", [](const Table& table) { return table.data().generator; })
      .def_property_readonly("generator_options", [](const Table& table) { return table.data().generator_options; })
      .def_property_readonly("exact_shapes", [](const Table& table) { return table.data().exact_shapes; },
                             "True for a scene table: it serves only its own shapes.")
      .def("__repr__", [](const Table& table) {
        return "<asperity.Table " + std::to_string(table.data().sets.size()) + " curve sets>";
      });
}

}  // namespace asperity::python
