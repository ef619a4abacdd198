// The verdict on a whole surface from its two tested samples (surface_tests.hpp): is it
// Gaussian, which way do its heights lean, and which model the contact should use.
#pragma once
#include <cstddef>
#include <functional>
#include <string>

#include "asperity/topography/goodness_of_fit.hpp"

namespace asperity::topography {

// What the evidence says, for the surface as a whole (docs/surfaces.md, section 4):
//   Is it Gaussian? The heights' test and the summit heights' test, each at half the
//   significance (Bonferroni: the verdict's size stays at most the significance). Either
//   rejecting says "not Gaussian".
//   Which Weibull? The heights give the orientation (their marginal is what a wear process
//   bounds); the summit heights give the law GW integrates. The verdict names a model for the
//   contact only if it is not rejected on the summit heights, its shape is identified, and it
//   has contact curves (or, without a modulus, a shape scene tables serve).
struct SurfaceVerdict {
  bool tested = false;                 // an ensemble was run
  bool gaussian_rejected = false;
  double p_heights = 0, p_summits = 0;  // the Gaussian's Anderson-Darling p on each sample
  bool p_heights_bound = false, p_summits_bound = false;  // p at its floor 1/(B + 1): a bound
  HeightModel orientation = HeightModel::gaussian;  // the heights' Weibull, or gaussian: no orientation found
  bool named = false;                  // a model for the contact is named
  HeightModel model = HeightModel::gaussian;
  std::string text;
};

// What the verdict is drawn from.
struct SurfaceEvidence {
  const SampleAssessment* summit_heights = nullptr;  // required: what GW integrates
  const SampleAssessment* heights = nullptr;         // the marginal, when it was tested
  std::size_t surrogates = 0;                        // the ensemble's size
  std::string no_verdict;  // not empty: why there is no verdict (a map at its noise floor)
  // Whether a model has contact curves; empty when no contact was computed (then a Weibull is
  // named only where the scene tables serve its shape)
  std::function<bool(HeightModel)> has_contact_curves;
  std::string contact_headline;  // the contact comparison's headline, appended when not empty
};

SurfaceVerdict surface_verdict(const SurfaceEvidence& evidence);

}  // namespace asperity::topography
