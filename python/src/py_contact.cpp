// The physical quantities of a curve (asperity/contact.hpp): SurfaceScales, contact_at and the
// separation conventions.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>


#include "bindings.hpp"
#include "helpers.hpp"
#include "asperity/contact.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

void bind_contact(py::module_& m) {
  // ---- the physical quantities (asperity/contact.hpp) ----
  py::class_<SurfaceScales>(m, "SurfaceScales",
                            "The four scales contact_at multiplies a curve's integrals by: N summits of radius R, height\n"
                            "scale sigma_s (Gaussian: rms sigma), modulus E*, in any consistent units, with separations\n"
                            "in units of sigma_s (the lower level; Surface is its former name). A physical surface in SI\n"
                            "units, with its distribution, density and nominal area, for ContactModel: RoughSurface.")
      .def(py::init([](double summit_count, double summit_radius, double height_scale, double contact_modulus) {
             return SurfaceScales{summit_count, summit_radius, height_scale, contact_modulus};
           }),
           "summit_count"_a = 1.0, "summit_radius"_a = 1.0, "height_scale"_a = 1.0, "contact_modulus"_a = 1.0)
      .def_readwrite("summit_count", &SurfaceScales::summit_count)
      .def_readwrite("summit_radius", &SurfaceScales::summit_radius)
      .def_readwrite("height_scale", &SurfaceScales::height_scale)
      .def_readwrite("contact_modulus", &SurfaceScales::contact_modulus)
      .def("__repr__", [](const SurfaceScales& s) {
        return py::str("SurfaceScales(summit_count={!r}, summit_radius={!r}, height_scale={!r}, contact_modulus={!r})")
            .format(s.summit_count, s.summit_radius, s.height_scale, s.contact_modulus);
      });

  m.def(
      "contact_at",
      // the surface by value: a copy, read without the GIL while another thread may set its fields
      [](const Curve& curve, SurfaceScales surface, const ArrayLike& separation) -> ContactStateRecord {
        return {make_record(contact_state_type,
                           map_records<5>(separation.object, "separation", [&](double s, double** out, std::size_t i) {
                             ContactState state{nan, nan, nan, nan, nan};
                             contact_at(curve, surface, s, state);
                             out[0][i] = state.count;
                             out[1][i] = state.area;
                             out[2][i] = state.load;
                             out[3][i] = state.stiffness;
                             out[4][i] = state.stiffness_ratio;
                           }))};
      },
      "curve"_a, "surface"_a, "separation"_a,
      "Count, area, load, stiffness and stiffness/load ratio at the separations (a number or an array),\n"
      "as a ContactState of floats or arrays. NaN for a non-physical surface or a NaN/infinite separation.");
  m.def(
      "standardized_from_origin",
      [](const Curve& curve, const ArrayLike& separation) {
        return map_scalar(separation.object, "separation", [&](double s) { return standardized_from_origin(curve, s); });
      },
      "curve"_a, "separation"_a,
      "(s - mu_a)/c_a: the separation from the mean summit height in rms units (the GW/McCool convention).");
  m.def(
      "origin_from_standardized",
      [](const Curve& curve, const ArrayLike& standardized) {
        return map_scalar(standardized.object, "standardized", [&](double t) { return origin_from_standardized(curve, t); });
      },
      "curve"_a, "standardized"_a, "The inverse of standardized_from_origin.");
}

}  // namespace asperity::python
