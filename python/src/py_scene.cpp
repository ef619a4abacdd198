// Scenes (asperity/scene.hpp, scene_curves.hpp): a scene file, its curves served from a table.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>


#include "bindings.hpp"
#include "helpers.hpp"
#include "paths.hpp"
#include "asperity/scene.hpp"
#include "asperity/scene_curves.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

void bind_scene(py::module_& m) {
  // ---- scenes (asperity/scene.hpp, scene_curves.hpp) ----
  py::class_<SceneCurve>(m, "SceneCurve", "One curve a scene asks for.")
      .def_readonly("name", &SceneCurve::name)
      .def_readonly("distribution", &SceneCurve::distribution)
      .def_readonly("side", &SceneCurve::side)
      .def_readonly("shape", &SceneCurve::shape)
      .def_readonly("twice_orders", &SceneCurve::twice_orders)
      .def_readonly("by_load", &SceneCurve::by_load, "The range is of X_3/2, not of separation.")
      .def_readonly("range_min", &SceneCurve::range_min)
      .def_readonly("range_max", &SceneCurve::range_max)
      .def_readonly("max_rel_error", &SceneCurve::max_rel_error)
      .def_readonly("line", &SceneCurve::line, "Where the curve starts in the file.");
  py::class_<Scene>(m, "Scene", "The few curves one program needs (docs/scenes.md).")
      .def_readonly("name", &Scene::name)
      .def_property_readonly("source", [](const Scene& scene) { return path_text(scene.source); })
      .def_readonly("memory_budget_bytes", &Scene::memory_budget_bytes)
      .def_readonly("curves", &Scene::curves);
  py::class_<SceneCurveView>(m, "SceneCurveView", "A scene's curve served from a table.")
      .def_readonly("spec", &SceneCurveView::spec)
      .def_readonly("curve", &SceneCurveView::curve)
      .def_readonly("separation_min", &SceneCurveView::separation_min)
      .def_readonly("separation_max", &SceneCurveView::separation_max)
      .def_readonly("error_bound", &SceneCurveView::error_bound, "The table's error bound for these orders here.");
  m.def("read_scene_file", [](const PathName& path) { return read_scene_file(to_path(path.object)); }, "path"_a,
        "Reads a scene file (TOML); asperity.Error names the file, the line and the key.");
  m.def("parse_scene", &parse_scene, "text"_a, "source"_a = "<string>", "A scene from TOML text.");
  m.def("serve_scene", &serve_scene, "table"_a, "scene"_a,
        "The scene's curves from a table (a scene table, or any full table such as the default).");
  m.def(
      "separation_at_load",
      [](const Curve& curve, const ArrayLike& load) {
        return map_scalar(load.object, "load", [&](double x) { return separation_at_load(curve, x); });
      },
      "curve"_a, "load"_a, "The separation where X_3/2 = load (NaN if not reached).");
  m.def("quantity_twice_order", &quantity_twice_order, "quantity"_a,
        "twice_order of a quantity's integral: count 0, stiffness 1, area 2, load 3, F2 4, F5/2 5; -1 otherwise.");
}

}  // namespace asperity::python
