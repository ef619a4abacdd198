/* The C API of asperity: plain C (C99 and C++), for calling the runtime from any language.
 *
 * A table is loaded once (asperity_table_load); a curve resolves one distribution, side and
 * shape (asperity_curve_load) and is the hot handle. Both are immutable: any number of
 * threads may query the same curve at once. Queries never allocate, lock or abort:
 * bad input gives NaN (or a nonzero status for the batch call).
 *
 * What is defined and what is not:
 *  - Closing NULL does nothing. Closing a handle twice, or using it after it was closed, is
 *    undefined behaviour (as with free()): the handle is gone.
 *  - A table may be closed while curves and models made from it are still open: they hold their
 *    own data.
 *  - In the batch calls, out may overlap sep in any way (as with memmove): out == sep works in
 *    place, and a partial overlap gives the same values as separate buffers.
 *  - Messages: err gets a NUL-terminated message, cut to err_size - 1 bytes (nothing is written
 *    when err is NULL or err_size is 0).
 *  - Tables may be loaded from several threads; they are read one at a time (Debian's HDF5 is
 *    not thread-safe, so a host program that calls HDF5 itself from another thread at the same
 *    time must serialize that with table loading).
 *  - Table files are untrusted input: whatever their bytes, loading returns a status and a
 *    message, never crashes (docs/reliability.md says what is checked and what is promised).
 */
#ifndef ASPERITY_ASPERITY_H
#define ASPERITY_ASPERITY_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Status codes. Functions declared to return int return one of these too. */
typedef enum asperity_status {
  ASPERITY_OK = 0,
  ASPERITY_BAD_HANDLE = 1,      /* NULL curve, model, table or output */
  ASPERITY_BAD_ORDER = 2,       /* twice_order outside 0..5, or an order mask with no order or unknown bits */
  ASPERITY_BAD_SEPARATION = 3,  /* some separations were NaN or infinite: their outputs are NaN */
  ASPERITY_BAD_PARAMETER = 4,   /* a physical parameter <= 0 or not finite */
  /* asperity_table_load: why a table file was refused */
  ASPERITY_FILE_MISSING = 5,     /* no such file */
  ASPERITY_FILE_UNREADABLE = 6,  /* not a regular file (directory, FIFO, device), no permission, read error */
  ASPERITY_NOT_HDF5 = 7,         /* neither an asperity table nor any HDF5 file */
  ASPERITY_OTHER_SCHEMA = 8,     /* an HDF5 file, but not an asperity table */
  ASPERITY_OTHER_VERSION = 9,    /* an asperity table of another format version: regenerate it */
  ASPERITY_DAMAGED = 10,         /* truncated, extended or changed since it was written (integrity header) */
  ASPERITY_INVALID_TABLE = 11,   /* intact, but breaks the schema or its limits */
  /* asperity_curve_load, asperity_model_open */
  ASPERITY_BAD_NAME = 12,        /* dist or side is not a known name */
  ASPERITY_NOT_IN_TABLE = 13,    /* the table has no such curve set, or the shape is outside it */
  ASPERITY_NO_MEMORY = 14,
  ASPERITY_FAILURE = 15,         /* anything else: the message says what */
  /* asperity_eval_batch, asperity_contact, asperity_model_at_*: some separations lie outside the
   * ones the curve serves (a scene table's range, asperity_curve_range): their outputs are NaN */
  ASPERITY_OUTSIDE_RANGE = 16
} asperity_status;

/* Order masks: bit (1 << twice_order) keeps the integral of order twice_order / 2. A curve
 * holding fewer orders takes proportionally less memory and answers NaN for the others. */
