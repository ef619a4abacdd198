/* An adhesive law's withdrawal table through the C API (C99; issue 41, item 2): the JKR surface
 * of tables/scenes/jkr.toml tabulated on its approach branch (fixture cli_adhesive_scene_generate)
 * and on its withdrawal branch after an approach to s0 = -1 (tables/scenes/jkr-withdrawal.toml,
 * fixture cli_withdrawal_scene_generate), both served like any contact curves. The branch is
 * told by asperity_contact_curves_approach_separation (finite: withdrawal, NaN: approach); the
 * values against the loading table (equal at s0, more tension after it) and against closed forms
 * computed here, not by the library: the count before the kink (every summit that touched at s0,
 * eta erfc(s0/sqrt 2)/2), where the kink is (s0 sigma_s + delta_c, JKR's
 * delta_c = (3/4)(pi^2 dgamma^2 R/E*^2)^(1/3)) and the stiffness's jump there (summits leaving at
 * the fixed-grips end, JKR's load -(5/6) pi dgamma R: eta phi(s0)/sigma_s times it).
 *   test_c_api_withdrawal APPROACH_TABLE WITHDRAWAL_TABLE */
#include <math.h>
#include <stdio.h>

#include "asperity/asperity.h"

#include "c_check.h"

/* the scenes' surface and material (tables/scenes/jkr.toml) */
static const double modulus = 1.13e11, work = 0.5, radius = 1e-4, sigma = 2e-9, density = 4e8, s0 = -1;

static asperity_contact_curves *load(const char *path) {
  asperity_contact_curves *curves = NULL;
  char err[512];
  if (asperity_contact_curves_load(path, &curves, err, sizeof err) != ASPERITY_OK) {
    fprintf(stderr, "cannot load %s: %s\n", path, err);
    ++failures;
  }
  return curves;
}

int main(int argc, char **argv) {
  asperity_contact_curves *approach, *withdrawal;
  asperity_contact_curves_info a, w;
  const double pi = 3.14159265358979323846;
  const double delta_c = 0.75 * cbrt(pi * pi * work * work * radius / (modulus * modulus));
  const double u0 = s0 * sigma, kink = u0 + delta_c;
  const double touched = density * 0.5 * erfc(s0 / sqrt(2.0));
  double u, count_error = 0, left, right, jump, expected_jump;
  int i;
  if (argc != 3) {
    fprintf(stderr, "usage: test_c_api_withdrawal APPROACH_TABLE WITHDRAWAL_TABLE\n");
    return 2;
  }
  approach = load(argv[1]);
  withdrawal = load(argv[2]);
  if (!approach || !withdrawal) return 1;
  CHECK(asperity_contact_curves_get_info(approach, &a) == ASPERITY_OK);
  CHECK(asperity_contact_curves_get_info(withdrawal, &w) == ASPERITY_OK);

  /* the branch: stated by the table, readable */
  CHECK(isnan(asperity_contact_curves_approach_separation(approach)));
  CHECK(asperity_contact_curves_approach_separation(withdrawal) == u0);
  CHECK(w.min_separation == u0 && a.min_separation == u0 && w.max_separation == a.max_separation);
  CHECK(isnan(asperity_contact_curves_approach_separation(NULL)));
  CHECK(asperity_contact_curves_has_tension(withdrawal) == 1);

  /* at s0 both branches are the same state: equal within the two stored bounds (relative to the gross;
     at s0 the net is mostly compressive, so relative to the net with a margin of 2) */
  CHECK(fabs(asperity_contact_curves_pressure(withdrawal, u0) / asperity_contact_curves_pressure(approach, u0) - 1) <=
        2 * (w.max_rel_error[0] + a.max_rel_error[0]));
  CHECK(fabs(asperity_contact_curves_area_fraction(withdrawal, u0) / asperity_contact_curves_area_fraction(approach, u0) -
             1) <= w.max_rel_error[2] + a.max_rel_error[2]);
  /* after it the withdrawal holds the summits that left on loading: more area, more tension */
  for (i = 1; i <= 50; ++i) {
    u = u0 + (w.max_separation - u0) * i / 50.0;
    CHECK(asperity_contact_curves_pressure(withdrawal, u) < asperity_contact_curves_pressure(approach, u));
    CHECK(asperity_contact_curves_area_fraction(withdrawal, u) > asperity_contact_curves_area_fraction(approach, u));
    CHECK(asperity_contact_curves_summit_count(withdrawal, u) >= asperity_contact_curves_summit_count(approach, u));
    if (u < kink) {
      double e = fabs(asperity_contact_curves_summit_count(withdrawal, u) / touched - 1);
      if (e > count_error) count_error = e;
    }
  }
  /* Fuller-Tabor's pull-off (after the approach) is greater than the loading branch's */
  CHECK(asperity_contact_curves_pull_off_pressure(withdrawal) < asperity_contact_curves_pull_off_pressure(approach));
  CHECK(w.min_pressure == asperity_contact_curves_pull_off_pressure(withdrawal));
  /* the inverse on the withdrawal's stable part */
  u = 0.5 * (u0 + asperity_contact_curves_pull_off_separation(withdrawal));
  CHECK(fabs(asperity_contact_curves_separation(withdrawal, asperity_contact_curves_pressure(withdrawal, u)) - u) <=
        1e-9 * (w.max_separation - w.min_separation));

  /* the count up to the kink: every summit that touched at s0, within the count's stored bound */
  printf("count before the kink against eta erfc(s0/sqrt 2)/2: %.2e (stored bound %.2e)\n", count_error,
         asperity_contact_curves_summit_count_max_rel_error(withdrawal));
  CHECK(count_error <= asperity_contact_curves_summit_count_max_rel_error(withdrawal));
  /* the kink at s0 sigma_s + delta_c, the stiffness jumping there by eta phi(s0)/sigma_s (-(5/6) pi dgamma R):
     1e-14 of the span either side (some hundred ulps: the table's kink is rounded its own way; left of it the
     stiffness varies as the root of the distance, 1e-7 of it there) */
  right = asperity_contact_curves_stiffness(withdrawal, kink + 1e-14 * (w.max_separation - u0));
  left = asperity_contact_curves_stiffness(withdrawal, kink - 1e-14 * (w.max_separation - u0));
  jump = right - left;
  expected_jump = density * exp(-0.5 * s0 * s0) / sqrt(2 * pi) / sigma * (-5.0 / 6 * pi * work * radius);
  printf("stiffness jump at the kink %.17g Pa/m against %.17g (%.2e; stored stiffness bound %.2e of the gross)\n", jump,
         expected_jump, fabs(jump / expected_jump - 1), w.max_rel_error[1]);
  CHECK(fabs(jump / expected_jump - 1) < 1e-5);
  /* right of the kink the stiffness is continuous (the one break is there) */
  CHECK(fabs(asperity_contact_curves_stiffness(withdrawal, kink + 1e-6 * (w.max_separation - u0)) / right - 1) < 1e-3);

  asperity_contact_curves_close(approach);
  asperity_contact_curves_close(withdrawal);
  if (failures) fprintf(stderr, "%d checks failed\n", failures);
  return failures ? 1 : 0;
}
