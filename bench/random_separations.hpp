// Random queries for the benchmarks: uniform on [lo, hi], reproducible from the seed.
#pragma once
#include <cstddef>
#include <random>
#include <vector>

namespace asperity::bench {

inline std::vector<double> uniform(double lo, double hi, std::size_t count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pick(lo, hi);
  std::vector<double> values(count);
  for (double& value : values) value = pick(rng);
  return values;
}

}  // namespace asperity::bench
