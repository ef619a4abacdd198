// The height models, their fits and their evidence (asperity/topography/distribution_fit.hpp,
// goodness_of_fit.hpp): distributions, fits, statistics, the bootstrap's assessment and its verdict.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "record_bindings.hpp"
#include "topography_helpers.hpp"
#include "asperity/topography/distribution_fit.hpp"
#include "asperity/topography/goodness_of_fit.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

namespace topo = asperity::topography;

namespace {

topo::HeightModel to_model(const py::handle& value) {
  if (py::isinstance<topo::HeightModel>(value)) return value.cast<topo::HeightModel>();
  if (py::isinstance<py::str>(value)) {
    std::string name = value.cast<std::string>();
    std::replace(name.begin(), name.end(), '_', '-');  // Python's enum names: weibull_tail
    topo::HeightModel model;
    if (topo::parse_height_model(name, model)) return model;
    throw py::value_error("unknown height model '" + value.cast<std::string>() +
                          "': expected 'gaussian', 'weibull_tail' or 'weibull_bounded'");
  }
  throw py::type_error("model must be a str or an asperity.topography.HeightModel");
}

// A float64 array of values, in a vector (a copy).
std::vector<double> to_vector(py::handle values, const char* name) {
  const DoubleArray array = as_double_array(values, name);
  return std::vector<double>(array.data(), array.data() + array.size());
}

std::vector<double> sorted_vector(py::handle values, const char* name) {
  std::vector<double> sorted = to_vector(values, name);
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

template <class Function>
FloatOrArray map_values(py::handle input, const char* name, Function function) {
  return map_batch(
      input, name, py::none(),
      [&](const double* in, double* out, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) out[i] = function(in[i]);
      },
      function);
}

std::string repr_interval(const topo::Interval& interval) {
  return py::str("Interval(lo={!r}, hi={!r})").format(interval.lo, interval.hi).cast<std::string>();
}

}  // namespace

