/* The C API from C (compiled as C99): open, evaluate, batch, physical quantities, errors. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"

#include "c_check.h"

/* The default table's bytes, or NULL. */
static char *read_file(const char *path, size_t *size) {
  FILE *file = fopen(path, "rb");
  char *bytes;
  long length;
  if (!file) return NULL;
  fseek(file, 0, SEEK_END);
  length = ftell(file);
  fseek(file, 0, SEEK_SET);
  bytes = malloc((size_t)length);
  if (bytes && fread(bytes, 1, (size_t)length, file) != (size_t)length) {
    free(bytes);
    bytes = NULL;
  }
  fclose(file);
  *size = (size_t)length;
  return bytes;
}

static void write_file(const char *path, const char *bytes, size_t size) {
  FILE *file = fopen(path, "wb");
  if (!file) return;
  fwrite(bytes, 1, size, file);
  fclose(file);
}

/* asperity_table_load tells why a file was refused, as a status. */
static void table_statuses(void) {
  char err[512], path[512];
  asperity_table *table = (asperity_table *)1;
  size_t size = 0, i;
  char *bytes = read_file(ASPERITY_TEST_TABLE, &size);
  CHECK(bytes != NULL && size > 100000);
  if (!bytes) return;

  CHECK(asperity_table_load("/nonexistent/table.h5", &table, err, sizeof err) == ASPERITY_FILE_MISSING);
  CHECK(table == NULL && strstr(err, "no such file") != NULL);
  CHECK(asperity_table_load(ASPERITY_TEST_BINARY_DIR, &table, err, sizeof err) == ASPERITY_FILE_UNREADABLE);
  snprintf(path, sizeof path, "%s/c-api-text.h5", ASPERITY_TEST_BINARY_DIR);
  write_file(path, "dist,side,shape,sep\n", 20);
  CHECK(asperity_table_load(path, &table, err, sizeof err) == ASPERITY_NOT_HDF5);
  /* a format-1 table: the HDF5 file without the integrity header */
  snprintf(path, sizeof path, "%s/c-api-version1.h5", ASPERITY_TEST_BINARY_DIR);
  write_file(path, bytes + 512, size - 512);
  CHECK(asperity_table_load(path, &table, err, sizeof err) == ASPERITY_OTHER_VERSION);
  CHECK(strstr(err, "regenerate") != NULL);
  /* another program's HDF5 file: the same without the schema's name */
  for (i = 512; i + 14 <= size; ++i)
    if (memcmp(bytes + i, "asperity-table", 14) == 0) memcpy(bytes + i, "someone-elses!", 14);
  snprintf(path, sizeof path, "%s/c-api-foreign.h5", ASPERITY_TEST_BINARY_DIR);
  write_file(path, bytes + 512, size - 512);
  CHECK(asperity_table_load(path, &table, err, sizeof err) == ASPERITY_OTHER_SCHEMA);
  /* damaged: truncated, and (the same bytes as the header says, one changed) */
  snprintf(path, sizeof path, "%s/c-api-damaged.h5", ASPERITY_TEST_BINARY_DIR);
  write_file(path, bytes, size / 2);
  CHECK(asperity_table_load(path, &table, err, sizeof err) == ASPERITY_DAMAGED);
  CHECK(strstr(err, "truncated") != NULL);
  write_file(path, bytes, size);
  CHECK(asperity_table_load(path, &table, err, sizeof err) == ASPERITY_DAMAGED);
  CHECK(strstr(err, "SHA-256") != NULL);
  CHECK(asperity_table_load(NULL, NULL, err, sizeof err) == ASPERITY_BAD_HANDLE);
  CHECK(asperity_table_load("/nonexistent/table.h5", &table, NULL, 0) == ASPERITY_FILE_MISSING);
  CHECK(strcmp(asperity_status_string(ASPERITY_DAMAGED),
               "the table file is damaged (truncated or changed since it was written)") == 0);
  free(bytes);
}

