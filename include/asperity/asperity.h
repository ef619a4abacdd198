/* The C API of asperity: plain C (C99 and C++), for calling the runtime from any language.
 *
 * A table is loaded once (asperity_table_open); a curve resolves one distribution, side and
 * shape (asperity_curve_open) and is the hot handle. Both are immutable: any number of
 * threads may query the same curve at once. Queries never allocate, lock or abort:
 * bad input gives NaN (or a nonzero status for the batch call).
 */
#ifndef ASPERITY_ASPERITY_H
#define ASPERITY_ASPERITY_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct asperity_table asperity_table; /* a loaded table: immutable, thread-safe */
typedef struct asperity_curve asperity_curve; /* one dist/side/shape resolved: the hot handle */

/* Status codes of asperity_eval_batch and asperity_contact. */
enum {
  ASPERITY_OK = 0,
  ASPERITY_BAD_HANDLE = 1,    /* NULL curve or output */
  ASPERITY_BAD_ORDER = 2,     /* twice_order outside 0..5 */
  ASPERITY_BAD_SEPARATION = 3,/* some separations were NaN or infinite: their outputs are NaN */
  ASPERITY_BAD_PARAMETER = 4  /* a physical parameter <= 0 or not finite */
};

/* NULL path: the shipped default table ($ASPERITY_TABLE if set). On failure returns NULL
 * and writes a message into err (if err is not NULL and err_size > 0). */
asperity_table *asperity_table_open(const char *path, char *err, size_t err_size);
void asperity_table_close(asperity_table *table);

/* dist: "weibull" or "gaussian"; side: "tail" or "bounded"; shape ignored for the Gaussian. */
asperity_curve *asperity_curve_open(const asperity_table *table, const char *dist, const char *side,
                                    double shape, char *err, size_t err_size);
void asperity_curve_close(asperity_curve *curve);

/* twice_order: 0 -> I0, 1 -> I1/2, 2 -> I1, 3 -> I3/2, 4 -> I2, 5 -> I5/2; sep in the origin
 * convention (docs/model.md). NaN on bad input (NULL curve, bad order, NaN or infinite sep). */
double asperity_eval(const asperity_curve *curve, int twice_order, double sep);
/* ln of the value: finite wherever the value is positive, -inf where it is exactly 0. */
double asperity_eval_log(const asperity_curve *curve, int twice_order, double sep);
/* out[i] = asperity_eval(curve, twice_order, sep[i]) for i < n, vectorized for the widest
 * instruction set this CPU has (results agree with asperity_eval to rounding: a few ulp of
 * ln X). out may be sep. Returns a status code: the first problem found, every other output
 * still written. */
int asperity_eval_batch(const asperity_curve *curve, int twice_order, const double *sep, double *out, size_t n);
/* The same for asperity_eval_log. */
int asperity_eval_log_batch(const asperity_curve *curve, int twice_order, const double *sep, double *out, size_t n);

/* The physical quantities of docs/model.md section 3 in one call, for N summits of radius R, height
 * scale sigma_s and plane-strain modulus E*. Returns a status code (NaNs on failure). */
typedef struct asperity_contact_state {
  double count, area, load, stiffness, stiffness_ratio;
} asperity_contact_state;
int asperity_contact(const asperity_curve *curve, double summit_count, double summit_radius, double height_scale,
                     double contact_modulus, double sep, asperity_contact_state *out);

/* Separation conventions: standardized = (s - mean)/rms from the mean summit height. */
double asperity_standardized_from_origin(const asperity_curve *curve, double sep);
double asperity_origin_from_standardized(const asperity_curve *curve, double standardized);

const char *asperity_version(void);

/* A physical surface and its contact with a flat, forward and inverse (asperity/contact_model.hpp),
 * SI units. dist "weibull" (shape 0.3..50, side "tail" or "bounded") or "gaussian" (side "tail").
 * Returns NULL and writes a message into err for a bad parameter or a missing curve. The model
 * is immutable: one handle may serve many threads. */
typedef struct asperity_model asperity_model;
typedef struct asperity_physical_state {
  double separation;          /* m, origin convention (from the Weibull origin / Gaussian mean) */
  double mean_separation;     /* m, from the mean summit height */
  double count;               /* summits in contact */
  double real_area;           /* m^2 */
  double area_fraction;       /* A / A0 */
  double load;                /* N */
  double pressure;            /* Pa, load / A0 */
  double stiffness;           /* N/m */
  double stiffness_over_load; /* 1/m */
} asperity_physical_state;
asperity_model *asperity_model_open(const asperity_table *table, const char *dist, const char *side, double shape,
                                    double height_scale, double summit_radius, double summit_density,
                                    double nominal_area, double contact_modulus, char *err, size_t err_size);
void asperity_model_close(asperity_model *model);
/* Each returns a status code (ASPERITY_BAD_HANDLE for NULL, ASPERITY_BAD_SEPARATION for a NaN
 * input, whose outputs are NaN) and fills *out. A load, pressure or area <= 0 is no contact. */
int asperity_model_at_separation(const asperity_model *model, double separation, asperity_physical_state *out);
int asperity_model_at_load(const asperity_model *model, double load, asperity_physical_state *out);
int asperity_model_at_pressure(const asperity_model *model, double pressure, asperity_physical_state *out);
int asperity_model_at_real_area(const asperity_model *model, double real_area, asperity_physical_state *out);
/* 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2; NaN for E <= 0 or nu outside (-1, 0.5]. */
double asperity_contact_modulus(double young1, double poisson1, double young2, double poisson2);
/* A message for a status code (static storage). */
const char *asperity_status_string(int status);

#ifdef __cplusplus
}
#endif

#endif /* ASPERITY_ASPERITY_H */
