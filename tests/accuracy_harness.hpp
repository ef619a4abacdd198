// Shared machinery of the accuracy tests: evaluate many (curve, order, separation) points
// against the 50-digit reference on all cores, and report the worst relative error per class.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "asperity/curve.hpp"
#include "reference.hpp"
#include "test_subsample.hpp"

namespace asperity::test {

struct Probe {
  const Curve* curve;
  int twice_order;
  double separation;
  double tolerance;   // allowed relative error
  std::string label;  // for the message
  double reference = 0, value = 0, error = 0;
  // Take the reference from closed_form_log where it holds (reference.hpp), else quadrature.
  bool closed_form = false;
};


// Fills reference, value and error of every probe (relative error |X/X_ref - 1|, from logs),
// every subsample_stride()-th probe only where that is above 1.
inline void evaluate(std::vector<Probe>& probes) {
  if (const std::size_t stride = subsample_stride(); stride > 1) {
    std::vector<Probe> kept;
    for (std::size_t i = 0; i < probes.size(); i += stride) kept.push_back(probes[i]);
    probes.swap(kept);
  }
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned worker = 0; worker < threads; ++worker)
    pool.emplace_back([&, worker] {
      for (std::size_t i = worker; i < probes.size(); i += threads) {
        Probe& probe = probes[i];
        const Curve& curve = *probe.curve;
        std::optional<Precise> exact;
        if (probe.closed_form)
          exact = closed_form_log(curve.distribution(), curve.side(), curve.shape(), probe.twice_order, probe.separation);
        probe.reference = static_cast<double>(
            exact ? *exact
                  : reference_log(curve.distribution(), curve.side(), curve.shape(), order_of(probe.twice_order),
                                  probe.separation));
        probe.value = curve.log_value(probe.twice_order, probe.separation);
        if (std::isinf(probe.reference) && probe.reference < 0)
          probe.error = (std::isinf(probe.value) && probe.value < 0) ? 0.0 : INFINITY;
        else
          probe.error = std::fabs(std::expm1(probe.value - probe.reference));
        if (std::isnan(probe.error)) probe.error = INFINITY;
      }
    });
  for (std::thread& thread : pool) thread.join();
}

// The tolerance class of a point on a grid shape (issue #2): 1e-12 where X >= 1e-100,
// 1e-10 below, and 1e-10 in the asymptotic regions beyond the table.
inline double grid_tolerance(const Curve& curve, double log_reference, double separation) {
  const bool beyond = separation > curve.table_max_separation();
  if (beyond) return 1e-10;
  return log_reference >= std::log(1e-100) ? 1e-12 : 1e-10;
}

}  // namespace asperity::test
