// The analysis written out: JSON for programs (schema "asperity-surface/2"), a short summary for
// the terminal, and a report folder (Markdown with the plots, JSON, CSV of the curves and of the
// summits, plots as SVG drawn by the library itself: no program is run).
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
  std::string plot_note;           // why there are no plots (a map at its noise floor)
};

// Writes the report folder as tables are written (each file replaced atomically, no link
// followed, no special file opened, one run at a time, an earlier run's files not left beside
// this one's; docs/reliability.md). Creates the folder if needed; throws asperity::Error naming
// the file on a write error (a full disk), leaving each file the old or the new one, whole.
ReportOutcome write_report(const SurfaceAnalysis& analysis, const std::string& directory);

}  // namespace asperity::topography
