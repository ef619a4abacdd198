// The Python module asperity._asperity (imported by python/asperity/__init__.py): a thin
// binding of the C++ API with the same names, one binding file per part (bindings.hpp), called
// here in order. Arrays go through the vectorized batch path (arrays.hpp); asperity::Error
// becomes asperity.Error with the library's message.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "asperity/curve.hpp"
#include "asperity/integrals.hpp"
#include "asperity/topography/surface_formats.hpp"

namespace py = pybind11;

namespace asperity::python {
namespace {

// asperity.topography: the measured-surface library (include/asperity/topography/*.hpp) with the
// same names. Height maps carry their heights as a (ny, nx) float64 numpy array (a view into
// the map, x fastest); the long computations (reading, fits, the bootstrap, the analysis, the
// synthetic fields) run without the GIL, on copies taken while it is held: whatever another
// Python thread does to an object meanwhile (its properties, a map's heights through the view),
// the computation never reads memory that is being changed. The two calls that change a map
// (subtract_plane, to_weibull_marginal) keep the GIL: one pass over the heights, atomic for
// every other Python thread.
void bind_topography(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "topography",
      ("From a measured surface to its contact curves (docs/surfaces.md): reading height maps\n(" +
       asperity::topography::surface_format_list() +
       "), leveling, height statistics and spectral moments, summits, the three\n"
       "height models fitted with their evidence (Anderson-Darling and Kolmogorov-Smirnov by parametric\n"
       "bootstrap, AIC, a verdict), the contact curves of each fit, and reports. SI units throughout.")
          .c_str());
  bind_height_map(m);
  bind_statistics(m);
  bind_summits(m);
  bind_fits(m);
  bind_assessment(m);
  bind_synthetic(m);
  bind_exact_contact(m);
  bind_persson_contact(m);
  bind_contact_comparison(m);
  bind_analysis_options(m);
  bind_report(m);
}

void bind(py::module_& m) {
  m.doc() = "asperity: Greenwood-Williamson asperity integrals from precomputed tables (the C++ library's binding).";
  m.attr("__version__") = ASPERITY_VERSION_STRING;
  m.attr("ORDER_COUNT") = order_count;
  m.attr("ALL_ORDERS") = Curve::all_orders;
  bind_errors(m);
  bind_records(m);
  bind_vocabulary(m);
  bind_curve(m);
  bind_table(m);
  bind_contact(m);
  bind_surface(m);
  bind_fe_export(m);
  bind_inverse(m);
  bind_contact_model(m);
  bind_contact_curves(m);
  bind_persson(m);
  bind_scene(m);
  // the former names (deprecated, kept for existing code): Surface is SurfaceScales (contact_at's four
  // scales), PhysicalSurface is RoughSurface (ContactModel's surface in SI units)
  m.attr("Surface") = m.attr("SurfaceScales");
  m.attr("PhysicalSurface") = m.attr("RoughSurface");
  bind_topography(m);
  bind_law_curves(m);
  bind_output(m);
}

}  // namespace
}  // namespace asperity::python

PYBIND11_MODULE(_asperity, m) {
  // Types made while the module calls itself "asperity" are named asperity.Curve, ... in
  // signatures, messages and help(), as users import them.
  const py::object name = m.attr("__name__");
  m.attr("__name__") = "asperity";
  asperity::python::bind(m);
  m.attr("__name__") = name;
}
