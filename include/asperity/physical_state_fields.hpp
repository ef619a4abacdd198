// The fields of the physical state (contact_model.hpp's PhysicalState), defined once, in order.
// PhysicalState's members, the C API's copy into asperity_physical_state, the Python records
// (PhysicalState's names, its docstring, their arrays) and the command line's CSV columns are
// made from this list; the C header (asperity.h), the Fortran module (asperity.f90) and the
// Python stubs (__init__.pyi) are checked against it by a test (test_physical_state_fields),
// which parses them.
//
// ASPERITY_PHYSICAL_STATE_FIELDS(X) calls X(type, name, column, meaning) per field (a record's
// list, record_fields.hpp): every field a double, name the member, column the CSV column (the unit
// in its name), meaning what it is and its unit.
#pragma once
#include <cstddef>

#include "asperity/record_fields.hpp"

#define ASPERITY_PHYSICAL_STATE_FIELDS(X)                                                         \
  X(double, separation, "separation_m", "d [m], from the model's datum (default: origin convention, the Weibull origin / Gaussian mean)") \
  X(double, mean_separation, "mean_separation_m", "[m], from the mean summit height")                     \
  X(double, count, "count", "summits in contact")                                                         \
  X(double, real_area, "real_area_m2", "A [m^2]")                                                         \
  X(double, area_fraction, "area_fraction", "A / A0")                                                     \
  X(double, load, "load_N", "P [N]")                                                                      \
  X(double, pressure, "nominal_pressure_Pa", "P / A0 [Pa]")                                               \
  X(double, stiffness, "stiffness_N_per_m", "K = -dP/dd [N/m]")                                           \
  X(double, stiffness_over_load, "stiffness_over_load_per_m", "K / P [1/m]")

namespace asperity {

using PhysicalStateField = RecordField;

inline constexpr RecordField physical_state_fields[] = {ASPERITY_PHYSICAL_STATE_FIELDS(ASPERITY_RECORD_FIELD_ENTRY)};
inline constexpr std::size_t physical_state_field_count = sizeof physical_state_fields / sizeof physical_state_fields[0];

}  // namespace asperity
