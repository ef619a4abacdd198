// The whole path and its report (asperity/topography/analysis.hpp, surface_report.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "record_bindings.hpp"
#include "topography_helpers.hpp"
#include "asperity/topography/analysis.hpp"
#include "asperity/topography/surface_report.hpp"
#include "asperity/topography/next_steps.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace asperity::python {

namespace topo = asperity::topography;


void bind_analysis_options(py::module_& m) {
  // ---- the whole path (analysis.hpp, surface_report.hpp) ----
  // each result record's attributes from its one list (record_fields.hpp), its meanings the docstrings
  py::class_<topo::SamplingRow> sampling_row(m, "SamplingRow", "Summits and moments at factor times the sampling interval.");
  def_record_fields(sampling_row);
  py::class_<topo::SurfaceVerdict> surface_verdict(
      m, "SurfaceVerdict",
      "Is the surface Gaussian (its heights' and its summit heights' tests against surrogate\n"
      "surfaces of its own spectrum, each at half the significance), which way its heights\n"
      "lean, and the model named for the contact, in words.");
  def_record_fields(surface_verdict).def("__repr__", [](const topo::SurfaceVerdict& v) { return v.text; });
  m.attr("MIN_SUMMITS_TO_TEST") = topo::min_summits_to_test;
  m.attr("SIDE_INTERVAL_RATIO_MAX") = topo::side_interval_ratio_max;
  m.def("summit_test_rule", &topo::summit_test_rule, "When the summit heights' test speaks, in words.");
  m.def("side_rule", &topo::side_rule, "When a side is told, in words.");
  py::class_<topo::NextSteps> next_steps(
      m, "NextSteps",
      "What to do next with an analysis (next_steps): for the model the verdict names, the\n"
      "`asperity contact` command, the Python call and its card's command; the map's exact-contact\n"
      "command; where no model is named, why and what to use instead.");
  def_record_fields(next_steps).def("__repr__", [](const topo::NextSteps& n) { return n.text; });
  py::class_<topo::AnalysisOptions>(m, "AnalysisOptions", "What analyse_height_map and analyse_surface_file do.")
      .def(py::init([](const std::optional<topo::ReadOptions>& read, bool level,
                       const std::optional<topo::SummitOptions>& summits,
                       const std::optional<topo::AssessmentOptions>& assessment, bool fit_heights,
                       std::size_t max_height_sample, std::vector<std::size_t> sampling_factors,
                       std::optional<topo::ContactOptions> contact, std::size_t max_fit_sample) {
             topo::AnalysisOptions options;
             if (read) options.read = *read;
             options.level = level;
             if (summits) options.summits = *summits;
             if (assessment) options.assessment = *assessment;
             options.fit_heights = fit_heights;
             options.max_height_sample = max_height_sample;
             options.sampling_factors = std::move(sampling_factors);
             options.contact = std::move(contact);
             options.max_fit_sample = max_fit_sample;
             return options;
           }),
           "read"_a = py::none(), "level"_a = true, "summits"_a = py::none(), "assessment"_a = py::none(),
           "fit_heights"_a = true, "max_height_sample"_a = topo::AnalysisOptions{}.max_height_sample,
           "sampling_factors"_a = topo::AnalysisOptions{}.sampling_factors, "contact"_a = py::none(),
           "max_fit_sample"_a = topo::AnalysisOptions{}.max_fit_sample,
           "read: ReadOptions (files only); level: subtract the least-squares plane; summits: SummitOptions;\n"
           "assessment: AssessmentOptions (the bootstrap); fit_heights: also fit the heights, thinned to one per\n"
           "correlation length and at most max_height_sample; sampling_factors: summits at k dx; contact:\n"
           "ContactOptions for the contact curves of each fit (None: no curves); max_fit_sample: the summit\n"
           "heights fitted, all up to this many, else a reproducible random subsample of this many.")
      .def_readwrite("read", &topo::AnalysisOptions::read)
      .def_readwrite("level", &topo::AnalysisOptions::level)
      .def_readwrite("summits", &topo::AnalysisOptions::summits)
      .def_readwrite("assessment", &topo::AnalysisOptions::assessment)
      .def_readwrite("fit_heights", &topo::AnalysisOptions::fit_heights)
      .def_readwrite("max_height_sample", &topo::AnalysisOptions::max_height_sample)
      .def_readwrite("sampling_factors", &topo::AnalysisOptions::sampling_factors)
      .def_readwrite("contact", &topo::AnalysisOptions::contact)
      .def_readwrite("max_fit_sample", &topo::AnalysisOptions::max_fit_sample);
}

