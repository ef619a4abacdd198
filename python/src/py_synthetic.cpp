// Synthetic surfaces (asperity/topography/synthetic.hpp): Gaussian random fields and Weibull marginals.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <vector>

#include "bindings.hpp"
#include "topography_helpers.hpp"
#include "asperity/topography/synthetic.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

namespace topo = asperity::topography;


void bind_synthetic(py::module_& m) {
  // ---- synthetic surfaces (synthetic.hpp) ----
  py::class_<topo::SpectrumComponent>(m, "SpectrumComponent",
                                      "A Gaussian bump of the spectrum: kernel standard deviation [points], variance [m^2].")
      .def(py::init([](double correlation, double variance) { return topo::SpectrumComponent{correlation, variance}; }),
           "correlation"_a = 4.0, "variance"_a = 1.0)
      .def_readwrite("correlation", &topo::SpectrumComponent::correlation)
      .def_readwrite("variance", &topo::SpectrumComponent::variance);
  m.def(
      "gaussian_random_field",
      [](const Count& nx, const Count& ny, double dx, double dy, std::vector<topo::SpectrumComponent> spectrum,
         std::uint64_t seed) {
        const std::size_t columns = to_size(nx.object, "nx"), rows = to_size(ny.object, "ny");
        return without_gil([&] { return topo::gaussian_random_field(columns, rows, dx, dy, spectrum, seed); });
      },
      "nx"_a, "ny"_a, "dx"_a, "dy"_a, "spectrum"_a, "seed"_a = 1,
      "A Gaussian random field: white noise convolved with a Gaussian kernel per component, summed. Every\n"
      "height is exactly N(0, total variance); reproducible from seed. Limits (asperity.Error beyond them):\n"
      "3 <= nx, ny and nx * ny <= 2^26 points; each correlation in (0, 65536] points; the noise convolved,\n"
      "(nx + 2h) (ny + 2h) with h = ceil(4 correlation), at most 2^27 points; at most 2^36 multiply-adds.");
  m.def("expected_spectral_moments", &topo::expected_spectral_moments, "dx"_a, "dy"_a, "spectrum"_a,
        "The spectral moments gaussian_random_field's fields have in expectation.");
  py::enum_<topo::CorrelationFunction>(m, "CorrelationFunction",
                                       "The correlation of spectral_random_field's fields: gaussian exp(-r^2/xi^2)\n"
                                       "(narrow band), exponential exp(-r/xi) (broad band).")
      .value("gaussian", topo::CorrelationFunction::gaussian)
      .value("exponential", topo::CorrelationFunction::exponential);
  m.def(
      "spectral_random_field",
      [](const Count& nx, const Count& ny, double dx, double dy, topo::CorrelationFunction function,
         double correlation_length, std::uint64_t seed) {
        const std::size_t columns = to_size(nx.object, "nx"), rows = to_size(ny.object, "ny");
        return without_gil([&] {
          return topo::spectral_random_field(columns, rows, dx, dy, function, correlation_length, seed);
        });
      },
      "nx"_a, "ny"_a, "dx"_a, "dy"_a, "function"_a, "correlation_length"_a, "seed"_a = 1,
      "An isotropic Gaussian random field of unit variance with the named correlation (correlation_length in\n"
      "points), by FFT on a periodic grid twice the map's size, cut to the map; reproducible from seed. The\n"
      "exponential one at correlation_length 20-25 is broad-band like measured maps (Nayak alpha ~30 at 256^2).\n"
      "Limits: 3 <= nx, ny and nx * ny <= 2^26; correlation_length in (0, 65536].");
  m.def("to_weibull_marginal", &topo::to_weibull_marginal, "map"_a, "shape"_a, "bounded"_a = false,
        "Maps each height of a unit-variance Gaussian field to a unit Weibull of the shape (bounded: mirrored,\n"
        "bounded above), in place. Holds the GIL (other Python threads see the map before or after).");
}

}  // namespace asperity::python