/* Curves with fewer orders, and why a curve could not be made. */
static void curve_statuses(const asperity_table *table) {
  char err[512];
  asperity_curve *curve = NULL;
  CHECK(asperity_curve_load(table, "weibull", "tail", 2.0, ASPERITY_ORDER_I3_2 | ASPERITY_ORDER_I1_2, &curve, err,
                            sizeof err) == ASPERITY_OK);
  CHECK(asperity_curve_order_mask(curve) == (ASPERITY_ORDER_I3_2 | ASPERITY_ORDER_I1_2));
  CHECK(isfinite(asperity_eval(curve, 3, 0.5)) && isnan(asperity_eval(curve, 2, 0.5)));
  asperity_curve_close(curve);
  CHECK(asperity_curve_load(table, "weibull", "tail", 2.0, 0u, &curve, err, sizeof err) == ASPERITY_BAD_ORDER);
  CHECK(asperity_curve_load(table, "weibull", "tail", 2.0, 0x40u, &curve, err, sizeof err) == ASPERITY_BAD_ORDER);
  CHECK(asperity_curve_load(table, "beta", "tail", 2.0, ASPERITY_ALL_ORDERS, &curve, err, sizeof err) ==
        ASPERITY_BAD_NAME);
  CHECK(asperity_curve_load(table, "weibull", "tail", 100.0, ASPERITY_ALL_ORDERS, &curve, err, sizeof err) ==
        ASPERITY_NOT_IN_TABLE);
  CHECK(curve == NULL && strstr(err, "outside") != NULL);
  CHECK(asperity_curve_load(table, "gaussian", "bounded", 0.0, ASPERITY_ALL_ORDERS, &curve, err, sizeof err) ==
        ASPERITY_NOT_IN_TABLE);
  CHECK(asperity_curve_load(NULL, "weibull", "tail", 2.0, ASPERITY_ALL_ORDERS, &curve, err, sizeof err) ==
        ASPERITY_BAD_HANDLE);
  CHECK(asperity_curve_order_mask(NULL) == 0u);
}

/* The separations a curve serves: the whole axis for a full table's curve (a scene table's
 * range: tests/test_scene.cpp); NaN and ASPERITY_BAD_HANDLE for NULL. */
static void curve_range(const asperity_table *table) {
  char err[512];
  double lo = 0, hi = 0;
  asperity_curve *curve = asperity_curve_open(table, "weibull", "bounded", 2.0, err, sizeof err);
  CHECK(curve != NULL);
  if (!curve) return;
  CHECK(asperity_curve_range(curve, &lo, &hi) == ASPERITY_OK);
  CHECK(isinf(lo) && lo < 0 && isinf(hi) && hi > 0);
  CHECK(asperity_curve_range(NULL, &lo, &hi) == ASPERITY_BAD_HANDLE);
  CHECK(isnan(lo) && isnan(hi));
  CHECK(asperity_curve_range(curve, NULL, &hi) == ASPERITY_BAD_HANDLE && isnan(hi));
  CHECK(strcmp(asperity_status_string(ASPERITY_OUTSIDE_RANGE), "unknown status") != 0);
  asperity_curve_close(curve);
}

/* The batch calls with out overlapping sep: the values of separate buffers. */
static void overlapping_batches(const asperity_curve *curve) {
  enum { n = 1000 };
  static double expected[n], expected_log[n], buffer[n + 40];
  int shift, i, log_output;
  for (shift = -20; shift <= 20; shift += 5) {
    double *sep = buffer + 20, *out = buffer + 20 + shift;
    for (log_output = 0; log_output <= 1; ++log_output) {
      int same = 1;
      for (i = 0; i < n; ++i) sep[i] = -3.0 + 6.0 * i / n;
      CHECK(asperity_eval_batch(curve, 3, sep, expected, n) == ASPERITY_OK);
      CHECK(asperity_eval_log_batch(curve, 3, sep, expected_log, n) == ASPERITY_OK);
      CHECK((log_output ? asperity_eval_log_batch : asperity_eval_batch)(curve, 3, sep, out, n) == ASPERITY_OK);
      for (i = 0; i < n; ++i) same = same && out[i] == (log_output ? expected_log : expected)[i];
      CHECK(same);
    }
  }
}

