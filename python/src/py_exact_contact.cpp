// The exact contact of a map (asperity/topography/exact_contact.hpp, exact_contact_table.hpp,
// self_affine.hpp): self-affine surfaces, ContactStep and the solver ExactContact.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "topography_helpers.hpp"
#include "asperity/contact_curves_data.hpp"
#include "asperity/output.hpp"
#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/exact_contact_table.hpp"
#include "asperity/topography/self_affine.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

namespace topo = asperity::topography;

namespace {

// A solver and the lock that makes its calls one at a time: a solve runs without the GIL and
// changes the solver's state (the warm start), so two Python threads must not run one together.
struct ExactContactHandle {
  ExactContactHandle(const topo::HeightMap& map, const topo::ExactContactOptions& options) : solver(map, options) {}
  topo::ExactContact solver;
  std::mutex lock;
};

// A field of the map's grid as a new (ny, nx) array.
py::array_t<double> grid_array(const std::vector<double>& field, std::size_t nx, std::size_t ny) {
  py::array_t<double> out({static_cast<py::ssize_t>(ny), static_cast<py::ssize_t>(nx)});
  std::copy(field.begin(), field.end(), out.mutable_data());
  return out;
}

// the solves (one at a time: the solver's lock), the table, the last solution's fields
void bind_exact_contact_solves(py::class_<ExactContactHandle>& exact_contact) {
  exact_contact
      .def(
          "at_pressure",
          [](ExactContactHandle& h, double pressure) {
            return without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              return h.solver.at_pressure(pressure);
            });
          },
          "pressure"_a, "The contact at a mean nominal pressure [Pa] >= 0.")
      .def(
          "at_mean_gap",
          [](ExactContactHandle& h, double mean_gap) {
            return without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              return h.solver.at_mean_gap(mean_gap);
            });
          },
          "mean_gap"_a, "The contact at a mean gap [m] > 0 (the separation from the mean plane).")
      .def(
          "at_approach",
          [](ExactContactHandle& h, double approach) {
            return without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              return h.solver.at_approach(approach);
            });
          },
          "approach"_a,
          "The contact with the flat at `approach` [m] above the mean plane (ContactStep.approach; padded Love: from\n"
          "the far field), from the last solution; with adhesion the cohesive zone continues the last step's.")
      .def(
          "write_table",
          [](ExactContactHandle& h, const PathName& path, const std::vector<double>& pressures, double safety_factor,
             const std::string& description, bool overwrite, std::size_t max_checks) {
            const std::string file = to_path(path.object);
            topo::ExactContactTable table;
            without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              OutputPlan plan(overwrite);  // the output checked before the first solve too
              plan.file("path", file, output_kinds::contact_curves_table);
              plan.check();
              for (std::size_t i = 1; i < pressures.size(); ++i)
                if (!(pressures[i] > pressures[i - 1])) throw Error("write_table needs the pressures in ascending order");
              // every limit of the table checked before the first solve
              topo::check_exact_contact_table_nodes(pressures);
              topo::check_exact_contact_table_max_checks(max_checks);
              for (double pressure : pressures) h.solver.check_pressure(pressure);
              const std::string options = topo::exact_contact_table_generator_options(
                  "asperity.topography.ExactContact.write_table: ", pressures);
              topo::check_exact_contact_table_text(description, options);
              std::vector<topo::ContactStep> nodes;
              for (double pressure : pressures) nodes.push_back(h.solver.at_pressure(pressure));
              table = topo::measure_exact_contact_table(h.solver, nodes, description, options, safety_factor,
                                                        max_checks);
              write_contact_curves_file(table.data, file, overwrite);
            });
            py::list nodes;
            for (const topo::ContactStep& step : table.nodes) nodes.append(step);
            return nodes;
          },
          "path"_a, "pressures"_a, "safety_factor"_a = topo::default_table_safety_factor, "description"_a = "",
          py::kw_only(), "overwrite"_a = false, "max_checks"_a = topo::default_table_max_checks,
          "Writes the map's contact curves as a contact-curves table (asperity.ContactCurves serves it): solves at\n"
          "the pressures [Pa] (ascending, at least 3) as nodes, solves between each two to measure the served\n"
          "curves' error: 2 then 5 an interval, finer where the two estimates differ by more than 1.25x, at most\n"
          "max_checks (>= 5) an interval; the stored bound is the largest error times safety_factor (bound_method\n"
          "'checks-until-settled'). Returns the nodes' ContactSteps. The\n"
          "pressures, the description's length, the solver's range and the output (a file there that is not a\n"
          "contact-curves table of asperity's is replaced only with overwrite=True) are checked before the first solve.")
      .def(
          "pressure_field",
          [](ExactContactHandle& h) {
            const std::vector<double> field = without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              return h.solver.pressure_field();
            });
            return grid_array(field, h.solver.nx(), h.solver.ny());
          },
          "The last solution's pressure [Pa] as a (ny, nx) array (0 off contact).")
      .def(
          "gap_field",
          [](ExactContactHandle& h) {
            const std::vector<double> field = without_gil([&] {
              std::lock_guard<std::mutex> guard(h.lock);
              return h.solver.gap_field();
            });
            return grid_array(field, h.solver.nx(), h.solver.ny());
          },
          "The last solution's gap [m] as a (ny, nx) array (0 in contact, NaN at missing points).");
}

}  // namespace

