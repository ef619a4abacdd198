#include "asperity/topography/surface_verdict.hpp"

#include "asperity/integrals.hpp"
#include "asperity/number_text.hpp"

namespace asperity::topography {

SurfaceVerdict surface_verdict(const SurfaceEvidence& evidence) {
  SurfaceVerdict v;
  if (!evidence.no_verdict.empty()) {
    v.text = "no verdict: " + evidence.no_verdict;
    return v;
  }
  if (!evidence.summit_heights) return v;
  const SampleAssessment& S = *evidence.summit_heights;
  const SampleAssessment* H = evidence.heights;
  if (S.models.size() != 3) return v;
  const double significance = S.options.significance;
  v.tested = S.options.bootstrap > 0;
  const ModelAssessment& gs = S.model(HeightModel::gaussian);
  v.p_summits = gs.anderson_darling_p;
  v.p_summits_bound = gs.p_at_floor;
  if (H) {
    v.p_heights = H->model(HeightModel::gaussian).anderson_darling_p;
    v.p_heights_bound = H->model(HeightModel::gaussian).p_at_floor;
  }
  const auto p = [](double value, bool bound) { return p_value_text(value, bound); };
  std::string text;
  if (!v.tested) {
    text = "Is it Gaussian? Not tested (no surrogate surfaces: --ensemble 0).";
  } else {
    const double half = significance / 2;
    const bool heights_reject = H && v.p_heights < half, summits_reject = v.p_summits < half;
    v.gaussian_rejected = heights_reject || summits_reject;
    // each test's answer in words, then which decides: either one rejecting (no contradiction
    // when one rejects and the other does not)
    const auto says = [&](const char* sample, double p_value, bool bound, bool rejects) {
      return std::string(sample) + (rejects ? " reject it (" : " do not (") + p(p_value, bound) + ")";
    };
    text = std::string("Is it Gaussian? ") + (v.gaussian_rejected ? "No" : "Not rejected") + ": against " +
           std::to_string(evidence.surrogates) + " Gaussian surfaces of the map's own spectrum, ";
    if (H) text += says("its heights", v.p_heights, v.p_heights_bound, heights_reject) + " and ";
    text += says("its summit heights", v.p_summits, v.p_summits_bound, summits_reject) +
            " (Anderson-Darling, each at " + three_digits(100 * half) + "%: either one rejecting decides, so that the "
            "verdict's size is " + three_digits(100 * significance) + "%).";
  }
  // the orientation from the heights' marginal
  if (H) {
    int best = -1;
    for (HeightModel model : {HeightModel::weibull_tail, HeightModel::weibull_bounded}) {
      const ModelAssessment& m = H->model(model);
      if ((v.tested && m.rejected) || !m.shape_identified) continue;
      if (best < 0 || m.aic < H->models[static_cast<std::size_t>(best)].aic) best = static_cast<int>(model);
    }
    if (best >= 0) {
      v.orientation = static_cast<HeightModel>(best);
      const ModelAssessment& m = H->models[static_cast<std::size_t>(best)];
      text += std::string(" The heights lean ") + (v.orientation == HeightModel::weibull_tail ? "tail up" : "bounded above") +
              " (" + describe(v.orientation) + ", a = " + three_digits(m.fit.distribution.shape) + " [" +
              three_digits(m.shape.lo) + ", " + three_digits(m.shape.hi) + "]).";
    } else {
      text += " Neither Weibull describes the heights (rejected or its shape not identified).";
    }
  }
  // the model named for the contact: from the summit heights, what GW integrates
  std::string reasons;
  int named = -1;
  for (HeightModel model : all_height_models) {
    const ModelAssessment& m = S.model(model);
    std::string why;
    if (model == HeightModel::gaussian && v.gaussian_rejected)
      why = std::string("the surface is not Gaussian (") +
            (H && v.p_heights < significance / 2 ? "its heights' test" : "its summit heights' test") + ")";
    else if (v.tested && m.rejected) why = "rejected on the summit heights (" + p(m.anderson_darling_p, m.p_at_floor) + ")";
    else if (!m.shape_identified) why = "its shape is " + m.identification;
    else if (evidence.has_contact_curves) {
      if (!evidence.has_contact_curves(model)) why = "it has no contact curves";
    } else if (model != HeightModel::gaussian && !(m.fit.distribution.shape >= weibull_shape_min && m.fit.distribution.shape <= weibull_shape_max)) {
      why = "its shape is outside what the tables serve (" + format_double(weibull_shape_min) + " to " +
            format_double(weibull_shape_max) + ")";
    }
    if (!why.empty()) {
      reasons += std::string(reasons.empty() ? "" : "; ") + describe(model) + ": " + why;
      continue;
    }
    if (named < 0 || m.aic < S.models[static_cast<std::size_t>(named)].aic) named = static_cast<int>(model);
  }
  if (named >= 0) {
    v.named = true;
    v.model = static_cast<HeightModel>(named);
    const ModelAssessment& m = S.models[static_cast<std::size_t>(named)];
    text += std::string(" For the contact (the summit heights, what GW integrates): ") + describe(v.model);
    if (v.model != HeightModel::gaussian)
      text += ", a = " + three_digits(m.fit.distribution.shape) + " [" + three_digits(m.shape.lo) + ", " +
              three_digits(m.shape.hi) + "]";
    text += " (" + (v.tested ? p(m.anderson_darling_p, m.p_at_floor) : std::string("not tested")) + ", Akaike weight " +
            three_digits(m.akaike_weight) + ").";
    if (H && v.orientation != HeightModel::gaussian && v.model != HeightModel::gaussian && v.model != v.orientation)
      text += " Its orientation is not the heights': the summits alone can mislead about it.";
  } else {
    text += " No model is named for the contact";
  }
  if (!reasons.empty()) text += (named >= 0 ? " Not named: " : ": ") + reasons + ".";
  else if (named < 0) text += ".";
  if (!evidence.contact_headline.empty()) text += " " + evidence.contact_headline + ".";
  v.text = text;
  return v;
}

}  // namespace asperity::topography
