#include "asperity/topography/surface_verdict.hpp"

#include <cmath>
#include <cstdio>

#include "asperity/integrals.hpp"
#include "asperity/number_text.hpp"

namespace asperity::topography {
namespace {

const char* side_name(HeightModel side) { return side == HeightModel::weibull_tail ? "tail up" : "bounded above"; }

HeightModel other_side(HeightModel side) {
  return side == HeightModel::weibull_tail ? HeightModel::weibull_bounded : HeightModel::weibull_tail;
}

std::string interval_text(const ModelAssessment& m) {
  return three_digits(m.fit.distribution.shape) + " [" + three_digits(m.shape.lo) + ", " + three_digits(m.shape.hi) + "]";
}

// Whether the shape interval is informative: finite, positive, at most side_interval_ratio_max wide.
bool interval_determined(const ModelAssessment& m) {
  return m.shape.lo > 0 && std::isfinite(m.shape.hi) && m.shape.hi <= side_interval_ratio_max * m.shape.lo;
}

// The other side is out of the running: rejected by its test, or its fit degenerate (its shape at
// the fit's bound: the family leaves its own side, e.g. a bounded-above Weibull whose bound runs off
// to infinity as its shape grows).
bool excluded(const ModelAssessment& m, double significance) {
  return m.anderson_darling_p < significance || m.fit.shape_at_bound;
}

struct Side {
  bool told = false;
  HeightModel side = HeightModel::gaussian;
  std::string why_not;  // when not told
};

// The side of `sample` (side_rule): `gaussian_rejected`, whether this sample's own Gaussian test
// rejected at the verdict's level for it.
Side tell_side(const SampleAssessment& sample, bool gaussian_rejected, double significance) {
  Side result;
  if (!gaussian_rejected) {
    result.why_not = "the " + sample.name + " do not reject a Gaussian, so neither side departs from it";
    return result;
  }
  std::string why;
  int told = -1;
  for (HeightModel side : {HeightModel::weibull_tail, HeightModel::weibull_bounded}) {
    const ModelAssessment& m = sample.model(side);
    const ModelAssessment& o = sample.model(other_side(side));
    std::string fails;
    if (m.rejected) fails = "rejected (" + p_value_text(m.anderson_darling_p, m.p_at_floor) + ")";
    else if (!m.shape_identified) fails = "its shape not identified";
    else if (!interval_determined(m))
      fails = "its shape " + interval_text(m) + " not determined (the interval spans over " +
              format_double(side_interval_ratio_max) + " times)";
    else if (!excluded(o, significance))
      fails = std::string("not told from ") + side_name(other_side(side)) + " (" + interval_text(o) + ", " +
              p_value_text(o.anderson_darling_p, o.p_at_floor) + ": not rejected)";
    if (fails.empty()) {
      // both sides pass only if each excludes the other, which cannot be: a rejected side fails
      told = static_cast<int>(side);
    } else {
      why += std::string(why.empty() ? "" : "; ") + side_name(side) + ": " + fails;
    }
  }
  if (told < 0) {
    result.why_not = why;
    return result;
  }
  result.told = true;
  result.side = static_cast<HeightModel>(told);
  return result;
}

}  // namespace

std::string summit_test_rule() {
  return "the summit heights' test speaks with at least " + std::to_string(min_summits_to_test) +
         " summits; below, it is not applicable and the heights' test alone decides, at half the significance as "
         "when both speak";
}

std::string side_rule() {
  return "a side is told when the heights reject a Gaussian, its Weibull is neither rejected nor of an unidentified "
         "shape, its shape interval spans at most " + format_double(side_interval_ratio_max) +
         " times (hi/lo), and the other side is rejected or its fit degenerate (its shape at the fit's bound); "
         "otherwise the side cannot be told from the map";
}

SurfaceVerdict surface_verdict(const SurfaceEvidence& evidence) {
  SurfaceVerdict v;
  if (!evidence.no_verdict.empty()) {
    v.text = "no verdict: " + evidence.no_verdict;
    v.side_note = "the side cannot be told from this map: no verdict";
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
  // issue 40, item 2: below min_summits_to_test the summit heights' test has no power to speak of
  v.summit_test_applicable = S.n >= min_summits_to_test;
  if (!v.summit_test_applicable)
    v.summit_test_note = "not applicable: " + std::to_string(S.n) + " summits, fewer than the " +
                         std::to_string(min_summits_to_test) +
                         " the summit heights' test needs to have power (docs/surfaces.md); it carries no weight";
  const auto p = [](double value, bool bound) { return p_value_text(value, bound); };
  std::string text;
  // each test that speaks at half the significance (Bonferroni over the two samples); a summit test
  // that cannot speak drops out and leaves the heights' level as it was: at the whole significance
  // the heights' test alone rejected 12/173 small Gaussian maps (6.9% [3.6, 11.8]) against 6/173 at
  // half (docs/surfaces.md), for 92% against 89% of the Weibull maps
  const int speaking = (H ? 1 : 0) + (v.summit_test_applicable ? 1 : 0);
  const double level = significance / 2;
  bool heights_reject = false, summits_reject = false;
  if (!v.tested) {
    text = "Is it Gaussian? Not tested (no surrogate surfaces: --ensemble 0).";
  } else if (speaking == 0) {
    text = "Is it Gaussian? Cannot be told: the heights were not tested and the summit heights' test is " +
           v.summit_test_note + ".";
  } else {
    heights_reject = H && v.p_heights < level;
    summits_reject = v.summit_test_applicable && v.p_summits < level;
    v.gaussian_rejected = heights_reject || summits_reject;
    // each test's answer in words, then which decides: either one rejecting (no contradiction
    // when one rejects and the other does not)
    const auto says = [&](const char* sample, double p_value, bool bound, bool rejects) {
      return std::string(sample) + (rejects ? " reject it (" : " do not (") + p(p_value, bound) + ")";
    };
    text = std::string("Is it Gaussian? ") + (v.gaussian_rejected ? "No" : "Not rejected") + ": against " +
           std::to_string(evidence.surrogates) + " Gaussian surfaces of the map's own spectrum, ";
    if (speaking == 2) {
      text += says("its heights", v.p_heights, v.p_heights_bound, heights_reject) + " and " +
              says("its summit heights", v.p_summits, v.p_summits_bound, summits_reject) +
              " (Anderson-Darling, each at " + three_digits(100 * level) +
              "%: either one rejecting decides, so that the verdict's size is " + three_digits(100 * significance) + "%).";
    } else if (H) {
      text += says("its heights", v.p_heights, v.p_heights_bound, heights_reject) + " (Anderson-Darling at " +
              three_digits(100 * level) + "%, so that the verdict's size stays within " + three_digits(100 * significance) +
              "%); the summit heights' test is " + v.summit_test_note + " (" + p(v.p_summits, v.p_summits_bound) + ").";
    } else {
      text += says("its summit heights", v.p_summits, v.p_summits_bound, summits_reject) + " (Anderson-Darling at " +
              three_digits(100 * level) + "%).";
    }
  }
  // issue 40, item 3: the side, from the heights' marginal (the summit heights' only when the heights
  // were not tested and their test speaks), told only where the data determine it
  const SampleAssessment* side_sample = H ? H : (v.summit_test_applicable ? &S : nullptr);
  Side side;
  if (!v.tested) side.why_not = "not tested (no surrogate surfaces)";
  else if (!side_sample) side.why_not = "the heights were not tested and the summit heights' test does not speak";
  else side = tell_side(*side_sample, H ? heights_reject : summits_reject, significance);
  v.side_told = side.told;
  if (side.told) {
    v.orientation = side.side;
    const ModelAssessment& m = side_sample->model(side.side);
    v.side_note = std::string(side_name(side.side)) + ", told from the " + side_sample->name;
    text += std::string(" The ") + (H ? "heights lean " : "summit heights lean ") + side_name(side.side) + " (" +
            describe(side.side) + ", a = " + interval_text(m) + "; " + side_name(other_side(side.side)) + " " +
            (side_sample->model(other_side(side.side)).fit.shape_at_bound ? "degenerate" : "rejected") + ").";
  } else {
    v.side_note = "the side cannot be told from this map: " + side.why_not;
    text += " The side cannot be told from this map (" + side.why_not + ").";
  }
  // the model named for the contact: from the summit heights, what GW integrates
  std::string reasons;
  int named = -1;
  for (HeightModel model : all_height_models) {
    const ModelAssessment& m = S.model(model);
    std::string why;
    if (model == HeightModel::gaussian && v.gaussian_rejected)
      why = std::string("the surface is not Gaussian (") + (heights_reject ? "its heights' test" : "its summit heights' test") + ")";
    else if (model != HeightModel::gaussian && !v.side_told) why = "the side cannot be told from this map";
    else if (model != HeightModel::gaussian && model != v.orientation)
      why = std::string("not the side the ") + (H ? "heights" : "summit heights") + " tell";
    else if (v.tested && v.summit_test_applicable && m.rejected)
      why = "rejected on the summit heights (" + p(m.anderson_darling_p, m.p_at_floor) + ")";
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
    if (v.model != HeightModel::gaussian) text += ", a = " + interval_text(m);
    text += " (" +
            (v.tested && v.summit_test_applicable ? p(m.anderson_darling_p, m.p_at_floor)
             : v.tested                           ? std::string("its test not applicable")
                                                  : std::string("not tested")) +
            ", Akaike weight " + three_digits(m.akaike_weight) + ").";
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