/* The height scale from the rms summit height: against closed forms (Gamma by the C library). */
static void rms_height_scale(const asperity_table *table) {
  char err[512];
  const double c2 = sqrt(1.0 - acos(-1.0) / 4.0); /* a = 2: Gamma(2) - Gamma(3/2)^2 = 1 - pi/4 */
  const double c16 = sqrt(tgamma(1.0 + 2.0 / 1.6) - pow(tgamma(1.0 + 1.0 / 1.6), 2));
  double scale;
  asperity_model *model;
  asperity_physical_state state;
  CHECK(fabs(asperity_height_scale_from_rms("weibull", 2.0, 1e-6) - 1e-6 / c2) < 1e-14 * (1e-6 / c2));
  scale = asperity_height_scale_from_rms("weibull", 1.6, 5e-7);
  CHECK(fabs(scale - 5e-7 / c16) < 1e-13 * scale);
  CHECK(fabs(scale - 8.715e-7) < 1e-3 * scale); /* what `asperity contact --rms` reports */
  CHECK(asperity_height_scale_from_rms("gaussian", NAN, 3e-7) == 3e-7); /* the Gaussian's sigma is the rms */
  CHECK(isnan(asperity_height_scale_from_rms(NULL, 2.0, 1e-6)));
  CHECK(isnan(asperity_height_scale_from_rms("beta", 2.0, 1e-6)));
  CHECK(isnan(asperity_height_scale_from_rms("weibull", 2.0, 0.0)));
  CHECK(isnan(asperity_height_scale_from_rms("weibull", 2.0, -1e-6)));
  CHECK(isnan(asperity_height_scale_from_rms("weibull", 2.0, NAN)));
  CHECK(isnan(asperity_height_scale_from_rms("weibull", 2.0, INFINITY)));
  CHECK(isnan(asperity_height_scale_from_rms("gaussian", 2.0, -1e-6)));
  CHECK(isnan(asperity_height_scale_from_rms("weibull", 0.0, 1e-6)));
  CHECK(isnan(asperity_height_scale_from_rms("weibull", -1.6, 1e-6)));
  CHECK(isnan(asperity_height_scale_from_rms("weibull", NAN, 1e-6)));
  CHECK(isnan(asperity_height_scale_from_rms("weibull", 1e-3, 1e-6))); /* c_a overflows */
  /* a model with that scale: separations from the origin and from the mean summit height differ by
   * the mean summit height Gamma(1 + 1/a) sigma_s */
  model = asperity_model_open(table, "weibull", "tail", 1.6, scale, 1e-4, 1e10, 1e-4, 1e11, err, sizeof err);
  CHECK(model != NULL);
  if (!model) return;
  CHECK(asperity_model_at_separation(model, 1e-6, &state) == ASPERITY_OK);
  CHECK(fabs((state.separation - state.mean_separation) - tgamma(1.0 + 1.0 / 1.6) * scale) < 1e-12 * scale);
  asperity_model_close(model);
}

/* The separation datum, units caught and the batch: asperity_model_open_datum, asperity_model_datum,
 * asperity_model_warnings, asperity_model_at_separation_batch. */