void bind_report(py::module_& m) {
  py::class_<topo::ReportOutcome>(m, "ReportOutcome", "What write_report wrote.")
      .def_property_readonly("files", [](const topo::ReportOutcome& o) { return path_texts(o.files); })
      .def_readonly("plots", &topo::ReportOutcome::plots)
      .def_readonly("plot_note", &topo::ReportOutcome::plot_note, "Why there are no plots (a map at its noise floor).");

  auto write_report = [](const topo::SurfaceAnalysis& analysis, const PathName& directory, bool overwrite) {
    const std::string path = to_path(directory.object, "directory");
    return without_gil([copy = analysis, &path, overwrite] { return topo::write_report(copy, path, overwrite); });
  };
  const char* report_doc =
      "Writes a report folder (created if needed): report.md with the plots, report.json, curves.csv,\n"
      "summits.csv, fits.svg and contact.svg (drawn by the library: nothing is run). Each file is replaced\n"
      "atomically, no link in the folder is followed, one run writes the folder at a time and an earlier\n"
      "report's files are not left beside this one's; a file of the user's under a report file's name is\n"
      "kept (the call fails) unless overwrite=True. Raises asperity.Error on a write error.";
  py::class_<topo::NoiseFloor> noise_floor(
      m, "NoiseFloor", "A roughness at the level of the heights' quantization q: Sq under 10 q / sqrt(12).");
  def_record_fields(noise_floor).def("__repr__", [](const topo::NoiseFloor& f) {
    return py::str("NoiseFloor(reached={!r}, resolution={!r})").format(f.reached, f.resolution);
  });

  py::class_<topo::SurfaceAnalysis> analysis(m, "SurfaceAnalysis",
                                    "A measured surface analysed: the map as analysed, statistics, moments, summits, the fits\n"
                                    "with their evidence, and the contact curves. to_dict() gives all of it as the JSON document\n"
                                    "(its schema: SURFACE_JSON_SCHEMA) that `asperity surface --json` writes.");
  def_record_fields(analysis)  // its fields from its list (analysis.hpp), each with its meaning
      .def("to_dict", [](const topo::SurfaceAnalysis& a) {
        return py::module_::import("json").attr("loads")(path_text(topo::analysis_json(a)));
      }, "The analysis as a dict: the JSON document (schema SURFACE_JSON_SCHEMA); NaN is None.")
      .def("json", [](const topo::SurfaceAnalysis& a) { return path_text(topo::analysis_json(a)); },
           "The JSON document (schema SURFACE_JSON_SCHEMA) as text.")
      .def("summary", [](const topo::SurfaceAnalysis& a) { return path_text(topo::analysis_summary(a)); },
           "The short summary `asperity surface` prints.")
      .def("write_report", write_report, "directory"_a, py::kw_only(), "overwrite"_a = false, report_doc);

  auto analysis_options = [](std::optional<topo::AnalysisOptions> options, const py::kwargs& fields) {
    if (fields.size() == 0) return options.value_or(topo::AnalysisOptions{});
    if (options) throw py::type_error("give options or its fields as keywords, not both");
    return py::type::of<topo::AnalysisOptions>()(**fields).cast<topo::AnalysisOptions>();
  };
  m.def(
      "analyse_height_map",
      [analysis_options](const topo::HeightMap& map, std::optional<topo::AnalysisOptions> options,
                         const py::kwargs& fields) {
        const topo::AnalysisOptions chosen = analysis_options(std::move(options), fields);
        return without_gil(
            [copy = map, &chosen]() mutable { return topo::analyse_height_map(std::move(copy), chosen); });
      },
      "map"_a, "options"_a = py::none(),
      "The whole path on a map (not changed): leveling, statistics, moments, summits, the fits of the summit\n"
      "heights (and of the thinned heights) with their evidence, and the contact curves when options.contact\n"
      "is given. options: an AnalysisOptions, or its fields as keywords. Raises asperity.Error (e.g. fewer than\n"
      "5 summits).");
  m.def(
      "analyse_surface_file",
      [analysis_options](const PathName& path, std::optional<topo::AnalysisOptions> options, const py::kwargs& fields) {
        const topo::AnalysisOptions chosen = analysis_options(std::move(options), fields);
        const std::string file = to_path(path.object);
        return without_gil([&] { return topo::analyse_surface_file(file, chosen); });
      },
      "path"_a, "options"_a = py::none(),
      "read_height_map and analyse_height_map in one call: options.read says how to read the file (format,\n"
      "pixel sizes, units); options: an AnalysisOptions, or its fields as keywords.");
  m.def(
      "analysis_json", [](const topo::SurfaceAnalysis& a) { return path_text(topo::analysis_json(a)); }, "analysis"_a,
      "The JSON document (schema SURFACE_JSON_SCHEMA) as text.");
  m.def(
      "analysis_summary", [](const topo::SurfaceAnalysis& a) { return path_text(topo::analysis_summary(a)); },
      "analysis"_a, "The short summary `asperity surface` prints.");
  m.attr("SURFACE_JSON_SCHEMA") = topo::surface_json_schema;
  m.def(
      "record_fields",
      [](const py::type& record) -> py::object {
        if (!py::hasattr(record, "_record_fields"))
          throw py::type_error(std::string(py::str(record.attr("__name__"))) + " is not a result record");
        return record.attr("_record_fields");
      },
      "record"_a,
      "A result record's fields, from the list that defines them (record_fields.hpp): a tuple of (name, key,\n"
      "meaning), the attribute's name, its key in the record's object of the JSON document (None: not written)\n"
      "and what it is with its unit. TypeError for a class that is no result record.");
  m.def("next_steps", &topo::next_steps, "analysis"_a,
        "What to do next: the named model's command, Python call and card, the map's exact contact (NextSteps).");
  m.def("write_report", write_report, "analysis"_a, "directory"_a, py::kw_only(), "overwrite"_a = false, report_doc);
}

}  // namespace asperity::python
