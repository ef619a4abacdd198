// What to do next with a surface's analysis: for the model the verdict names for the contact, the
// `asperity contact` command line and the Python call with its fitted parameters and its FE card's
// command; for the map itself, the exact-contact command that tabulates its curves (what every
// model is judged against); where no model is named, why, and what to use instead. The summary,
// report.md and report.json end with it.
#pragma once
#include <optional>
#include <string>

#include "asperity/topography/analysis.hpp"

namespace asperity::topography {

struct NextSteps {
  bool model_named = false;     // the verdict named a model for the contact
  std::optional<ContactModelKind> model;  // that model (contact_model_name: "weibull-tail"), none when none
  std::string why;              // why this model, or why none is named
  std::string contact_command;  // `asperity contact ...` on the model's surface (empty: none named, or no E*)
  std::string python;           // the same surface and model in Python
  std::string card_command;     // its pressure-overclosure card for CalculiX
  std::string exact_command;    // the map's exact contact tabulated (a contact-curves table) and its card
  std::string instead;          // where no model is named: what to use instead
  std::string text;             // all of it in words, for the summary and report.md
};

// The next steps of an analysis. Commands need the contact modulus (AnalysisOptions::contact);
// without it they are left empty and `text` says so. Numbers in shortest round-trip form, so a
// command reproduces the report's curves.
NextSteps next_steps(const SurfaceAnalysis& analysis);

}  // namespace asperity::topography
