/* The C API's contact curves from C (C99): a measured surface's table (made by the fixture
 * cli_exact_table: asperity exact-contact --table) opened, queried, inverted, its card written;
 * the statuses of bad handles, NaN, out-of-range queries and the other kind of table; an
 * adhesive law's table (cli_adhesive_scene_generate: JKR): signed pressure, the pull-off, the
 * summit count, the card refused.
 *   test_c_api_contact_curves CONTACT_CURVES_TABLE ADHESIVE_TABLE */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"

#include "c_check.h"

int main(int argc, char **argv) {
  asperity_contact_curves *curves = NULL;
  asperity_contact_curves_info info;
  asperity_contact_curves_state state;
  char err[512];
  int i, status;
  size_t length = 0;
  char *card;
  if (argc != 3) {
    fprintf(stderr, "usage: test_c_api_contact_curves TABLE ADHESIVE_TABLE\n");
    return 2;
  }
  status = asperity_contact_curves_load(argv[1], &curves, err, sizeof err);
  if (status != ASPERITY_OK) {
    fprintf(stderr, "cannot load %s: %s\n", argv[1], err);
    return 1;
  }
  CHECK(asperity_contact_curves_get_info(curves, &info) == ASPERITY_OK);
  CHECK(info.nodes >= 3 && info.check_points >= 5 * (info.nodes - 1)); /* 5 checks an interval at least */
  CHECK(info.min_separation < info.max_separation && info.min_pressure < info.max_pressure);
  CHECK(info.safety_factor == 2 && info.max_rel_error[0] == 2 * info.measured_rel_error[0]);
  CHECK(info.solver_tolerance > 0 && info.contact_modulus == 1e11 && info.nominal_area > 0);
  CHECK(isfinite(info.mean_summit_height));

  /* the ends of the range: their pressures; between them, falling pressure and area */
  CHECK(fabs(asperity_contact_curves_pressure(curves, info.min_separation) / info.max_pressure - 1) < 1e-14);
  CHECK(fabs(asperity_contact_curves_pressure(curves, info.max_separation) / info.min_pressure - 1) < 1e-14);
  for (i = 1; i <= 100; ++i) {
    const double u0 = info.min_separation + (info.max_separation - info.min_separation) * (i - 1) / 100.0;
    const double u1 = info.min_separation + (info.max_separation - info.min_separation) * i / 100.0;
    const double p = asperity_contact_curves_pressure(curves, u1);
    CHECK(p < asperity_contact_curves_pressure(curves, u0));
    CHECK(asperity_contact_curves_stiffness(curves, u1) > 0);
    CHECK(asperity_contact_curves_area_fraction(curves, u1) <= asperity_contact_curves_area_fraction(curves, u0));
    /* the inverse */
    CHECK(fabs(asperity_contact_curves_separation(curves, p) - u1) <= 1e-12 * (info.max_separation - info.min_separation));
    CHECK(asperity_contact_curves_at_pressure(curves, p, &state) == ASPERITY_OK);
    CHECK(fabs(state.separation - u1) <= 1e-12 * (info.max_separation - info.min_separation));
    CHECK(asperity_contact_curves_at_separation(curves, u1, &state) == ASPERITY_OK);
    CHECK(state.pressure == p && state.separation == u1);
    CHECK(state.stiffness == asperity_contact_curves_stiffness(curves, u1));
  }

  /* statuses: outside the range, NaN, NULL */
  CHECK(asperity_contact_curves_at_separation(curves, info.max_separation * 2, &state) == ASPERITY_OUTSIDE_RANGE);
  CHECK(isnan(state.pressure) && isnan(state.stiffness) && isnan(state.area_fraction));
  CHECK(asperity_contact_curves_at_pressure(curves, info.max_pressure * 2, &state) == ASPERITY_OUTSIDE_RANGE);
  CHECK(isnan(state.separation));
  CHECK(asperity_contact_curves_at_separation(curves, NAN, &state) == ASPERITY_BAD_SEPARATION);
  CHECK(asperity_contact_curves_at_separation(NULL, 1e-7, &state) == ASPERITY_BAD_HANDLE);
  CHECK(asperity_contact_curves_at_separation(curves, 1e-7, NULL) == ASPERITY_BAD_HANDLE);
  CHECK(asperity_contact_curves_get_info(NULL, &info) == ASPERITY_BAD_HANDLE);
  CHECK(isnan(asperity_contact_curves_pressure(NULL, 1e-7)));
  CHECK(isnan(asperity_contact_curves_separation(curves, -1)));
  /* a measured surface's table: no tension, no count */
  CHECK(asperity_contact_curves_has_tension(curves) == 0 && asperity_contact_curves_has_tension(NULL) == 0);
  CHECK(isnan(asperity_contact_curves_pull_off_pressure(curves)) && isnan(asperity_contact_curves_pull_off_separation(curves)));
  CHECK(isnan(asperity_contact_curves_summit_count(curves, 0.5 * (info.min_separation + info.max_separation))));
  CHECK(isnan(asperity_contact_curves_summit_count(NULL, 1e-7)) && isnan(asperity_contact_curves_pull_off_pressure(NULL)));
  CHECK(isnan(asperity_contact_curves_summit_count_max_rel_error(curves)));
  CHECK(isnan(asperity_contact_curves_summit_count_max_rel_error(NULL)));

  /* the card: its size first, then into a buffer */
  status = asperity_contact_curves_pressure_overclosure_card(curves, info.min_pressure, info.max_pressure, 1e-3,
                                                             "calculix", "si", "test", NULL, 0, &length, err, sizeof err);
  CHECK(status == ASPERITY_OK && length > 100);
  card = malloc(length + 1);
  status = asperity_contact_curves_pressure_overclosure_card(curves, info.min_pressure, info.max_pressure, 1e-3,
                                                             "calculix", "si", "test", card, length + 1, &length, err,
                                                             sizeof err);
  CHECK(status == ASPERITY_OK && strstr(card, "PRESSURE-OVERCLOSURE=TABULAR") != NULL);
  free(card);
  status = asperity_contact_curves_pressure_overclosure_card(curves, info.min_pressure / 10, info.max_pressure, 1e-3,
                                                             "calculix", "si", NULL, NULL, 0, &length, err, sizeof err);
  CHECK(status == ASPERITY_BAD_PARAMETER && strstr(err, "serve pressures") != NULL);
  CHECK(asperity_contact_curves_pressure_overclosure_card(curves, info.min_pressure, info.max_pressure, 1e-3, "ansys",
                                                          "si", NULL, NULL, 0, &length, err,
                                                          sizeof err) == ASPERITY_BAD_NAME);
  asperity_contact_curves_close(curves);
  asperity_contact_curves_close(NULL);

  /* an adhesive law's table: tension, the pull-off, the inverse on the stable branch, the count */
  status = asperity_contact_curves_load(argv[2], &curves, err, sizeof err);
  CHECK(status == ASPERITY_OK);
  if (status == ASPERITY_OK) {
    double pull_p = asperity_contact_curves_pull_off_pressure(curves);
    double pull_u = asperity_contact_curves_pull_off_separation(curves);
    CHECK(asperity_contact_curves_has_tension(curves) == 1);
    CHECK(asperity_contact_curves_get_info(curves, &info) == ASPERITY_OK);
    CHECK(pull_p < 0 && info.min_pressure == pull_p && pull_u > info.min_separation && pull_u < info.max_separation);
    CHECK(asperity_contact_curves_stiffness(curves, pull_u) == asperity_contact_curves_stiffness(curves, pull_u));
    CHECK(fabs(asperity_contact_curves_pressure(curves, pull_u) - pull_p) <= 1e-12 * fabs(pull_p));
    CHECK(asperity_contact_curves_pressure(curves, info.max_separation) < 0);
    CHECK(fabs(asperity_contact_curves_separation(curves, pull_p / 2) - pull_u) > 0 &&
          asperity_contact_curves_separation(curves, pull_p / 2) < pull_u);
    CHECK(isnan(asperity_contact_curves_separation(curves, 1.01 * pull_p)));
    CHECK(asperity_contact_curves_summit_count(curves, info.min_separation) >
          asperity_contact_curves_summit_count(curves, info.max_separation));
    CHECK(asperity_contact_curves_summit_count(curves, info.max_separation) > 0);
    /* the count's own stored bound (issue 41, item 4): stated, positive, finite */
    CHECK(asperity_contact_curves_summit_count_max_rel_error(curves) > 0 &&
          asperity_contact_curves_summit_count_max_rel_error(curves) < 1e-3);
    status = asperity_contact_curves_pressure_overclosure_card(curves, pull_p, info.max_pressure, 1e-3, "calculix",
                                                               "si", NULL, NULL, 0, &length, err, sizeof err);
    CHECK(status != ASPERITY_OK && strstr(err, "tension") != NULL);
    asperity_contact_curves_close(curves);
  }

  /* loading: missing, the other kind, NULL */
  CHECK(asperity_contact_curves_load("/nonexistent/curves.h5", &curves, err, sizeof err) == ASPERITY_FILE_MISSING);
  CHECK(curves == NULL);
  CHECK(asperity_contact_curves_load(ASPERITY_TEST_TABLE, &curves, err, sizeof err) == ASPERITY_OTHER_SCHEMA);
  CHECK(curves == NULL && strstr(err, "Greenwood-Williamson") != NULL);
  CHECK(asperity_contact_curves_load(NULL, &curves, err, sizeof err) == ASPERITY_BAD_HANDLE);
  {
    asperity_table *table = NULL;
    CHECK(asperity_table_load(argv[1], &table, err, sizeof err) == ASPERITY_OTHER_SCHEMA);
    CHECK(table == NULL && strstr(err, "contact curves") != NULL);
  }
  if (failures) fprintf(stderr, "%d checks failed\n", failures);
  return failures ? 1 : 0;
}