static void model_datum_warnings_batch(const asperity_table *table) {
  char err[512], text[512];
  const double sigma = 1e-6, mean = tgamma(1.5) * 1e-6; /* a = 2: the mean summit Gamma(3/2) sigma_s from the origin */
  asperity_physical_state a, b, c;
  double sep[7], out[7], in_place[7];
  size_t i;
  int q;
  asperity_model *origin = asperity_model_open(table, "weibull", "tail", 2.0, sigma, 1e-4, 1e10, 1e-4, 1e11, err, sizeof err);
  asperity_model *summit = asperity_model_open_datum(table, "weibull", "tail", 2.0, sigma, 1e-4, 1e10, 1e-4, 1e11,
                                                     "mean-summit", NAN, err, sizeof err);
  asperity_model *plane = asperity_model_open_datum(table, "weibull", "tail", 2.0, sigma, 1e-4, 1e10, 1e-4, 1e11,
                                                    "mean-plane", 2e-7, err, sizeof err);
  asperity_model *slip;
  CHECK(origin != NULL && summit != NULL && plane != NULL);
  if (!origin || !summit || !plane) return;
  CHECK(strcmp(asperity_model_datum(origin), "origin") == 0);
  CHECK(strcmp(asperity_model_datum(summit), "mean-summit") == 0);
  CHECK(strcmp(asperity_model_datum(plane), "mean-plane") == 0);
  CHECK(asperity_model_datum(NULL) == NULL);
  /* the same load, each datum's separation: the origin's less the mean summit (less 2e-7 for the plane) */
  CHECK(asperity_model_at_load(origin, 1.0, &a) == ASPERITY_OK);
  CHECK(asperity_model_at_load(summit, 1.0, &b) == ASPERITY_OK);
  CHECK(asperity_model_at_load(plane, 1.0, &c) == ASPERITY_OK);
  CHECK(fabs(b.separation - (a.separation - mean)) < 1e-15 * sigma);
  CHECK(fabs(c.separation - (a.separation - mean + 2e-7)) < 1e-15 * sigma);
  CHECK(fabs(b.separation - b.mean_separation) < 1e-15 * sigma);
  CHECK(asperity_model_at_separation(summit, b.separation, &c) == ASPERITY_OK && fabs(c.load - 1.0) < 1e-9);
  /* refused: an unknown datum, the mean plane without its height, a height with another datum */
  CHECK(asperity_model_open_datum(table, "weibull", "tail", 2.0, sigma, 1e-4, 1e10, 1e-4, 1e11, "mean", NAN, err,
                                  sizeof err) == NULL && strstr(err, "unknown datum 'mean'") != NULL);
  CHECK(asperity_model_open_datum(table, "weibull", "tail", 2.0, sigma, 1e-4, 1e10, 1e-4, 1e11, "mean-plane", NAN, err,
                                  sizeof err) == NULL && strstr(err, "mean summit height above the mean plane") != NULL);
  CHECK(asperity_model_open_datum(table, "weibull", "tail", 2.0, sigma, 1e-4, 1e10, 1e-4, 1e11, "origin", 1e-6, err,
                                  sizeof err) == NULL && strstr(err, "goes with the mean-plane datum") != NULL);
  /* units caught: a plausible surface has no warning; 10 (um) as R and 210 (GPa) as E* have one each */
  CHECK(asperity_model_warnings(origin, text, sizeof text) == 0 && text[0] == '\0');
  slip = asperity_model_open(table, "weibull", "tail", 2.0, sigma, 10.0, 1e10, 1e-4, 210.0, err, sizeof err);
  CHECK(slip != NULL);
  if (slip) {
    CHECK(asperity_model_warnings(slip, text, sizeof text) == 2);
    CHECK(strstr(text, "summit radius 10 m is implausible (above 0.001 m): did you mean 10 \xC2\xB5m (1e-05 m)?\n") != NULL);
    CHECK(strstr(text, "contact modulus E* 210 Pa is implausible") != NULL);
    CHECK(asperity_model_warnings(slip, NULL, 0) == 2);
    CHECK(asperity_model_warnings(slip, text, 8) == 2 && strlen(text) == 7); /* cut, NUL-terminated */
    asperity_model_close(slip);
  }
  CHECK(asperity_model_warnings(NULL, text, sizeof text) == 0);
  /* the batch: each element the scalar answer (to the batch lookup's rounding), NaN exactly, in place */
  sep[0] = -1e-6, sep[1] = 0, sep[2] = 1e-6, sep[3] = 2.5e-6, sep[4] = INFINITY, sep[5] = -INFINITY, sep[6] = 4e-6;
  for (q = ASPERITY_QUANTITY_COUNT; q <= ASPERITY_QUANTITY_STIFFNESS; ++q) {
    CHECK(asperity_model_at_separation_batch(summit, q, sep, out, 7) == ASPERITY_OK);
    memcpy(in_place, sep, sizeof sep);
    CHECK(asperity_model_at_separation_batch(summit, q, in_place, in_place, 7) == ASPERITY_OK);
    for (i = 0; i < 7; ++i) {
      double scalar;
      asperity_model_at_separation(summit, sep[i], &c);
      scalar = q == ASPERITY_QUANTITY_COUNT ? c.count
               : q == ASPERITY_QUANTITY_REAL_AREA ? c.real_area
               : q == ASPERITY_QUANTITY_AREA_FRACTION ? c.area_fraction
               : q == ASPERITY_QUANTITY_LOAD ? c.load
               : q == ASPERITY_QUANTITY_PRESSURE ? c.pressure
                                                  : c.stiffness;
      CHECK(in_place[i] == out[i]);
      if (scalar == 0 || isinf(scalar)) CHECK(out[i] == scalar);
      else CHECK(fabs(out[i] - scalar) <= 1e-13 * scalar);
    }
  }
  sep[2] = NAN;
  CHECK(asperity_model_at_separation_batch(summit, ASPERITY_QUANTITY_LOAD, sep, out, 7) == ASPERITY_BAD_SEPARATION);
  CHECK(isnan(out[2]) && !isnan(out[0]));
  CHECK(asperity_model_at_separation_batch(summit, 6, sep, out, 7) == ASPERITY_BAD_PARAMETER && isnan(out[0]));
  CHECK(asperity_model_at_separation_batch(NULL, ASPERITY_QUANTITY_LOAD, sep, out, 7) == ASPERITY_BAD_HANDLE);
  CHECK(asperity_model_at_separation_batch(summit, ASPERITY_QUANTITY_LOAD, NULL, NULL, 0) == ASPERITY_OK);
  asperity_model_close(origin);
  asperity_model_close(summit);
  asperity_model_close(plane);
}

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
    {
      double given = 0;
      CHECK(asperity_contact_modulus_given(NAN, 2.1e11, 0.3, 2.1e11, 0.3, &given, err, sizeof err) == ASPERITY_OK);
      CHECK(given == modulus);
      CHECK(asperity_contact_modulus_given(NAN, NAN, NAN, NAN, NAN, &given, err, sizeof err) == ASPERITY_OK);
      CHECK(isnan(given));
      CHECK(asperity_contact_modulus_given(1e11, 2.1e11, 0.3, 2.1e11, 0.3, &given, err, sizeof err) ==
            ASPERITY_BAD_PARAMETER);
      CHECK(strstr(err, "not both") != NULL);
      CHECK(asperity_contact_modulus_given(NAN, 2.1e11, 0.3, NAN, 0.3, &given, err, sizeof err) ==
            ASPERITY_BAD_PARAMETER);
      CHECK(asperity_contact_modulus_given(-1, NAN, NAN, NAN, NAN, &given, err, sizeof err) == ASPERITY_BAD_PARAMETER);
    }

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
      /* FE export from C: the size first, then the card, the same text as C++'s (test_pressure_overclosure) */
      {
        size_t length = 0, small_length = 0;
        char small[8];
        char *card;
        CHECK(asperity_model_pressure_overclosure_card(model, 1e3, 1e8, 1e-3, "calculix", "si", "from C", NULL, 0,
                                                       &length, err, sizeof err) == ASPERITY_OK);
        CHECK(length > 100);
        CHECK(asperity_model_pressure_overclosure_card(model, 1e3, 1e8, 1e-3, "calculix", "si", "from C", small,
                                                       sizeof small, &small_length, err, sizeof err) == ASPERITY_NO_MEMORY);
        CHECK(small_length == length); /* a buffer too small still tells the size */
        card = (char *)malloc(length + 1);
        CHECK(card != NULL);
        if (card) {
          CHECK(asperity_model_pressure_overclosure_card(model, 1e3, 1e8, 1e-3, "calculix", "si", "from C", card,
                                                         length + 1, &length, err, sizeof err) == ASPERITY_OK);
          CHECK(strlen(card) == length);
          CHECK(strstr(card, "*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=TABULAR\n0,-") != NULL);
          CHECK(strstr(card, "from C") != NULL);
          free(card);
        }
        CHECK(asperity_model_pressure_overclosure_card(model, 1e3, 1e8, 1e-3, "nastran", "si", NULL, NULL, 0, &length,
                                                       err, sizeof err) == ASPERITY_BAD_NAME);
        CHECK(asperity_model_pressure_overclosure_card(model, 1e8, 1e3, 1e-3, "abaqus", "mm", NULL, NULL, 0, &length,
                                                       err, sizeof err) == ASPERITY_BAD_PARAMETER);
      }
      {
        const double pressures[3] = {0, 1e6, 1e7}, overclosures[3] = {-2e-6, -1e-6, -0.5e-6};
        char card[1024];
        size_t length = 0;
        CHECK(asperity_tabulated_pressure_overclosure_card(pressures, overclosures, 3, "abaqus", "si", "tabulated",
                                                           NULL, card, sizeof card, &length, err,
                                                           sizeof err) == ASPERITY_OK);
        CHECK(strstr(card, "1000000,-1e-06") != NULL);
        CHECK(asperity_tabulated_pressure_overclosure_card(pressures, overclosures, 1, "abaqus", "si", NULL, NULL,
                                                           card, sizeof card, &length, err,
                                                           sizeof err) == ASPERITY_BAD_PARAMETER);
      }
      CHECK(asperity_model_at_load(model, NAN, &inverse) == ASPERITY_BAD_SEPARATION);
      CHECK(isnan(inverse.separation));
      CHECK(asperity_model_at_load(NULL, 1.0, &inverse) == ASPERITY_BAD_HANDLE);
      asperity_model_close(model);
    }
    CHECK(asperity_model_open(table, "weibull", "tail", 2.0, -1e-6, 1e-4, 1e10, 1e-4, modulus, err, sizeof err) == NULL);
    CHECK(strstr(err, "height scale") != NULL);
    asperity_model_close(NULL);
  }

  table_statuses();
  curve_statuses(table);
  rms_height_scale(table);
  model_datum_warnings_batch(table);
  curve_range(table);
  overlapping_batches(curve);

  asperity_curve_close(curve);
  asperity_curve_close(NULL);
  asperity_table_close(table);
  asperity_table_close(NULL);
  if (failures == 0) printf("test_c_api: all checks passed\n");
  return failures == 0 ? 0 : 1;
}
