// A physical rough surface and its unit helpers (asperity/surface.hpp): RoughSurface, the contact
// modulus, the height scale from an rms, a Gaussian surface from spectral moments.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "helpers.hpp"
#include "asperity/surface.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

void bind_surface(py::module_& m) {
  // ---- physical surfaces and the contact model (surface.hpp, contact_model.hpp, inverse.hpp) ----
  py::class_<RoughSurface>(m, "RoughSurface",
                              "A physical rough surface in SI units, what ContactModel takes: Weibull summit heights "
                              "of shape a and scale sigma_s, or Gaussian (rms sigma), summit radius and density, "
                              "nominal area, contact modulus (PhysicalSurface is its former name; SurfaceScales, "
                              "formerly Surface, is the lower level's four scales for contact_at).")
      .def(py::init([](const DistributionName& distribution, const std::optional<SideName>& side,
                       std::optional<double> given_shape, std::optional<double> height_scale,
                       std::optional<double> summit_radius, std::optional<double> summit_density,
                       std::optional<double> nominal_area, std::optional<double> contact_modulus,
                       std::optional<double> rms) {
             RoughSurface s;
             s.distribution = to_distribution(distribution.object);
             const bool weibull = s.distribution == Distribution::weibull;
             s.side = side ? to_side(side->object) : Side::tail;  // GW's approach, as --side's default
             if (!weibull && s.side != Side::tail)
               throw py::value_error("the Gaussian has no bounded side (side='tail' or None)");
             // the Gaussian has no shape: None (or any shape) is taken, as Table.curve takes it
             if (!given_shape && weibull)
               throw py::value_error("a Weibull surface needs its shape (shape=None is for the Gaussian)");
             s.shape = weibull ? *given_shape : 2.0;
             if (height_scale && rms) throw py::value_error("give the height scale once: height_scale or rms");
             // no physical value has a default: a forgotten one is an error, not a silent 1e-4 m
             std::string missing;
             const std::pair<const char*, bool> required[] = {
                 {"height_scale (or rms)", height_scale || rms}, {"summit_radius", summit_radius.has_value()},
                 {"summit_density", summit_density.has_value()}, {"nominal_area", nominal_area.has_value()},
                 {"contact_modulus", contact_modulus.has_value()}};
             for (const auto& [name, given] : required)
               if (!given) missing += std::string(missing.empty() ? "" : ", ") + name;
             if (!missing.empty()) throw py::value_error("RoughSurface needs " + missing + " (physical values have no default)");
             s.height_scale = rms ? height_scale_from_rms(s.distribution, s.shape, *rms) : *height_scale;
             s.summit_radius = *summit_radius;
             s.summit_density = *summit_density;
             s.nominal_area = *nominal_area;
             s.contact_modulus = *contact_modulus;
             return s;
           }),
           "distribution"_a, "side"_a = py::none(), "shape"_a = py::none(), "height_scale"_a = py::none(),
           "summit_radius"_a = py::none(), "summit_density"_a = py::none(), "nominal_area"_a = py::none(),
           "contact_modulus"_a = py::none(), py::kw_only(), "rms"_a = py::none(),
           "The physical surface a ContactModel takes (PhysicalSurface is its former name); every physical value is\n"
           "required (no defaults). side: 'tail' (GW's approach; None means it) or 'bounded' (the Weibull's worn\n"
           "side). shape: the Weibull shape a (required; None for the Gaussian, which has none). height_scale\n"
           "sigma_s [m]: the Weibull scale (not its rms), or the Gaussian's rms summit height; or instead rms [m],\n"
           "the rms summit height GW users measure, which sets height_scale through height_scale_from_rms (for\n"
           "a = 1.6, rms = 0.574 sigma_s). summit_radius R [m], summit_density [1/m^2], nominal_area A0 [m^2],\n"
           "contact_modulus E* [Pa] (plane strain). A missing or conflicting value raises ValueError.")
      .def_property(
          "distribution", [](const RoughSurface& s) { return s.distribution; },
          [](RoughSurface& s, const DistributionName& value) { s.distribution = to_distribution(value.object); })
      .def_property(
          "side", [](const RoughSurface& s) { return s.side; },
          [](RoughSurface& s, const SideName& value) { s.side = to_side(value.object); })
      .def_readwrite("shape", &RoughSurface::shape)
      .def_readwrite("height_scale", &RoughSurface::height_scale)
      .def_readwrite("summit_radius", &RoughSurface::summit_radius)
      .def_readwrite("summit_density", &RoughSurface::summit_density)
      .def_readwrite("nominal_area", &RoughSurface::nominal_area)
      .def_readwrite("contact_modulus", &RoughSurface::contact_modulus)
      .def_property(
          "rms",
          [](const RoughSurface& s) {
            return s.distribution == Distribution::gaussian ? s.height_scale : s.height_scale * weibull_rms(s.shape);
          },
          [](RoughSurface& s, double rms) { s.height_scale = height_scale_from_rms(s.distribution, s.shape, rms); },
          "The rms summit height [m] (about the mean): height_scale * weibull_rms(shape) for the Weibull, height_scale\n"
          "for the Gaussian. Setting it sets height_scale for the current distribution and shape.")
      .def_property_readonly("summit_count", &RoughSurface::summit_count, "summit_density * nominal_area")
      .def("validate", &RoughSurface::validate, "Raises asperity.Error naming the first bad parameter.")
      .def("__repr__", [](const RoughSurface& s) {
        // what applies only: the Gaussian has no side and no shape
        const std::string heights =
            s.distribution == Distribution::weibull
                ? std::string(py::str("'weibull', side='{}', shape={!r}").format(to_string(s.side), s.shape))
                : std::string("'gaussian'");
        return py::str("RoughSurface({}, height_scale={!r}, summit_radius={!r}, summit_density={!r}, nominal_area={!r}, "
                       "contact_modulus={!r})")
            .format(heights, s.height_scale, s.summit_radius, s.summit_density, s.nominal_area, s.contact_modulus);
      });
  m.def("contact_modulus_from", py::vectorize(&contact_modulus_from), "young1"_a, "poisson1"_a, "young2"_a, "poisson2"_a,
        "E* from 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (broadcasts); raises asperity.Error for E <= 0 or nu\n"
        "outside (-1, 0.5].");
  m.def(
      "contact_modulus_given",
      [](std::optional<double> contact_modulus, std::optional<double> young1, std::optional<double> poisson1,
         std::optional<double> young2, std::optional<double> poisson2) -> std::optional<double> {
        const double not_given = std::numeric_limits<double>::quiet_NaN();
        const double modulus =
            contact_modulus_given(contact_modulus.value_or(not_given), young1.value_or(not_given),
                                  poisson1.value_or(not_given), young2.value_or(not_given), poisson2.value_or(not_given));
        if (std::isnan(modulus)) return std::nullopt;
        return modulus;
      },
      "contact_modulus"_a = py::none(), "young1"_a = py::none(), "poisson1"_a = py::none(), "young2"_a = py::none(),
      "poisson2"_a = py::none(),
      "E* [Pa] from what a user gave: contact_modulus itself, or young1, poisson1, young2, poisson2 together\n"
      "(the commands' check); None where none is given. Raises asperity.Error for both, the four\n"
      "incomplete, E* not positive, or a bad E or nu.");
  m.def("nominal_pressure_from_load", &nominal_pressure_from_load, "load"_a, "nominal_area"_a,
        "A total load [N] as the nominal pressure [Pa] over the nominal area [m^2]; asperity.Error for a\n"
        "load or area that is not a positive number.");
  m.def(
      "height_scale_from_rms",
      [](const DistributionName& distribution, const ArrayLike& shape, const ArrayLike& rms) -> py::object {
        const Distribution d = to_distribution(distribution.object);
        return py::vectorize([d](double a, double r) { return height_scale_from_rms(d, a, r); })(shape.object,
                                                                                                rms.object);
      },
      "distribution"_a, "shape"_a, "rms"_a,
      "The height scale sigma_s that gives an rms summit height rms (about the mean, [m]): rms / c_a for the\n"
      "Weibull, c_a = weibull_rms(shape) (for a = 1.6, rms = 0.574 sigma_s); the rms itself for the Gaussian\n"
      "(shape ignored). Broadcasts over shape and rms. Raises asperity.Error for rms or a Weibull shape <= 0.");
  m.def("gaussian_surface_from_moments", &gaussian_surface_from_moments, "m0"_a, "m2"_a, "m4"_a, "nominal_area"_a,
        "contact_modulus"_a,
        "A Gaussian RoughSurface from its profile's spectral moments (Nayak's bandwidth, McCool's summit\n"
        "statistics; docs/model.md section 6).");
  m.def("bandwidth_alpha", &bandwidth_alpha, "m0"_a, "m2"_a, "m4"_a, "Nayak's bandwidth alpha = m0 m4 / m2^2.");
}

}  // namespace asperity::python