void bind_fits(py::module_& m) {
  // ---- height distributions and their fits (distribution_fit.hpp, goodness_of_fit.hpp) ----
  py::enum_<topo::HeightModel>(m, "HeightModel",
                               "gaussian N(location, scale^2); weibull_tail x = location + scale W (the tail up, GW's\n"
                               "side); weibull_bounded x = location - scale W (bounded above: worn, polished).")
      .value("gaussian", topo::HeightModel::gaussian)
      .value("weibull_tail", topo::HeightModel::weibull_tail)
      .value("weibull_bounded", topo::HeightModel::weibull_bounded);
  // the models' names as the JSON documents spell them (to_string's one table), in HeightModel's order
  py::list height_model_names;
  for (topo::HeightModel model : topo::all_height_models) height_model_names.append(topo::to_string(model));
  m.attr("height_model_names") = py::tuple(height_model_names);
  m.def("describe", [](const py::object& model) { return std::string(topo::describe(to_model(model))); }, "model"_a,
        "The model in words.");
  m.def("parameter_count", [](const py::object& model) { return topo::parameter_count(to_model(model)); }, "model"_a,
        "2 for the Gaussian, 3 for the Weibulls.");

  py::class_<topo::HeightDistribution> height_distribution(
      m, "HeightDistribution",
      "One of the three height models with its parameters [m] (the Gaussian: mean and\n"
      "standard deviation; the Weibulls: location, scale and shape a). The functions\n"
      "take a number (a float back) or an array of any shape (an array back).");
  // its parameters from their one list, writable (an input too); the model also from its name
  def_record_fields(height_distribution, true);
  height_distribution
      .def(py::init([](const py::object& model, double location, double scale, double shape) {
             return topo::HeightDistribution{to_model(model), location, scale, shape};
           }),
           "model"_a = "gaussian", "location"_a = 0.0, "scale"_a = 1.0, "shape"_a = 0.0)
      .def_property(
          "model", [](const topo::HeightDistribution& d) { return d.model; },
          [](topo::HeightDistribution& d, const py::object& value) { d.model = to_model(value); }, "the height model")
      .def("pdf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return std::exp(d.log_pdf(v)); });
      }, "x"_a, "The density.")
      .def("log_pdf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return d.log_pdf(v); });
      }, "x"_a, "ln of the density (-inf outside the support).")
      .def("cdf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return d.cdf(v); });
      }, "x"_a, "P(X <= x).")
      .def("log_cdf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return d.log_cdf(v); });
      }, "x"_a, "ln P(X <= x).")
      .def("log_sf", [](topo::HeightDistribution d, const ArrayLike& x) {
        return map_values(x.object, "x", [&](double v) { return d.log_sf(v); });
      }, "x"_a, "ln P(X > x).")
      .def("quantile", [](topo::HeightDistribution d, const ArrayLike& p) {
        return map_values(p.object, "p", [&](double v) { return d.quantile(v); });
      }, "p"_a, "The x with P(X <= x) = p, p in (0, 1) (NaN outside).")
      .def("mean", &topo::HeightDistribution::mean,
           "The mean: NaN for parameters that are no distribution (scale <= 0, a Weibull shape <= 0, not finite),\n"
           "+-inf beyond the largest double (a Weibull shape below ~0.006).")
      .def("standard_deviation", &topo::HeightDistribution::standard_deviation,
           "The standard deviation: NaN for parameters that are no distribution, inf beyond the largest double.")
      .def("__repr__", [](const topo::HeightDistribution& d) {
        return py::str("HeightDistribution(model='{}', location={!r}, scale={!r}, shape={!r})")
            .format(py::str(py::cast(d.model).attr("name")), d.location, d.scale, d.shape);
      });

  py::class_<topo::FitOptions>(m, "FitOptions", "The Weibull shape's search range of the fits.")
      .def(py::init([](double shape_min, double shape_max) {
             topo::FitOptions options;
             options.shape_min = shape_min;
             options.shape_max = shape_max;
             return options;
           }),
           "shape_min"_a = topo::FitOptions{}.shape_min, "shape_max"_a = topo::FitOptions{}.shape_max)
      .def_readwrite("shape_min", &topo::FitOptions::shape_min)
      .def_readwrite("shape_max", &topo::FitOptions::shape_max);
  py::class_<topo::FitResult> fit_result(m, "FitResult", "A fitted distribution.");
  def_record_fields(fit_result);
  m.def(
      "fit_height_distribution",
      [](const py::object& model, const ArrayLike& values, const std::optional<topo::FitOptions>& options) {
        const topo::HeightModel chosen = to_model(model);
        const std::vector<double> sorted = sorted_vector(values.object, "values");
        const topo::FitOptions fit = options.value_or(topo::FitOptions{});
        return without_gil([&] { return topo::fit_height_distribution(chosen, sorted, fit); });
      },
      "model"_a, "values"_a, "options"_a = py::none(),
      "Fits a height model to values (any order): the Gaussian by maximum likelihood, the three-parameter\n"
      "Weibulls by maximum product of spacings (well-posed for every shape, also below 1). At least 5\n"
      "finite values not all equal (asperity.Error otherwise).");
  m.def(
      "mean_log_spacing",
      [](const topo::HeightDistribution& d, const ArrayLike& values) {
        return topo::mean_log_spacing(d, sorted_vector(values.object, "values"));
      },
      "distribution"_a, "values"_a, "The MPS objective S (mean log spacing) of a distribution on values.");
  m.def(
      "log_likelihood",
      [](const topo::HeightDistribution& d, const ArrayLike& values) {
        return topo::log_likelihood(d, to_vector(values.object, "values"));
      },
      "distribution"_a, "values"_a, "ln L of values.");
  m.def(
      "anderson_darling",
      [](const topo::HeightDistribution& d, const ArrayLike& values) {
        return topo::anderson_darling(d, sorted_vector(values.object, "values"));
      },
      "distribution"_a, "values"_a, "The Anderson-Darling statistic A^2 of values against a distribution.");
  m.def(
      "kolmogorov_smirnov",
      [](const topo::HeightDistribution& d, const ArrayLike& values) {
        return topo::kolmogorov_smirnov(d, sorted_vector(values.object, "values"));
      },
      "distribution"_a, "values"_a, "The Kolmogorov-Smirnov statistic D of values against a distribution.");
  m.def(
      "draw_sample",
      [](const topo::HeightDistribution& d, std::size_t n, std::uint64_t seed) {
        return to_array(without_gil([d, n, seed] { return topo::draw_sample(d, n, seed); }));
      },
      "distribution"_a, "n"_a, "seed"_a = 1,
      "n reproducible draws (the bootstrap's generator: the same on every platform).");
}

