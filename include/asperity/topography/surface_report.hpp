// The analysis written out: JSON for programs (schema surface_json_schema), a short summary for
// the terminal, and a report folder (Markdown with the plots, JSON, CSV of the curves and of the
// summits, plots as SVG drawn by the library itself: no program is run).
#pragma once
#include <string>
#include <vector>

#include "asperity/output.hpp"

#include "asperity/topography/analysis.hpp"

namespace asperity::topography {

// The JSON document's schema, its "schema" member: the one spelling (the command's help, Python's
// asperity.topography.SURFACE_JSON_SCHEMA and the batch read it from here). 3: each physical
// state (contact.models[].at_pressures and curve, contact.law) keyed by PhysicalState's list
// (nominal_pressure_Pa, count, ...), as `asperity contact` writes it.
inline constexpr const char* surface_json_schema = "asperity-surface/3";

std::string analysis_json(const SurfaceAnalysis& analysis);
std::string analysis_summary(const SurfaceAnalysis& analysis);

struct ReportOutcome {
  std::vector<std::string> files;  // written
  bool plots = false;
  std::string plot_note;           // why there are no plots (a map at its noise floor)
};

// Every file a report can hold, in the folder's order.
inline constexpr const char* report_file_names[] = {"report.md",   "report.json", "summits.csv", "curves.csv",
                                                    "fits.svg",    "contact.svg", "law.svg"};

// The report folder's outputs under the output policy (asperity/output.hpp), checked: call it
// before the analysis, so that nothing is computed for a folder that cannot take the report (a
// file of the user's where a report file goes, a link, a FIFO; `input` is never written over).
OutputPlan report_plan(const std::string& directory, const std::string& input, bool overwrite = false);

// Writes the report folder under the output policy: the files staged and renamed into place
// together, no link followed, no special file opened, a file of the user's never replaced
// (unless `overwrite`), an earlier report's files that this one does not write removed (only
// report files of ours). Creates the folder if needed; throws asperity::Error naming the file
// on a write error (a full disk), leaving the folder as it was.
ReportOutcome write_report(const SurfaceAnalysis& analysis, const std::string& directory, bool overwrite = false);

}  // namespace asperity::topography
