// The contact kernel's record and entry point, for the layers above core that serve their own
// curves through it (physics' ContactCurves): the kernels themselves stay core's
// (runtime/core/kernel/kernels.hpp, which includes this for the record's one definition).
#pragma once
#include "asperity/contact_scales.hpp"
#include "asperity/detail/fast_grid.hpp"

namespace asperity::detail {

// The contact records (curve_data.hpp's CurveLookup::contact_records): per interval, six rows
// (the coefficient of y^j, j = 0..5) of four lanes, log2 X of orders 0, 1, 3/2, 1/2 (the state's
// order: count, area, load, stiffness, so that the products need no permutation and the
// stiffness/load ratio is within the upper half), from a 64-byte boundary (three cache lines).
// (Why base 2, and the coefficients' accuracy: kernels.hpp.)
inline constexpr int contact_record_size = 4 * fast_stride;  // doubles: [coefficient][lane]
// each lane's twice_order: the served combination's (contact_scales.hpp), in its quantities' order
inline constexpr int contact_lane_orders[4] = {served_combination.twice_order[0], served_combination.twice_order[1],
                                               served_combination.twice_order[2], served_combination.twice_order[3]};

// The four lanes at position y of one record: log2s[k] = log2 X and values[k] = 2^log2s[k], output
// k taking the lane whose contact_lane_orders entry is k (kernels.hpp's Kernels::contact4).
using Contact4 = void (*)(const double* record, double y, double* log2s, double* values) noexcept;
// The one built for this CPU (the best instruction set's kernels, kernels_dispatch.cpp).
Contact4 best_contact4() noexcept;

}  // namespace asperity::detail
