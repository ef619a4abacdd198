/* The C API from C (compiled as C99): open, evaluate, batch, physical quantities, errors. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "asperity/asperity.h"

static int failures = 0;
#define CHECK(condition)                                                   \
  do {                                                                     \
    if (!(condition)) {                                                    \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #condition); \
      ++failures;                                                          \
    }                                                                      \
  } while (0)

int main(void) {
  char err[512];
  asperity_table *table = asperity_table_open(NULL, err, sizeof err);
  CHECK(table != NULL);
  if (!table) return 1;

  asperity_curve *curve = asperity_curve_open(table, "weibull", "tail", 2.0, err, sizeof err);
  CHECK(curve != NULL);
  /* J_1(0) = Gamma(3/2) for a = 2 */
  CHECK(fabs(asperity_eval(curve, 2, 0.0) - 0.88622692545275801) < 1e-14);
  CHECK(fabs(asperity_eval_log(curve, 0, 3.0) + 9.0) < 1e-13); /* ln J_0 = -s^2 */
  CHECK(isnan(asperity_eval(curve, 6, 1.0)));
  CHECK(isnan(asperity_eval(curve, 0, NAN)));
  CHECK(isnan(asperity_eval(NULL, 0, 1.0)));

  double sep[4] = {-1.0, 0.0, 1.0, 40.0}, out[4];
  CHECK(asperity_eval_batch(curve, 3, sep, out, 4) == ASPERITY_OK);
  CHECK(out[1] == asperity_eval(curve, 3, 0.0));
  CHECK(out[3] == 0.0); /* underflow to exactly 0 */
  sep[2] = INFINITY;
  CHECK(asperity_eval_batch(curve, 3, sep, out, 4) == ASPERITY_BAD_SEPARATION);
  CHECK(isnan(out[2]));
  CHECK(asperity_eval_batch(curve, 9, sep, out, 4) == ASPERITY_BAD_ORDER);
  CHECK(asperity_eval_batch(NULL, 3, sep, out, 4) == ASPERITY_BAD_HANDLE);

  asperity_contact_state state;
  CHECK(asperity_contact(curve, 100.0, 1e-4, 1e-6, 1e11, 1.0, &state) == ASPERITY_OK);
  CHECK(state.load > 0 && state.stiffness > 0 && state.area > 0 && state.count > 0);
  CHECK(asperity_contact(curve, -1.0, 1e-4, 1e-6, 1e11, 1.0, &state) == ASPERITY_BAD_PARAMETER);
  CHECK(isnan(state.load));
  CHECK(fabs(asperity_origin_from_standardized(curve, asperity_standardized_from_origin(curve, 1.3)) - 1.3) < 1e-14);

  CHECK(asperity_curve_open(table, "weibull", "tail", 100.0, err, sizeof err) == NULL);
  CHECK(strstr(err, "outside") != NULL);
  CHECK(asperity_curve_open(table, "beta", "tail", 2.0, err, sizeof err) == NULL);
  CHECK(strstr(err, "unknown dist") != NULL);
  CHECK(asperity_curve_open(table, "gaussian", "bounded", 0.0, err, sizeof err) == NULL);
  CHECK(asperity_table_open("/nonexistent.h5", err, sizeof err) == NULL);
  CHECK(strstr(err, "no such file") != NULL);
  CHECK(asperity_table_open("/nonexistent.h5", NULL, 0) == NULL); /* no buffer: still safe */
  CHECK(strlen(asperity_version()) > 0);
  CHECK(strcmp(asperity_status_string(ASPERITY_OK), "ok") == 0);

  /* the physical layer: a load and back */
  {
    const double modulus = asperity_contact_modulus(2.1e11, 0.3, 2.1e11, 0.3);
    asperity_physical_state forward, inverse;
    asperity_model *model;
    CHECK(fabs(modulus - 2.1e11 / 1.82) < 1e-3);
    CHECK(isnan(asperity_contact_modulus(-1.0, 0.3, 1.0, 0.3)));
    model = asperity_model_open(table, "weibull", "tail", 2.0, 1e-6, 1e-4, 1e10, 1e-4, modulus, err, sizeof err);
    CHECK(model != NULL);
    if (model) {
      CHECK(asperity_model_at_separation(model, 3e-6, &forward) == ASPERITY_OK);
      CHECK(forward.load > 0 && forward.real_area > 0 && forward.stiffness_over_load > 0);
      CHECK(asperity_model_at_load(model, forward.load, &inverse) == ASPERITY_OK);
      CHECK(fabs(inverse.separation - 3e-6) < 1e-15);
      CHECK(asperity_model_at_pressure(model, forward.pressure, &inverse) == ASPERITY_OK);
      CHECK(fabs(inverse.load - forward.load) < 1e-11 * forward.load);
      CHECK(asperity_model_at_real_area(model, forward.real_area, &inverse) == ASPERITY_OK);
      CHECK(fabs(inverse.separation - 3e-6) < 1e-15);
      CHECK(asperity_model_at_load(model, NAN, &inverse) == ASPERITY_BAD_SEPARATION);
      CHECK(isnan(inverse.separation));
      CHECK(asperity_model_at_load(NULL, 1.0, &inverse) == ASPERITY_BAD_HANDLE);
      asperity_model_close(model);
    }
    CHECK(asperity_model_open(table, "weibull", "tail", 2.0, -1e-6, 1e-4, 1e10, 1e-4, modulus, err, sizeof err) == NULL);
    CHECK(strstr(err, "height scale") != NULL);
    asperity_model_close(NULL);
  }

  asperity_curve_close(curve);
  asperity_curve_close(NULL);
  asperity_table_close(table);
  asperity_table_close(NULL);
  if (failures == 0) printf("test_c_api: all checks passed\n");
  return failures == 0 ? 0 : 1;
}