void bind_assessment(py::module_& m) {
  py::class_<topo::AssessmentOptions> assessment_options(m, "AssessmentOptions",
                                                         "The bootstrap and the tests of assess_sample.");
  assessment_options.def(py::init([](int bootstrap, std::uint64_t seed, int threads, double confidence, double significance,
                       const std::optional<topo::FitOptions>& fit) {
             topo::AssessmentOptions options;
             options.bootstrap = bootstrap;
             options.seed = seed;
             options.threads = threads;
             options.confidence = confidence;
             options.significance = significance;
             if (fit) options.fit = *fit;
             return options;
           }),
           "bootstrap"_a = topo::AssessmentOptions{}.bootstrap, "seed"_a = 1, "threads"_a = 0, "confidence"_a = 0.95, "significance"_a = 0.05,
           "fit"_a = py::none(),
           "bootstrap: B parametric-bootstrap samples (0: no p-values, no intervals); seed: reproducible; threads:\n"
           "0 for all cores; confidence of the intervals; significance of the tests for the verdict.");
  def_record_fields(assessment_options, true);
  // each result record's attributes from its one list (record_fields.hpp), its meanings the docstrings
  py::class_<topo::Interval> interval(
      m, "Interval", "A bootstrap interval [lo, hi] (ModelAssessment.shape_interval says how it was made).");
  def_record_fields(interval).def("__repr__", &repr_interval);
  py::class_<topo::ModelAssessment> model_assessment(m, "ModelAssessment",
                                                     "One model fitted to one sample, with its evidence.");
  def_record_fields(model_assessment)
      .def_property_readonly(
          "interval_method", [](const topo::ModelAssessment& m) { return topo::interval_method(m.shape_interval); },
          "The same in words, as report.json's fits.*.intervals gives it.")
      .def("__repr__", [](const topo::ModelAssessment& m) {
        // the p-values as the reports write them: a bound where they are one ("p <= 0.005")
        return "<asperity.topography.ModelAssessment " + std::string(topo::to_string(m.fit.distribution.model)) +
               ": AD " + topo::p_value_text(m.anderson_darling_p, m.p_at_floor) + ", KS " +
               topo::p_value_text(m.kolmogorov_smirnov_p, m.kolmogorov_smirnov_p_at_floor) + ">";
      });
  py::class_<topo::Verdict> verdict(m, "Verdict", "Which model the evidence favours, and the evidence in words.");
  def_record_fields(verdict);
  py::class_<topo::SampleAssessment> sample_assessment(m, "SampleAssessment",
                                                       "The three models fitted to one sample, and a verdict.");
  def_record_fields(sample_assessment)
      .def("model", [](const topo::SampleAssessment& a, const py::object& model) { return a.model(to_model(model)); },
           "model"_a, "The assessment of one model.");
  m.def(
      "assess_sample",
      [](const std::string& name, const ArrayLike& values, const std::optional<topo::AssessmentOptions>& options) {
        std::vector<double> sample = to_vector(values.object, "values");
        const topo::AssessmentOptions chosen = options.value_or(topo::AssessmentOptions{});
        return without_gil([&] { return topo::assess_sample(name, std::move(sample), chosen); });
      },
      "name"_a, "values"_a, "options"_a = py::none(),
      "Fits the three models to values, tests each (Anderson-Darling, Kolmogorov-Smirnov, p-values by parametric\n"
      "bootstrap), gives percentile intervals, AIC and a verdict. The values are assumed independent.");
}

}  // namespace asperity::python
