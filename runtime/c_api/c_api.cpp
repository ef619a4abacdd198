// The C API (include/asperity/asperity.h) over the C++ runtime. Exceptions stop here.
#include "asperity/asperity.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/contact.hpp"
#include "asperity/contact_curves.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/error.hpp"
#include "asperity/plausibility.hpp"
#include "asperity/pressure_overclosure.hpp"
#include "asperity/separation_datum.hpp"
#include "asperity/surface.hpp"
#include "asperity/table.hpp"
#include "asperity/table_file.hpp"

struct asperity_table {
  asperity::Table table;
};
struct asperity_curve {
  asperity::Curve curve;
};
struct asperity_model {
  asperity::ContactModel model;
  std::string warnings;  // asperity_model_warnings: implausible_values, one a line
};
struct asperity_contact_curves {
  asperity::ContactCurves curves;
};

namespace {

void write_error(char* err, size_t err_size, const char* message) {
  if (err && err_size > 0) std::snprintf(err, err_size, "%s", message);
}

const double not_a_number = std::numeric_limits<double>::quiet_NaN();

// Runs make(); an exception becomes a message in err and a NULL result.
template <class Make>
auto guarded(char* err, size_t err_size, const char* where, Make make) -> decltype(make()) {
  try {
    return make();
  } catch (const std::exception& error) {
    write_error(err, err_size, error.what());
  } catch (...) {
    write_error(err, err_size, (std::string(where) + ": unknown failure").c_str());
  }
  return nullptr;
}

}  // namespace

namespace {
// Whether every x[i] is finite: a bit test the compiler vectorizes (exponent field all ones ->
// bit 63 of (bits & field) + 2^52), eight at a time, where a branch per separation was 8% of
// asperity_eval_batch's samples (perf, bench_lookup BM_BatchCApi); on x86 built also for AVX2
// and AVX-512, chosen at load time (6.6%, most of it the input's first trip from L2). Not under a
// sanitizer: the clones' resolver runs while the dynamic loader relocates the library, before the
// sanitizer's runtime is set up (ThreadSanitizer's test_hot_path crashed there, in
// elf_machine_lazy_rel).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__) && \
    !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
bool all_finite(const double* x, size_t n) {
  constexpr std::uint64_t field = 0x7ff0000000000000ull, carry = 0x0010000000000000ull;
  const auto flag = [](double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return (bits & field) + carry;
  };
  std::uint64_t any[8] = {};
  size_t i = 0;
  for (; i + 8 <= n; i += 8)
    for (int k = 0; k < 8; ++k) any[k] |= flag(x[i + k]);
  for (; i < n; ++i) any[0] |= flag(x[i]);
  std::uint64_t all = 0;
  for (const std::uint64_t part : any) all |= part;
  return (all >> 63) == 0;
}

int eval_batch(const asperity_curve* curve, int twice_order, const double* sep, double* out, size_t n,
               bool log_output) {
  if (!curve || (n > 0 && (!sep || !out))) return ASPERITY_BAD_HANDLE;
  if (twice_order < 0 || twice_order >= asperity::order_count) {
    for (size_t i = 0; i < n; ++i) out[i] = not_a_number;
    return ASPERITY_BAD_ORDER;
  }
  // Scan for non-finite separations first: out may overlap sep.
  int status = all_finite(sep, n) ? ASPERITY_OK : ASPERITY_BAD_SEPARATION;
  // and, for a curve that serves a range only (a scene table's), for separations outside it
  const asperity::Curve& served = curve->curve;
  if (status == ASPERITY_OK && (served.served_min_separation() > -HUGE_VAL || served.served_max_separation() < HUGE_VAL))
    for (size_t i = 0; i < n; ++i)
      if (!served.serves(sep[i])) {
        status = ASPERITY_OUTSIDE_RANGE;
        break;
      }
  auto run = [&](const double* in, double* to, size_t count) {
    if (log_output) curve->curve.log_value_batch(twice_order, in, to, count);
    else curve->curve.value_batch(twice_order, in, to, count);
  };
  const auto in_address = reinterpret_cast<std::uintptr_t>(sep), out_address = reinterpret_cast<std::uintptr_t>(out);
  const std::uintptr_t bytes = n * sizeof(double);
  if (in_address == out_address || in_address + bytes <= out_address || out_address + bytes <= in_address) {
    run(sep, out, n);  // in place (the kernel copies each block first) or apart
    return status;
  }
  // A partial overlap, as memmove: each chunk of input copied before its outputs are written,
  // chunks taken in the order that never overwrites input not yet copied.
  constexpr size_t chunk = 256;
  double copy[chunk];
  const size_t chunks = (n + chunk - 1) / chunk;
  for (size_t step = 0; step < chunks; ++step) {
    const size_t index = out_address > in_address ? chunks - 1 - step : step;
    const size_t start = index * chunk, count = std::min(chunk, n - start);
    std::memcpy(copy, sep + start, count * sizeof(double));
    run(copy, out + start, count);
  }
  return status;
}

asperity_status table_status(asperity::TableFileStatus status) {
  switch (status) {
    case asperity::TableFileStatus::missing: return ASPERITY_FILE_MISSING;
    case asperity::TableFileStatus::unreadable: return ASPERITY_FILE_UNREADABLE;
    case asperity::TableFileStatus::not_hdf5: return ASPERITY_NOT_HDF5;
    case asperity::TableFileStatus::other_schema: return ASPERITY_OTHER_SCHEMA;
    case asperity::TableFileStatus::other_version: return ASPERITY_OTHER_VERSION;
    case asperity::TableFileStatus::damaged: return ASPERITY_DAMAGED;
    case asperity::TableFileStatus::invalid: return ASPERITY_INVALID_TABLE;
  }
  return ASPERITY_FAILURE;
}

// Runs make() into *result; an exception becomes a status (failure_status for asperity::Error)
// and a message in err.
template <class Make, class Result>
asperity_status guarded_status(char* err, size_t err_size, const char* where, asperity_status failure_status,
                               Result** result, Make make) {
  try {
    *result = make();
    return ASPERITY_OK;
  } catch (const asperity::TableFileError& error) {
    write_error(err, err_size, error.what());
    return table_status(error.status());
  } catch (const asperity::Error& error) {
    write_error(err, err_size, error.what());
    return failure_status;
  } catch (const std::bad_alloc&) {
    write_error(err, err_size, (std::string(where) + ": out of memory").c_str());
    return ASPERITY_NO_MEMORY;
  } catch (const std::exception& error) {
    write_error(err, err_size, error.what());
  } catch (...) {
    write_error(err, err_size, (std::string(where) + ": unknown failure").c_str());
  }
  return ASPERITY_FAILURE;
}
}  // namespace

