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

// Its fields defined once (record_fields.hpp): report.json's next_steps, Python's NextSteps
#define ASPERITY_NEXT_STEPS_FIELDS(X)                                                                          \
  X(bool, model_named, "model_named", "the verdict named a model for the contact")                            \
  X(std::optional<ContactModelKind>, model, "model", "the named model (\"weibull-tail\"), empty when none") \
  X(std::string, why, "why", "why this model, or why none is named")                                         \
  X(std::string, contact_command, "contact_command",                                                         \
    "`asperity contact ...` on the model's surface (empty: none named, or no E*)")                            \
  X(std::string, python, "python", "Python code building the named model's ContactModel")                    \
  X(std::string, card_command, "card_command", "its pressure-overclosure card for CalculiX")                 \
  X(std::string, exact_command, "exact_command", "the map's exact contact tabulated (a contact-curves table) and its card") \
  X(std::string, instead, "instead", "where no model is named: what to use instead")                          \
  X(std::string, text, "text", "all of it in words, for the summary and report.md")

struct NextSteps {
  ASPERITY_NEXT_STEPS_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// The next steps of an analysis. Commands need the contact modulus (AnalysisOptions::contact);
// without it they are left empty and `text` says so. Numbers in shortest round-trip form, so a
// command reproduces the report's curves.
NextSteps next_steps(const SurfaceAnalysis& analysis);

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::NextSteps, ASPERITY_NEXT_STEPS_FIELDS)
}  // namespace asperity