void bind_exact_contact(py::module_& m) {
  // ---- the exact contact of a map (exact_contact.hpp, self_affine.hpp) ----
  m.def(
      "self_affine_surface",
      [](const Count& nx, const Count& ny, double dx, double dy, double hurst, double rolloff_wavelength,
         double cutoff_wavelength, double rms_height, std::uint64_t seed) {
        const std::size_t columns = to_size(nx.object, "nx"), rows = to_size(ny.object, "ny");
        topo::SelfAffineSpectrum spectrum;
        spectrum.hurst = hurst;
        spectrum.rolloff_wavelength = rolloff_wavelength;
        spectrum.cutoff_wavelength = cutoff_wavelength;
        spectrum.rms_height = rms_height;
        return without_gil([&] { return topo::self_affine_surface(columns, rows, dx, dy, spectrum, seed); });
      },
      "nx"_a, "ny"_a, "dx"_a, "dy"_a, py::kw_only(), "hurst"_a = 0.8, "rolloff_wavelength"_a = 0.0,
      "cutoff_wavelength"_a = 0.0, "rms_height"_a = 1e-6, "seed"_a = 1,
      "A periodic self-affine Gaussian surface: C(q) flat below the roll-off wavenumber 2 pi / rolloff_wavelength\n"
      "(0: the map's size), q^(-2(1 + hurst)) up to 2 pi / cutoff_wavelength (0: Nyquist), zero beyond; mean 0,\n"
      "rms height exactly rms_height [m]; reproducible from seed. Raises asperity.Error for bad sizes or spectra.");
  m.def(
      "spectral_rms_gradient",
      [](const topo::HeightMap& map) { return without_gil([copy = map] { return topo::spectral_rms_gradient(copy); }); },
      "map"_a,
      "The rms gradient sqrt(<|grad h|^2>) of a map taken as periodic, from its Fourier spectrum: the slope in\n"
      "the area-load law A/A0 = kappa p / (E* h'_rms). Raises asperity.Error for missing points.");
  py::class_<topo::ContactStep> contact_step(m, "ContactStep",
                                "One load step of the exact contact: nominal pressure and load, the mean gap (the\n"
                                "separation of the flat from the mean plane), that less the mean summit height (the GW\n"
                                "curves' datum), area, stiffness -dP/d(mean gap) from the incremental solve, contact\n"
                                "patches, and the solve's iterations and residual.");
  // its fields from their one list (ContactStep's, exact_contact.hpp), each with its meaning
#define ASPERITY_BIND_FIELD(type, name, column, meaning) contact_step.def_readonly(#name, &topo::ContactStep::name, meaning);
  ASPERITY_CONTACT_STEP_FIELDS(ASPERITY_BIND_FIELD)
#undef ASPERITY_BIND_FIELD
  contact_step.def("__repr__", [](const topo::ContactStep& s) {
        return "ContactStep(pressure=" + std::string(py::repr(py::float_(s.pressure))) +
               ", mean_gap=" + std::string(py::repr(py::float_(s.mean_gap))) +
               ", area_fraction=" + std::string(py::repr(py::float_(s.area_fraction))) + ")";
      });
  py::class_<ExactContactHandle> exact_contact(m, "ExactContact",
      "The exact elastic contact of a height map with a flat (boundary elements on FFTs, a constrained conjugate\n"
      "gradient; docs/exact-contact.md). boundary: 'periodic' or 'padded' (non-periodic, zero padding); kernel:\n"
      "'fourier' (point force) or 'love' (pixel-constant pressure); solver: 'preconditioned' (by the inverse\n"
      "Green's function's 3 x 3 stencil) or 'polonsky-keer' (as published). Each step starts from the solution\n"
      "on the map coarsened 2 x 2 (coarse_start) or else from the last solution. A solve that does not converge raises asperity.Error. Calls on one solver run\n"
      "one at a time (a lock), without the GIL. max_memory: the bytes it may allocate (None: no limit): a map whose\n"
      "estimate (its arrays, counted) exceeds it raises asperity.Error before anything is allocated, as running out\n"
      "of memory does, with the map's size and the estimate. A pressure below one node of contact or beyond the\n"
      "solver's numerical range raises asperity.Error before iterating, naming the bound; a periodic map without\n"
      "missing points pressed flat (above its full-contact pressure, from one FFT) is answered in closed form.\n"
      "hardness [Pa]: the pressure capped at it on every point (elastic-perfectly-plastic: points at it are\n"
      "plastic, ContactStep.plastic_points; 0 or inf: elastic); a pressure at or above plastic_limit raises.\n"
      "work_of_adhesion [J/m^2] with adhesive_stress [Pa]: adhesive (the Maugis-Dugdale cohesive zone: the tension\n"
      "adhesive_stress wherever the gap is within work_of_adhesion / adhesive_stress; ContactStep.adhesive_pressure,\n"
      "adhesive_points), solved by at_approach (or at_mean_gap, periodic without missing points), each step from\n"
      "the last (loading and unloading follow their branches); at_pressure raises.");
  exact_contact
      .def(py::init([](const topo::HeightMap& map, double contact_modulus, const std::string& boundary,
                       const std::string& kernel, double tolerance, int max_iterations, int love_aliases,
                       bool stiffness, int threads, const std::string& solver, bool coarse_start,
                       std::optional<std::size_t> max_memory, double hardness, double work_of_adhesion,
                       double adhesive_stress) {
             topo::ExactContactOptions options;
             options.hardness = hardness;
             options.work_of_adhesion = work_of_adhesion;
             options.adhesive_stress = adhesive_stress;
             options.contact_modulus = contact_modulus;
             if (!topo::parse_contact_boundary(boundary, options.boundary))
               throw py::value_error("boundary must be 'periodic' or 'padded', not '" + boundary + "'");
             if (!topo::parse_contact_kernel(kernel, options.kernel))
               throw py::value_error("kernel must be 'fourier' or 'love', not '" + kernel + "'");
             if (!topo::parse_contact_solver(solver, options.solver))
               throw py::value_error("solver must be 'preconditioned' or 'polonsky-keer', not '" + solver + "'");
             options.coarse_start = coarse_start;
             options.tolerance = tolerance;
             options.max_iterations = max_iterations;
             options.love_aliases = love_aliases;
             options.stiffness = stiffness;
             options.threads = threads;
             options.max_memory = max_memory.value_or(0);  // None: no limit
             return without_gil([copy = map, &options] { return std::make_unique<ExactContactHandle>(copy, options); });
           }),
           "map"_a, py::kw_only(), "contact_modulus"_a, "boundary"_a = "periodic", "kernel"_a = "fourier",
           "tolerance"_a = 1e-8, "max_iterations"_a = 20000, "love_aliases"_a = 16, "stiffness"_a = true,
           "threads"_a = 0, "solver"_a = "preconditioned", "coarse_start"_a = true, "max_memory"_a = py::none(),
           "hardness"_a = 0.0, "work_of_adhesion"_a = 0.0, "adhesive_stress"_a = 0.0);
  bind_exact_contact_solves(exact_contact);
  exact_contact
      .def_property_readonly("nx", [](const ExactContactHandle& h) { return h.solver.nx(); })
      .def_property_readonly("full_contact_pressure",
                             [](const ExactContactHandle& h) { return h.solver.pressure_range().full_contact; },
                             "The nominal pressure [Pa] above which the whole map touches (a periodic map without missing\n"
                             "points, from one FFT; inf otherwise): at_pressure answers above it in closed form.")
      .def_property_readonly("plastic_limit",
                             [](const ExactContactHandle& h) { return h.solver.pressure_range().plastic_limit; },
                             "With a hardness, the nominal pressure [Pa] of the whole map plastic (refused at or above\n"
                             "it); inf elastic.")
      .def_property_readonly("memory_estimate", [](const ExactContactHandle& h) { return h.solver.memory_estimate(); },
                             "The bytes the solver needs, as max_memory counts them.")
      .def_property_readonly("ny", [](const ExactContactHandle& h) { return h.solver.ny(); })
      .def_property_readonly("rms_height", [](const ExactContactHandle& h) { return h.solver.rms_height(); },
                             "About the mean plane [m].")
      .def_property_readonly("max_height", [](const ExactContactHandle& h) { return h.solver.max_height(); },
                             "The highest point above the mean plane [m].")
      .def_property_readonly("mean_summit_height",
                             [](const ExactContactHandle& h) { return h.solver.mean_summit_height(); },
                             "Above the mean plane [m] (NaN without summits).")
      .def_property_readonly("summits", [](const ExactContactHandle& h) { return h.solver.summits(); })
      .def_property_readonly("nominal_area", [](const ExactContactHandle& h) { return h.solver.nominal_area(); },
                             "[m^2]");
}

}  // namespace asperity::python