#define ASPERITY_ORDER_I0 0x01u   /* count */
#define ASPERITY_ORDER_I1_2 0x02u /* stiffness */
#define ASPERITY_ORDER_I1 0x04u   /* area */
#define ASPERITY_ORDER_I3_2 0x08u /* load */
#define ASPERITY_ORDER_I2 0x10u
#define ASPERITY_ORDER_I5_2 0x20u
#define ASPERITY_ALL_ORDERS 0x3Fu
#define ASPERITY_CONTACT_ORDERS 0x0Fu /* what asperity_contact needs */

typedef struct asperity_table asperity_table; /* a loaded table: immutable, thread-safe */
typedef struct asperity_curve asperity_curve; /* one dist/side/shape resolved: the hot handle */

/* Loads a table file; NULL path: the shipped default table ($ASPERITY_TABLE if set). On success
 * returns ASPERITY_OK and sets *table; on failure a status (ASPERITY_FILE_MISSING ...
 * ASPERITY_INVALID_TABLE tell why), *table = NULL, and a message in err. */
asperity_status asperity_table_load(const char *path, asperity_table **table, char *err, size_t err_size);
/* The same, returning the table or NULL (the reason only as text). */
asperity_table *asperity_table_open(const char *path, char *err, size_t err_size);
void asperity_table_close(asperity_table *table);

/* dist: "weibull" or "gaussian"; side: "tail" or "bounded"; shape ignored for the Gaussian.
 * order_mask: ASPERITY_ALL_ORDERS or an OR of ASPERITY_ORDER_* bits. On failure *curve = NULL,
 * a status (ASPERITY_BAD_NAME, ASPERITY_NOT_IN_TABLE, ASPERITY_BAD_ORDER, ...) and a message. */
asperity_status asperity_curve_load(const asperity_table *table, const char *dist, const char *side, double shape,
                                    unsigned order_mask, asperity_curve **curve, char *err, size_t err_size);
/* The orders a curve holds (ASPERITY_ORDER_* bits); 0 for NULL. */
unsigned asperity_curve_order_mask(const asperity_curve *curve);
/* asperity_curve_load with all orders, returning the curve or NULL (the reason only as text). */
asperity_curve *asperity_curve_open(const asperity_table *table, const char *dist, const char *side,
                                    double shape, char *err, size_t err_size);
void asperity_curve_close(asperity_curve *curve);

/* The separations a curve serves: *min = -INFINITY and *max = INFINITY for a full table's curves,
 * a scene table's range for its curves (docs/scenes.md). Outside it every query answers NaN, except
 * on the bounded side at sep >= 0, where the values are exactly 0. Returns ASPERITY_OK, or
 * ASPERITY_BAD_HANDLE for a NULL argument (then *min and *max, where given, are NaN). */
int asperity_curve_range(const asperity_curve *curve, double *min, double *max);

/* twice_order: 0 -> I0, 1 -> I1/2, 2 -> I1, 3 -> I3/2, 4 -> I2, 5 -> I5/2; sep in the origin
 * convention (docs/model.md). NaN on bad input (NULL curve, bad order, NaN or infinite sep, a sep
 * outside the curve's range: asperity_curve_range). */
double asperity_eval(const asperity_curve *curve, int twice_order, double sep);
/* ln of the value: finite wherever the value is positive, -inf where it is exactly 0. */
double asperity_eval_log(const asperity_curve *curve, int twice_order, double sep);
/* out[i] = asperity_eval(curve, twice_order, sep[i]) for i < n, vectorized for the widest
 * instruction set this CPU has (results agree with asperity_eval to rounding: a few ulp of
 * ln X). out may overlap sep in any way. Returns a status code, every other output still written:
 * ASPERITY_BAD_SEPARATION if some sep are NaN or infinite, else ASPERITY_OUTSIDE_RANGE if some lie
 * outside the curve's range (their outputs NaN). */
int asperity_eval_batch(const asperity_curve *curve, int twice_order, const double *sep, double *out, size_t n);
/* The same for asperity_eval_log. */
int asperity_eval_log_batch(const asperity_curve *curve, int twice_order, const double *sep, double *out, size_t n);