namespace {
// The card `write` makes, into the caller's buffer (asperity.h: the NUL too if it fits; *length
// always); its exceptions as status codes
template <class Write>
int card_out(Write write, char* buffer, size_t buffer_size, size_t* length, char* err, size_t err_size) {
  std::string text;
  try {
    std::ostringstream out;
    write(out);
    text = out.str();
  } catch (const asperity::Error& error) {
    write_error(err, err_size, error.what());
    return ASPERITY_BAD_PARAMETER;
  } catch (const std::bad_alloc&) {
    return ASPERITY_NO_MEMORY;
  } catch (const std::exception& error) {
    write_error(err, err_size, error.what());
    return ASPERITY_FAILURE;
  }
  if (length) *length = text.size();
  if (buffer_size == 0 && !buffer) return ASPERITY_OK;  // asking for the size
  if (!buffer || buffer_size < text.size() + 1) {
    write_error(err, err_size, "the card does not fit in the buffer: *length tells its size");
    return ASPERITY_NO_MEMORY;
  }
  std::memcpy(buffer, text.c_str(), text.size() + 1);
  return ASPERITY_OK;
}

bool card_names(const char* format, const char* units, asperity::CardFormat& card_format,
                asperity::CardUnits& card_units, char* err, size_t err_size) {
  if (!format || !asperity::parse_card_format(format, card_format)) {
    write_error(err, err_size, "unknown card format (calculix, abaqus or csv)");
    return false;
  }
  if (!units || !asperity::parse_card_units(units, card_units)) {
    write_error(err, err_size, "unknown card units (si or mm)");
    return false;
  }
  return true;
}
}  // namespace

