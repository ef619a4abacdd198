// The analysis written out: JSON for programs (schema "asperity-surface/1"), a short summary for
// the terminal, and a report directory (Markdown with the plots, JSON, CSV of the curves and of
// the summits, plots as SVG and PNG drawn by topography/scripts/surface_plots.py with
// matplotlib; without python3 or matplotlib the report is still written and says so).
#pragma once
#include <string>
#include <vector>

#include "asperity/topography/analysis.hpp"

namespace asperity::topography {

std::string analysis_json(const SurfaceAnalysis& analysis);
std::string analysis_summary(const SurfaceAnalysis& analysis);

struct ReportOutcome {
  std::vector<std::string> files;  // written
  bool plots = false;
  std::string plot_note;           // why there are no plots, when there are none
};

// Creates the directory if needed; throws asperity::Error on a write error. `plot_script`
// empty: $ASPERITY_SURFACE_PLOTS if set, else the script in the source tree.
ReportOutcome write_report(const SurfaceAnalysis& analysis, const std::string& directory,
                           const std::string& plot_script = {});

}  // namespace asperity::topography