/* The physical quantities of docs/model.md section 3 in one call, for N summits of radius R, height
 * scale sigma_s and plane-strain modulus E*. Returns a status code (NaNs on failure):
 * ASPERITY_BAD_SEPARATION, ASPERITY_OUTSIDE_RANGE (sep outside the curve's range) or
 * ASPERITY_BAD_PARAMETER. */
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
 * is immutable: one handle may serve many threads.
 *
 * Separations (asperity_model_at_separation's input, separation in every answer) are measured
 * from the model's datum (asperity/separation_datum.hpp, docs/model.md section 2):
 *   "origin"       the Weibull origin (lowest summit on the tail side, highest on the bounded
 *                  side) or the Gaussian's mean: asperity_model_open's, and the default (NULL);
 *   "mean-summit"  the mean summit height (GW's and McCool's datum);
 *   "mean-plane"   the mean plane of the surface heights, mean_summit_height [m] below the mean
 *                  summit height (the summit heights do not fix it: the caller gives it).
 * mean_separation is always from the mean summit height. */
typedef struct asperity_model asperity_model;
typedef struct asperity_physical_state {
  double separation;          /* m, from the model's datum (asperity_model_open: the origin) */
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
/* asperity_model_open with a datum ("origin", "mean-summit", "mean-plane"; NULL: "origin") and, for
 * "mean-plane" only, the mean summit height above the mean plane [m] (NaN otherwise). NULL and a
 * message for an unknown datum, "mean-plane" without a finite height, or a height with another datum. */
asperity_model *asperity_model_open_datum(const asperity_table *table, const char *dist, const char *side,
                                          double shape, double height_scale, double summit_radius,
                                          double summit_density, double nominal_area, double contact_modulus,
                                          const char *datum, double mean_summit_height, char *err, size_t err_size);
/* The model's datum ("origin", "mean-summit" or "mean-plane"; static storage); NULL for NULL. */
const char *asperity_model_datum(const asperity_model *model);
/* Units caught (asperity/plausibility.hpp): the surface's implausible values, most likely a unit
 * slip (a summit radius over 1 mm, E* under 1 MPa or over 10 TPa, sigma_s over 1 mm, a summit
 * density outside 1e4..1e18 per m^2, ...), found when the model was opened. Returns how many;
 * writes them into buffer one a line ("summit radius 10 m is implausible (above 0.001 m): did you
 * mean 10 µm (1e-05 m)?\n", UTF-8), NUL-terminated, cut to buffer_size - 1 bytes (nothing written for
 * a NULL buffer or buffer_size 0). 0 for a plausible surface or a NULL model. */
size_t asperity_model_warnings(const asperity_model *model, char *buffer, size_t buffer_size);
void asperity_model_close(asperity_model *model);
/* Each returns a status code (ASPERITY_BAD_HANDLE for NULL, ASPERITY_BAD_SEPARATION for a NaN
 * input, ASPERITY_OUTSIDE_RANGE for a separation, or a load, pressure or area whose separation,
 * outside the range a scene table's curve serves; the outputs of both NaN) and fills *out. A load,
 * pressure or area <= 0 is no contact. */
int asperity_model_at_separation(const asperity_model *model, double separation, asperity_physical_state *out);
int asperity_model_at_load(const asperity_model *model, double load, asperity_physical_state *out);
int asperity_model_at_pressure(const asperity_model *model, double pressure, asperity_physical_state *out);
int asperity_model_at_real_area(const asperity_model *model, double real_area, asperity_physical_state *out);
/* The batch: out[i] = the quantity of asperity_model_at_separation(model, separation[i]) for i < n,
 * through the vectorized lookup (asperity_eval_batch) and the quantity's factor: the same answer to
 * the batch lookup's rounding (a few ulp of ln X), and exactly the scalar one where it is NaN, 0 or
 * infinite. out may be separation (not a partial overlap). No allocation. Returns ASPERITY_OK,
 * ASPERITY_BAD_HANDLE (NULL model, or NULL arrays with n > 0), ASPERITY_BAD_PARAMETER (quantity not an
 * asperity_quantity: every out NaN), ASPERITY_BAD_SEPARATION (some separations NaN: their out NaN) or
 * ASPERITY_OUTSIDE_RANGE (some outside a scene table's range: their out NaN). */
typedef enum asperity_quantity {
  ASPERITY_QUANTITY_COUNT = 0,         /* summits in contact */
  ASPERITY_QUANTITY_REAL_AREA = 1,     /* m^2 */
  ASPERITY_QUANTITY_AREA_FRACTION = 2, /* A / A0 */
  ASPERITY_QUANTITY_LOAD = 3,          /* N */
  ASPERITY_QUANTITY_PRESSURE = 4,      /* Pa, load / A0 */
  ASPERITY_QUANTITY_STIFFNESS = 5      /* N/m */
} asperity_quantity;
int asperity_model_at_separation_batch(const asperity_model *model, int quantity, const double *separation,
                                       double *out, size_t n);
/* 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2; NaN for E <= 0 or nu outside (-1, 0.5]. */
double asperity_contact_modulus(double young1, double poisson1, double young2, double poisson2);
/* The height scale asperity_model_open takes, from the rms summit height GW users measure (about
 * the mean, in m): for dist "weibull" the scale sigma_s = rms / c_a with
 * c_a = sqrt(Gamma(1 + 2/a) - Gamma(1 + 1/a)^2) (docs/model.md section 1; for shape a = 1.6,
 * rms = 0.574 sigma_s); for "gaussian" the rms itself (shape ignored). NaN for a NULL or unknown
 * dist, or an rms or Weibull shape that is not a positive finite number. */
double asperity_height_scale_from_rms(const char *dist, double shape, double rms);
/* The input check every interface shares: E* from what a user gave, the contact modulus itself
 * or the four E1, nu1, E2, nu2 together, NaN marking a value not given. *out is NaN where none
 * is given. ASPERITY_BAD_PARAMETER (with a message in err) for both given, the four incomplete,
 * E* not positive, or a bad E or nu. */
int asperity_contact_modulus_given(double contact_modulus, double young1, double poisson1, double young2,
                                   double poisson2, double *out, char *err, size_t err_size);

/* FE export (asperity/pressure_overclosure.hpp): a model's contact-pressure law as the tabular
 * pressure-overclosure card of CalculiX or Abaqus (*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR),
 * or as CSV. Overclosure is measured from the mean summit height (positive where the surfaces
 * overlap); points are placed until linear interpolation is within `tolerance` (relative, in
 * pressure, 1e-6..0.1) of the law from pressure_min to pressure_max [Pa]. format "calculix",
 * "abaqus" or "csv"; units "si" (m, Pa) or "mm" (mm, MPa); description: the card's comment
 * header (may be NULL). The text is written into buffer with its NUL if it fits in buffer_size
 * bytes (else nothing is written there); *length (if not NULL) receives its length without the
 * NUL, so a call with buffer NULL and buffer_size 0 tells the size needed. Returns ASPERITY_OK,
 * ASPERITY_BAD_HANDLE, ASPERITY_BAD_NAME (format or units), ASPERITY_BAD_PARAMETER (range,
 * tolerance, a card too fine for CalculiX), ASPERITY_NO_MEMORY (buffer too small, *length set)
 * or ASPERITY_FAILURE, with a message in err. */
int asperity_model_pressure_overclosure_card(const asperity_model *model, double pressure_min, double pressure_max,
                                             double tolerance, const char *format, const char *units,
                                             const char *description, char *buffer, size_t buffer_size,
                                             size_t *length, char *err, size_t err_size);
/* The card with the command line's options and defaults (asperity contact --export): datum
 * "zero-pressure" (NULL: the default, the card starts with the surfaces touching), "mean-summit"
 * (asperity_model_pressure_overclosure_card's), "origin" or "mean-plane"; max_points the cap on
 * the card's rows (0: the default, 200 for calculix, what its node-to-surface contact holds; none
 * for abaqus and csv; a tolerance that needs more is loosened to the smallest that fits, as the
 * header says); face_size the slave faces' edge in the card's units (m, or mm with units "mm";
 * NaN: not given): a calculix card's header warns where its clearance reaches beyond CalculiX's
 * contact-spring cut-off 1e-3 face_size. Statuses as above (ASPERITY_BAD_NAME for the datum). */
int asperity_model_pressure_overclosure_card_options(const asperity_model *model, double pressure_min,
                                                     double pressure_max, double tolerance, const char *format,
                                                     const char *units, const char *datum, size_t max_points,
                                                     double face_size, const char *description, char *buffer,
                                                     size_t buffer_size, size_t *length, char *err, size_t err_size);
/* The same card for a curve given by its points (a tabulated law, e.g. the exact contact of a
 * measured map): count >= 2 points, ascending in overclosure [m], pressures [Pa] never falling;
 * notes (may be NULL): more header lines. */
int asperity_tabulated_pressure_overclosure_card(const double *pressures, const double *overclosures, size_t count,
                                                 const char *format, const char *units, const char *description,
                                                 const char *notes, char *buffer, size_t buffer_size, size_t *length,
                                                 char *err, size_t err_size);

/* Contact curves against separation (asperity/contact_curves.hpp): a measured surface's exact
 * contact tabulated (asperity exact-contact --table), served like any curve. The separation is
 * from the table's datum (for a measured map: the mean gap, from the map's mean plane) in m;
 * pressure the mean nominal pressure in Pa; stiffness -dp/d(separation) in Pa/m; area_fraction
 * the real contact area over the nominal area. Served from the first to the last node; outside,
 * NaN. The handle is immutable: one may serve many threads; queries never allocate or lock. */
typedef struct asperity_contact_curves asperity_contact_curves;
typedef struct asperity_contact_curves_state {
  double separation, pressure, stiffness, area_fraction;
} asperity_contact_curves_state;
/* What a contact-curves table states about itself. */
typedef struct asperity_contact_curves_info {
  double min_separation, max_separation; /* m: the range served */
  double min_pressure, max_pressure;     /* Pa: the pressures the inverse serves (adhesive curves:
                                            from the pull-off's, negative, up; see below) */
  double max_rel_error[3];               /* the stored bound (relative): pressure, stiffness, area fraction */
  double measured_rel_error[3];          /* the largest measured between the nodes (bound = this x safety_factor) */
  double safety_factor;
  double solver_tolerance;               /* the solves' relative residual */
  double contact_modulus;                /* Pa */
  double nominal_area;                   /* m^2 */
  double mean_summit_height;             /* m above the separation's datum; NaN if not stated */
  int nodes, check_points;
} asperity_contact_curves_info;
/* Loads a contact-curves table; the statuses of asperity_table_load (ASPERITY_OTHER_SCHEMA for a
 * table of Greenwood-Williamson integrals), *curves = NULL and a message on failure. */
asperity_status asperity_contact_curves_load(const char *path, asperity_contact_curves **curves, char *err,
                                             size_t err_size);
void asperity_contact_curves_close(asperity_contact_curves *curves);
/* ASPERITY_OK, or ASPERITY_BAD_HANDLE for a NULL argument. */
int asperity_contact_curves_get_info(const asperity_contact_curves *curves, asperity_contact_curves_info *out);
/* The hot path: NaN for a NULL handle, a NaN input or one outside the range served. */
double asperity_contact_curves_pressure(const asperity_contact_curves *curves, double separation);
double asperity_contact_curves_stiffness(const asperity_contact_curves *curves, double separation);
double asperity_contact_curves_area_fraction(const asperity_contact_curves *curves, double separation);
/* The separation where the served pressure is `pressure` (the inverse; adhesive curves: on the
 * stable branch, up to the pull-off separation). */
double asperity_contact_curves_separation(const asperity_contact_curves *curves, double pressure);
/* Summits in contact per m^2 of nominal area (a law's table; NaN for a table without the count,
 * such as a measured surface's exact contact, a NULL handle or outside the range). */
double asperity_contact_curves_summit_count(const asperity_contact_curves *curves, double separation);
/* The summit count's stored bound (relative), apart from max_rel_error's three: on a Weibull tail
 * it may exceed the error asked (docs/contact-laws.md section 8). NaN for a table without the
 * count or a NULL handle. (A function, not a field of asperity_contact_curves_info: that struct's
 * size is part of the ABI.) */
double asperity_contact_curves_summit_count_max_rel_error(const asperity_contact_curves *curves);
/* Adhesive curves (an adhesive law's table, docs/contact-laws.md section 8): 1 if the curves have
 * a tensile part (the pressure served is then signed, negative: tension; the stored pressure and
 * stiffness bounds are relative to the gross compressive + tensile), else 0 (also for NULL).
 * The pull-off: the greatest tension (Pa, < 0) and the separation where it is reached (m); NaN
 * without tension, for NULL, or where the pull-off is not inside the range served. */
int asperity_contact_curves_has_tension(const asperity_contact_curves *curves);
double asperity_contact_curves_pull_off_pressure(const asperity_contact_curves *curves);
double asperity_contact_curves_pull_off_separation(const asperity_contact_curves *curves);
/* The branch of adhesive curves: an adhesive law's withdrawal (unloading, fixed grips) branch after
 * an approach to this separation (m, from the table's datum, at or below the first node served),
 * or NaN for the approach (loading) branch, curves without tension and NULL. Finite: the pull-off
 * above is the withdrawal's (Fuller-Tabor's). (A function: asperity_contact_curves_info's size is
 * part of the ABI.) */
double asperity_contact_curves_approach_separation(const asperity_contact_curves *curves);
/* All four at a separation, or at a pressure. Return ASPERITY_OK, ASPERITY_BAD_HANDLE (NULL),
 * ASPERITY_BAD_SEPARATION (NaN input) or ASPERITY_OUTSIDE_RANGE (outside the range served: NaN
 * outputs). */
int asperity_contact_curves_at_separation(const asperity_contact_curves *curves, double separation,
                                          asperity_contact_curves_state *out);
int asperity_contact_curves_at_pressure(const asperity_contact_curves *curves, double pressure,
                                        asperity_contact_curves_state *out);
/* The curves' pressure-overclosure card, as asperity_model_pressure_overclosure_card (the same
 * buffer contract and statuses): overclosure from the mean summit height, pressures within the
 * range served. */
int asperity_contact_curves_pressure_overclosure_card(const asperity_contact_curves *curves, double pressure_min,
                                                      double pressure_max, double tolerance, const char *format,
                                                      const char *units, const char *description, char *buffer,
                                                      size_t buffer_size, size_t *length, char *err, size_t err_size);
/* With the command line's options and defaults, as asperity_model_pressure_overclosure_card_options
 * (datum "zero-pressure" by default, "mean-summit" or "origin"). */
int asperity_contact_curves_pressure_overclosure_card_options(const asperity_contact_curves *curves,
                                                              double pressure_min, double pressure_max,
                                                              double tolerance, const char *format, const char *units,
                                                              const char *datum, size_t max_points, double face_size,
                                                              const char *description, char *buffer,
                                                              size_t buffer_size, size_t *length, char *err,
                                                              size_t err_size);

/* A message for a status code (static storage). */
const char *asperity_status_string(int status);

#ifdef __cplusplus
}
#endif

#endif /* ASPERITY_ASPERITY_H */