extern "C" {

asperity_status asperity_table_load(const char* path, asperity_table** table, char* err, size_t err_size) {
  if (!table) {
    write_error(err, err_size, "asperity_table_load: NULL output");
    return ASPERITY_BAD_HANDLE;
  }
  *table = nullptr;
  return guarded_status(err, err_size, "asperity_table_load", ASPERITY_FAILURE, table, [&] {
    return new asperity_table{path ? asperity::Table::open(path) : asperity::Table::open_default()};
  });
}

asperity_table* asperity_table_open(const char* path, char* err, size_t err_size) {
  asperity_table* table = nullptr;
  asperity_table_load(path, &table, err, err_size);
  return table;
}

void asperity_table_close(asperity_table* table) { delete table; }

asperity_status asperity_curve_load(const asperity_table* table, const char* dist, const char* side, double shape,
                                    unsigned order_mask, asperity_curve** curve, char* err, size_t err_size) {
  if (!curve) {
    write_error(err, err_size, "asperity_curve_load: NULL output");
    return ASPERITY_BAD_HANDLE;
  }
  *curve = nullptr;
  if (!table || !dist || !side) {
    write_error(err, err_size, "asperity_curve_load: NULL table, dist or side");
    return ASPERITY_BAD_HANDLE;
  }
  asperity::Distribution distribution;
  asperity::Side which;
  if (!asperity::parse_distribution(dist, distribution)) {
    write_error(err, err_size, (std::string("unknown dist '") + dist + "' (weibull or gaussian)").c_str());
    return ASPERITY_BAD_NAME;
  }
  if (!asperity::parse_side(side, which)) {
    write_error(err, err_size, (std::string("unknown side '") + side + "' (tail or bounded)").c_str());
    return ASPERITY_BAD_NAME;
  }
  if (order_mask == 0 || (order_mask & ~ASPERITY_ALL_ORDERS) != 0) {
    write_error(err, err_size, "order_mask must be a nonzero OR of ASPERITY_ORDER_* bits");
    return ASPERITY_BAD_ORDER;
  }
  return guarded_status(err, err_size, "asperity_curve_load", ASPERITY_NOT_IN_TABLE, curve, [&] {
    return new asperity_curve{table->table.curve(distribution, which, shape, order_mask)};
  });
}

asperity_curve* asperity_curve_open(const asperity_table* table, const char* dist, const char* side, double shape,
                                    char* err, size_t err_size) {
  asperity_curve* curve = nullptr;
  asperity_curve_load(table, dist, side, shape, ASPERITY_ALL_ORDERS, &curve, err, err_size);
  return curve;
}

unsigned asperity_curve_order_mask(const asperity_curve* curve) { return curve ? curve->curve.order_mask() : 0u; }

void asperity_curve_close(asperity_curve* curve) { delete curve; }

asperity_model* asperity_model_open(const asperity_table* table, const char* dist, const char* side, double shape,
                                    double height_scale, double summit_radius, double summit_density,
                                    double nominal_area, double contact_modulus, char* err, size_t err_size) {
  return asperity_model_open_datum(table, dist, side, shape, height_scale, summit_radius, summit_density, nominal_area,
                                   contact_modulus, nullptr, not_a_number, err, err_size);
}

asperity_model* asperity_model_open_datum(const asperity_table* table, const char* dist, const char* side,
                                          double shape, double height_scale, double summit_radius,
                                          double summit_density, double nominal_area, double contact_modulus,
                                          const char* datum, double mean_summit_height, char* err, size_t err_size) {
  if (!table || !dist || !side) {
    write_error(err, err_size, "asperity_model_open: NULL table, dist or side");
    return nullptr;
  }
  asperity::SeparationDatum separation_datum = asperity::default_separation_datum;
  if (datum && !asperity::parse_separation_datum(datum, separation_datum)) {
    write_error(err, err_size,
                (std::string("unknown datum '") + datum + "' (origin, mean-summit or mean-plane)").c_str());
    return nullptr;
  }
  asperity::RoughSurface surface;
  if (!asperity::parse_distribution(dist, surface.distribution)) {
    write_error(err, err_size, (std::string("unknown dist '") + dist + "' (weibull or gaussian)").c_str());
    return nullptr;
  }
  if (!asperity::parse_side(side, surface.side)) {
    write_error(err, err_size, (std::string("unknown side '") + side + "' (tail or bounded)").c_str());
    return nullptr;
  }
  surface.shape = shape;
  surface.height_scale = height_scale;
  surface.summit_radius = summit_radius;
  surface.summit_density = summit_density;
  surface.nominal_area = nominal_area;
  surface.contact_modulus = contact_modulus;
  return guarded(err, err_size, "asperity_model_open", [&] {
    asperity_model* model = new asperity_model{
        asperity::ContactModel(table->table, surface, separation_datum, mean_summit_height), std::string()};
    for (const std::string& line : asperity::implausible_values(surface)) model->warnings += line + "\n";
    return model;
  });
}

const char* asperity_model_datum(const asperity_model* model) {
  return model ? asperity::separation_datum_name(model->model.datum()) : nullptr;
}

size_t asperity_model_warnings(const asperity_model* model, char* buffer, size_t buffer_size) {
  if (!model) return 0;
  if (buffer && buffer_size > 0) std::snprintf(buffer, buffer_size, "%s", model->warnings.c_str());
  return static_cast<size_t>(std::count(model->warnings.begin(), model->warnings.end(), '\n'));
}

static_assert(ASPERITY_QUANTITY_COUNT == static_cast<int>(asperity::ContactQuantity::count) &&
                  ASPERITY_QUANTITY_REAL_AREA == static_cast<int>(asperity::ContactQuantity::real_area) &&
                  ASPERITY_QUANTITY_AREA_FRACTION == static_cast<int>(asperity::ContactQuantity::area_fraction) &&
                  ASPERITY_QUANTITY_LOAD == static_cast<int>(asperity::ContactQuantity::load) &&
                  ASPERITY_QUANTITY_PRESSURE == static_cast<int>(asperity::ContactQuantity::pressure) &&
                  ASPERITY_QUANTITY_STIFFNESS == static_cast<int>(asperity::ContactQuantity::stiffness),
              "asperity_quantity is asperity::ContactQuantity");

int asperity_model_at_separation_batch(const asperity_model* model, int quantity, const double* separation,
                                       double* out, size_t n) {
  if (!model || (n > 0 && (!separation || !out))) return ASPERITY_BAD_HANDLE;
  if (quantity < 0 || quantity >= asperity::contact_quantity_count) {
    for (size_t i = 0; i < n; ++i) out[i] = not_a_number;
    return ASPERITY_BAD_PARAMETER;
  }
  // the status from the inputs, read before out (which may be separation) is written
  bool bad = false;
  for (size_t i = 0; i < n; ++i) bad |= std::isnan(separation[i]);
  model->model.at_separations(static_cast<asperity::ContactQuantity>(quantity), separation, out, n);
  if (bad) return ASPERITY_BAD_SEPARATION;
  bool outside = false;
  for (size_t i = 0; i < n; ++i) outside |= std::isnan(out[i]);
  return outside ? ASPERITY_OUTSIDE_RANGE : ASPERITY_OK;
}

void asperity_model_close(asperity_model* model) { delete model; }

// asperity.h's asperity_physical_state is PhysicalState field for field: its names and order
// checked here against the one list (physical_state_fields.hpp)
#define ASPERITY_SAME_FIELD(type, name, column, meaning)                                          \
  static_assert(offsetof(asperity_physical_state, name) == offsetof(asperity::PhysicalState, name), \
                "asperity.h's asperity_physical_state." #name " is out of place");
ASPERITY_PHYSICAL_STATE_FIELDS(ASPERITY_SAME_FIELD)
#undef ASPERITY_SAME_FIELD
static_assert(sizeof(asperity_physical_state) == sizeof(asperity::PhysicalState),
              "asperity.h's asperity_physical_state has fields PhysicalState lacks");
// the same for asperity_contact_state (ContactState, contact.hpp) and
// asperity_contact_curves_state (ContactCurvesState, contact_curves.hpp)
#define ASPERITY_SAME_FIELD(type, name, column, meaning)                                            \
  static_assert(offsetof(asperity_contact_state, name) == offsetof(asperity::ContactState, name), \
                "asperity.h's asperity_contact_state." #name " is out of place");
ASPERITY_CONTACT_STATE_FIELDS(ASPERITY_SAME_FIELD)
#undef ASPERITY_SAME_FIELD
static_assert(sizeof(asperity_contact_state) == sizeof(asperity::ContactState),
              "asperity.h's asperity_contact_state has fields ContactState lacks");
#define ASPERITY_SAME_FIELD(type, name, column, meaning)                                                          \
  static_assert(offsetof(asperity_contact_curves_state, name) == offsetof(asperity::ContactCurvesState, name), \
                "asperity.h's asperity_contact_curves_state." #name " is out of place");
ASPERITY_CONTACT_CURVES_STATE_FIELDS(ASPERITY_SAME_FIELD)
#undef ASPERITY_SAME_FIELD
static_assert(sizeof(asperity_contact_curves_state) == sizeof(asperity::ContactCurvesState),
              "asperity.h's asperity_contact_curves_state has fields ContactCurvesState lacks");

static int physical_query(const asperity_model* model, double input, asperity_physical_state* out,
                          asperity::PhysicalState (asperity::ContactModel::*query)(double) const noexcept) {
  if (!model || !out) return ASPERITY_BAD_HANDLE;
  const asperity::PhysicalState state = (model->model.*query)(input);
#define ASPERITY_COPY_FIELD(type, name, column, meaning) out->name = state.name;
  ASPERITY_PHYSICAL_STATE_FIELDS(ASPERITY_COPY_FIELD)
#undef ASPERITY_COPY_FIELD
  if (std::isnan(input)) return ASPERITY_BAD_SEPARATION;
  // the count is NaN for a number in only where the separation is not served (a scene table's range)
  return std::isnan(state.count) ? ASPERITY_OUTSIDE_RANGE : ASPERITY_OK;
}

int asperity_model_at_separation(const asperity_model* model, double separation, asperity_physical_state* out) {
  return physical_query(model, separation, out, &asperity::ContactModel::at_separation);
}
int asperity_model_at_load(const asperity_model* model, double load, asperity_physical_state* out) {
  return physical_query(model, load, out, &asperity::ContactModel::at_load);
}
int asperity_model_at_pressure(const asperity_model* model, double pressure, asperity_physical_state* out) {
  return physical_query(model, pressure, out, &asperity::ContactModel::at_pressure);
}
int asperity_model_at_real_area(const asperity_model* model, double real_area, asperity_physical_state* out) {
  return physical_query(model, real_area, out, &asperity::ContactModel::at_real_area);
}

double asperity_contact_modulus(double young1, double poisson1, double young2, double poisson2) {
  try {
    return asperity::contact_modulus_from(young1, poisson1, young2, poisson2);
  } catch (const std::exception&) {
    return not_a_number;
  }
}

double asperity_height_scale_from_rms(const char* dist, double shape, double rms) {
  asperity::Distribution distribution;
  if (!dist || !asperity::parse_distribution(dist, distribution)) return not_a_number;
  try {
    const double scale = asperity::height_scale_from_rms(distribution, shape, rms);
    // a shape so small or large that c_a overflows or vanishes has no usable scale
    return std::isfinite(scale) && scale > 0 ? scale : not_a_number;
  } catch (const std::exception&) {
    return not_a_number;
  }
}

double asperity_eval(const asperity_curve* curve, int twice_order, double sep) {
  return curve ? curve->curve.value(twice_order, sep) : not_a_number;
}

double asperity_eval_log(const asperity_curve* curve, int twice_order, double sep) {
  return curve ? curve->curve.log_value(twice_order, sep) : not_a_number;
}


int asperity_eval_batch(const asperity_curve* curve, int twice_order, const double* sep, double* out, size_t n) {
  return eval_batch(curve, twice_order, sep, out, n, false);
}

int asperity_eval_log_batch(const asperity_curve* curve, int twice_order, const double* sep, double* out, size_t n) {
  return eval_batch(curve, twice_order, sep, out, n, true);
}

int asperity_contact(const asperity_curve* curve, double summit_count, double summit_radius, double height_scale,
                     double contact_modulus, double sep, asperity_contact_state* out) {
  if (!curve || !out) return ASPERITY_BAD_HANDLE;
  asperity::ContactState state;
  const bool ok = asperity::contact_at(curve->curve, {summit_count, summit_radius, height_scale, contact_modulus},
                                       sep, state);
#define ASPERITY_COPY_FIELD(type, name, column, meaning) out->name = state.name;
  ASPERITY_CONTACT_STATE_FIELDS(ASPERITY_COPY_FIELD)
#undef ASPERITY_COPY_FIELD
  if (ok) return ASPERITY_OK;
  if (!std::isfinite(sep)) return ASPERITY_BAD_SEPARATION;
  return curve->curve.serves(sep) ? ASPERITY_BAD_PARAMETER : ASPERITY_OUTSIDE_RANGE;
}

int asperity_curve_range(const asperity_curve* curve, double* min, double* max) {
  if (!curve || !min || !max) {
    if (min) *min = not_a_number;
    if (max) *max = not_a_number;
    return ASPERITY_BAD_HANDLE;
  }
  *min = curve->curve.served_min_separation();
  *max = curve->curve.served_max_separation();
  return ASPERITY_OK;
}

double asperity_standardized_from_origin(const asperity_curve* curve, double sep) {
  return curve ? asperity::standardized_from_origin(curve->curve, sep) : not_a_number;
}

double asperity_origin_from_standardized(const asperity_curve* curve, double standardized) {
  return curve ? asperity::origin_from_standardized(curve->curve, standardized) : not_a_number;
}

int asperity_contact_modulus_given(double contact_modulus, double young1, double poisson1, double young2,
                                   double poisson2, double* out, char* err, size_t err_size) {
  if (!out) return ASPERITY_BAD_HANDLE;
  try {
    *out = asperity::contact_modulus_given(contact_modulus, young1, poisson1, young2, poisson2);
    return ASPERITY_OK;
  } catch (const std::exception& error) {
    *out = not_a_number;
    write_error(err, err_size, error.what());
    return ASPERITY_BAD_PARAMETER;
  }
}

int asperity_model_pressure_overclosure_card(const asperity_model* model, double pressure_min, double pressure_max,
                                             double tolerance, const char* format, const char* units,
                                             const char* description, char* buffer, size_t buffer_size,
                                             size_t* length, char* err, size_t err_size) {
  if (!model) return ASPERITY_BAD_HANDLE;
  asperity::CardFormat card_format;
  asperity::CardUnits card_units;
  if (!card_names(format, units, card_format, card_units, err, err_size)) return ASPERITY_BAD_NAME;
  return card_out(
      [&](std::ostream& out) {
        const asperity::PressureOverclosureTable table =
            asperity::tabulate_pressure_overclosure(model->model, pressure_min, pressure_max, tolerance);
        asperity::write_pressure_overclosure(out, table, card_format, card_units, description ? description : "");
      },
      buffer, buffer_size, length, err, err_size);
}

namespace {
// The *_card_options functions' datum, cap and face size: the command line's defaults.
bool card_options(const char* datum, size_t max_points, double face_size, asperity::CardFormat card_format,
                  asperity::CardUnits card_units, asperity::OverclosureDatum& card_datum, std::size_t& cap,
                  double& face_size_m, char* err, size_t err_size) {
  card_datum = asperity::OverclosureDatum::zero_pressure;
  if (datum && !asperity::parse_overclosure_datum(datum, card_datum)) {
    write_error(err, err_size, "unknown overclosure datum (zero-pressure, mean-summit, origin or mean-plane)");
    return false;
  }
  cap = max_points == 0 ? asperity::default_card_points(card_format) : max_points;
  face_size_m = std::isnan(face_size) ? face_size : face_size * asperity::card_length_unit(card_units);
  return true;
}

// The card of a model or of contact curves with the _options functions' names and values (C++
// linkage: a template, inside the extern "C" block)
extern "C++" template <class Source>
int card_with_options(const Source& source, double pressure_min, double pressure_max, double tolerance,
                      const char* format, const char* units, const char* datum, size_t max_points, double face_size,
                      const char* description, char* buffer, size_t buffer_size, size_t* length, char* err,
                      size_t err_size) {
  asperity::CardFormat card_format;
  asperity::CardUnits card_units;
  if (!card_names(format, units, card_format, card_units, err, err_size)) return ASPERITY_BAD_NAME;
  asperity::OverclosureDatum card_datum;
  std::size_t cap;
  double face_size_m;
  if (!card_options(datum, max_points, face_size, card_format, card_units, card_datum, cap, face_size_m, err, err_size))
    return ASPERITY_BAD_NAME;
  return card_out(
      [&](std::ostream& out) {
        if (!(std::isnan(face_size) || face_size > 0)) throw asperity::Error("the face size must be positive");
        const asperity::PressureOverclosureTable table = asperity::tabulate_pressure_overclosure(
            source, pressure_min, pressure_max, tolerance, card_datum, cap);
        asperity::write_pressure_overclosure(out, table, card_format, card_units, description ? description : "",
                                             face_size_m);
      },
      buffer, buffer_size, length, err, err_size);
}
}  // namespace

int asperity_model_pressure_overclosure_card_options(const asperity_model* model, double pressure_min,
                                                     double pressure_max, double tolerance, const char* format,
                                                     const char* units, const char* datum, size_t max_points,
                                                     double face_size, const char* description, char* buffer,
                                                     size_t buffer_size, size_t* length, char* err, size_t err_size) {
  if (!model) return ASPERITY_BAD_HANDLE;
  return card_with_options(model->model, pressure_min, pressure_max, tolerance, format, units, datum, max_points,
                           face_size, description, buffer, buffer_size, length, err, err_size);
}

asperity_status asperity_contact_curves_load(const char* path, asperity_contact_curves** curves, char* err,
                                             size_t err_size) {
  if (!curves || !path) {
    write_error(err, err_size, "asperity_contact_curves_load: NULL path or output");
    if (curves) *curves = nullptr;
    return ASPERITY_BAD_HANDLE;
  }
  *curves = nullptr;
  return guarded_status(err, err_size, "asperity_contact_curves_load", ASPERITY_FAILURE, curves,
                        [&] { return new asperity_contact_curves{asperity::ContactCurves::open(path)}; });
}

void asperity_contact_curves_close(asperity_contact_curves* curves) { delete curves; }

int asperity_contact_curves_get_info(const asperity_contact_curves* curves, asperity_contact_curves_info* out) {
  if (!curves || !out) return ASPERITY_BAD_HANDLE;
  const asperity::ContactCurves& c = curves->curves;
  const asperity::ContactCurvesData& data = c.data();
  asperity_contact_curves_info info{};
  info.min_separation = c.min_separation();
  info.max_separation = c.max_separation();
  info.min_pressure = c.min_pressure();
  info.max_pressure = c.max_pressure();
  for (int i = 0; i < 3; ++i) {
    info.max_rel_error[i] = data.max_rel_error[i];
    info.measured_rel_error[i] = data.measured_rel_error[i];
  }
  info.safety_factor = data.safety_factor;
  info.solver_tolerance = data.solver_tolerance;
  info.contact_modulus = data.contact_modulus;
  info.nominal_area = data.nominal_area;
  info.mean_summit_height = data.mean_summit_height;
  info.nodes = static_cast<int>(data.separation.size());
  info.check_points = data.check_points;
  *out = info;
  return ASPERITY_OK;
}

double asperity_contact_curves_pressure(const asperity_contact_curves* curves, double separation) {
  return curves ? curves->curves.pressure(separation) : not_a_number;
}
double asperity_contact_curves_stiffness(const asperity_contact_curves* curves, double separation) {
  return curves ? curves->curves.stiffness(separation) : not_a_number;
}
double asperity_contact_curves_area_fraction(const asperity_contact_curves* curves, double separation) {
  return curves ? curves->curves.area_fraction(separation) : not_a_number;
}
double asperity_contact_curves_separation(const asperity_contact_curves* curves, double pressure) {
  return curves ? curves->curves.separation_at_pressure(pressure) : not_a_number;
}
double asperity_contact_curves_summit_count(const asperity_contact_curves* curves, double separation) {
  return curves ? curves->curves.summit_count(separation) : not_a_number;
}
double asperity_contact_curves_summit_count_max_rel_error(const asperity_contact_curves* curves) {
  if (!curves || curves->curves.data().summit_count.empty()) return not_a_number;
  return curves->curves.data().summit_count_max_rel_error;
}
double asperity_contact_curves_approach_separation(const asperity_contact_curves* curves) {
  return curves ? curves->curves.data().approach_separation : not_a_number;
}
int asperity_contact_curves_has_tension(const asperity_contact_curves* curves) {
  return curves && curves->curves.has_tension() ? 1 : 0;
}
double asperity_contact_curves_pull_off_pressure(const asperity_contact_curves* curves) {
  return curves ? curves->curves.pull_off_pressure() : not_a_number;
}
double asperity_contact_curves_pull_off_separation(const asperity_contact_curves* curves) {
  return curves ? curves->curves.pull_off_separation() : not_a_number;
}

namespace {
int curves_state(const asperity::ContactCurvesState& state, double input, asperity_contact_curves_state* out) {
#define ASPERITY_COPY_FIELD(type, name, column, meaning) out->name = state.name;
  ASPERITY_CONTACT_CURVES_STATE_FIELDS(ASPERITY_COPY_FIELD)
#undef ASPERITY_COPY_FIELD
  if (std::isnan(input)) return ASPERITY_BAD_SEPARATION;
  return std::isnan(state.pressure) || std::isnan(state.separation) ? ASPERITY_OUTSIDE_RANGE : ASPERITY_OK;
}
}  // namespace

int asperity_contact_curves_at_separation(const asperity_contact_curves* curves, double separation,
                                          asperity_contact_curves_state* out) {
  if (!curves || !out) return ASPERITY_BAD_HANDLE;
  return curves_state(curves->curves.at_separation(separation), separation, out);
}

int asperity_contact_curves_at_pressure(const asperity_contact_curves* curves, double pressure,
                                        asperity_contact_curves_state* out) {
  if (!curves || !out) return ASPERITY_BAD_HANDLE;
  return curves_state(curves->curves.at_pressure(pressure), pressure, out);
}

int asperity_contact_curves_pressure_overclosure_card(const asperity_contact_curves* curves, double pressure_min,
                                                      double pressure_max, double tolerance, const char* format,
                                                      const char* units, const char* description, char* buffer,
                                                      size_t buffer_size, size_t* length, char* err, size_t err_size) {
  if (!curves) return ASPERITY_BAD_HANDLE;
  asperity::CardFormat card_format;
  asperity::CardUnits card_units;
  if (!card_names(format, units, card_format, card_units, err, err_size)) return ASPERITY_BAD_NAME;
  return card_out(
      [&](std::ostream& out) {
        const asperity::PressureOverclosureTable table =
            asperity::tabulate_pressure_overclosure(curves->curves, pressure_min, pressure_max, tolerance);
        asperity::write_pressure_overclosure(out, table, card_format, card_units, description ? description : "");
      },
      buffer, buffer_size, length, err, err_size);
}

int asperity_contact_curves_pressure_overclosure_card_options(const asperity_contact_curves* curves,
                                                              double pressure_min, double pressure_max,
                                                              double tolerance, const char* format, const char* units,
                                                              const char* datum, size_t max_points, double face_size,
                                                              const char* description, char* buffer,
                                                              size_t buffer_size, size_t* length, char* err,
                                                              size_t err_size) {
  if (!curves) return ASPERITY_BAD_HANDLE;
  return card_with_options(curves->curves, pressure_min, pressure_max, tolerance, format, units, datum, max_points,
                           face_size, description, buffer, buffer_size, length, err, err_size);
}

int asperity_tabulated_pressure_overclosure_card(const double* pressures, const double* overclosures, size_t count,
                                                 const char* format, const char* units, const char* description,
                                                 const char* notes, char* buffer, size_t buffer_size, size_t* length,
                                                 char* err, size_t err_size) {
  if (count > 0 && (!pressures || !overclosures)) return ASPERITY_BAD_HANDLE;
  asperity::CardFormat card_format;
  asperity::CardUnits card_units;
  if (!card_names(format, units, card_format, card_units, err, err_size)) return ASPERITY_BAD_NAME;
  return card_out(
      [&](std::ostream& out) {
        std::vector<asperity::PressureOverclosurePoint> points(count);
        for (size_t i = 0; i < count; ++i) points[i] = {pressures[i], overclosures[i]};
        asperity::write_tabulated_pressure_overclosure(out, points, card_format, card_units,
                                                       description ? description : "", notes ? notes : "");
      },
      buffer, buffer_size, length, err, err_size);
}

const char* asperity_version(void) { return ASPERITY_VERSION_STRING; }

const char* asperity_status_string(int status) {
  switch (status) {
    case ASPERITY_OK: return "ok";
    case ASPERITY_BAD_HANDLE: return "NULL curve, model, table, input or output";
    case ASPERITY_BAD_ORDER: return "twice_order outside 0..5, or a bad order mask";
    case ASPERITY_BAD_SEPARATION: return "a separation is NaN or infinite";
    case ASPERITY_BAD_PARAMETER: return "a physical parameter is not a positive finite number";
    case ASPERITY_FILE_MISSING: return "no such table file";
    case ASPERITY_FILE_UNREADABLE: return "the table file cannot be read (not a regular file, permission, I/O)";
    case ASPERITY_NOT_HDF5: return "not a table file (nor any HDF5 file)";
    case ASPERITY_OTHER_SCHEMA: return "an HDF5 file, but not an asperity table";
    case ASPERITY_OTHER_VERSION: return "an asperity table of another format version (regenerate it)";
    case ASPERITY_DAMAGED: return "the table file is damaged (truncated or changed since it was written)";
    case ASPERITY_INVALID_TABLE: return "the table file breaks the schema or its limits";
    case ASPERITY_BAD_NAME: return "unknown distribution or side name";
    case ASPERITY_NOT_IN_TABLE: return "the table has no such curve, or the shape is outside it";
    case ASPERITY_NO_MEMORY: return "out of memory";
    case ASPERITY_FAILURE: return "failure";
    case ASPERITY_OUTSIDE_RANGE: return "a separation lies outside the ones the curve serves (a scene table's range)";
    default: return "unknown status";
  }
}

}  // extern "C"
