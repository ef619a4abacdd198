// The fields of the physical state (contact_model.hpp's PhysicalState), defined once, in order.
// PhysicalState's members, the C API's copy into asperity_physical_state, the Python records
// (PhysicalState's names, its docstring, their arrays) and the command line's CSV columns are
// made from this list; the C header (asperity.h), the Fortran module (asperity.f90) and the
// Python stubs (__init__.pyi) are checked against it by a test (test_physical_state_fields),
// which parses them.
//
// ASPERITY_PHYSICAL_STATE_FIELDS(X) calls X(name, column, meaning) per field: name the member,
// column the CSV column (the unit in its name), meaning what it is and its unit.
#pragma once
#include <cstddef>

#define ASPERITY_PHYSICAL_STATE_FIELDS(X)                                                         \
  X(separation, "separation_m", "d [m], from the model's datum (default: origin convention, the Weibull origin / Gaussian mean)") \
  X(mean_separation, "mean_separation_m", "[m], from the mean summit height")                     \
  X(count, "count", "summits in contact")                                                         \
  X(real_area, "real_area_m2", "A [m^2]")                                                         \
  X(area_fraction, "area_fraction", "A / A0")                                                     \
  X(load, "load_N", "P [N]")                                                                      \
  X(pressure, "nominal_pressure_Pa", "P / A0 [Pa]")                                               \
  X(stiffness, "stiffness_N_per_m", "K = -dP/dd [N/m]")                                           \
  X(stiffness_over_load, "stiffness_over_load_per_m", "K / P [1/m]")

namespace asperity {

struct PhysicalStateField {
  const char* name;     // the member's name, in every language
  const char* column;   // the CSV column
  const char* meaning;  // what it is, its unit
};

#define ASPERITY_PHYSICAL_STATE_FIELD_ENTRY(name, column, meaning) PhysicalStateField{#name, column, meaning},
inline constexpr PhysicalStateField physical_state_fields[] = {ASPERITY_PHYSICAL_STATE_FIELDS(ASPERITY_PHYSICAL_STATE_FIELD_ENTRY)};
#undef ASPERITY_PHYSICAL_STATE_FIELD_ENTRY
inline constexpr std::size_t physical_state_field_count = sizeof physical_state_fields / sizeof physical_state_fields[0];

}  // namespace asperity
