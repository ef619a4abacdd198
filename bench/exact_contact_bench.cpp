// The exact contact's speed (topography/exact_contact.hpp; docs/exact-contact.md, Speed): time
// per load step and per constrained-CG iteration over map sizes, against the baseline of the
// same binary, one 2-D FFT pair (forward and inverse) of the solve grid: an iteration costs two
// convolutions, so iteration / FFT pair stays near a constant if the cost per iteration is
// O(N log N).
//
// The surface: self-affine, H 0.8, roll-off at a quarter of the map, cutoff at 4 pixels, rms
// height 1 um on a 1 mm map, E* 1e11 Pa; the load steps p / (E* h'_rms) = 0.01, 0.02, 0.05, 0.1
// (area fractions of about 2% to 20%), each from the last (a warm start), the incremental
// stiffness solved at each. Counters: seconds per step (wall, and CPU over all threads), iterations per step (constrained,
// stiffness, and the coarse start's), seconds per convolution, and that over the FFT pair's time.
// The default solver (preconditioned, started from the coarsened map) beside Polonsky and Keer's
// as published (periodic_fourier_polonsky_keer: the reference, no coarse start) and the
// preconditioned one without the coarse start.
//
//   build/bench/exact_contact_bench                        # all sizes (2048^2 takes minutes)
//   build/bench/exact_contact_bench --benchmark_filter=/512
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <ctime>
#include <vector>

#include "asperity/topography/exact_contact.hpp"
#include "asperity/topography/self_affine.hpp"
#include "statistics/fft.hpp"

namespace {
using namespace asperity::topography;

HeightMap surface(std::size_t n) {
  SelfAffineSpectrum spectrum;
  spectrum.hurst = 0.8;
  spectrum.rolloff_wavelength = 1e-3 / 4;
  spectrum.cutoff_wavelength = 4e-3 / static_cast<double>(n);
  spectrum.rms_height = 1e-6;
  return self_affine_surface(n, n, 1e-3 / static_cast<double>(n), 1e-3 / static_cast<double>(n), spectrum, 1);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One forward and one inverse 2-D transform of an n x n field, as the solver's convolution does.
double fft_pair_seconds(std::size_t n) {
  std::vector<double> field(n * n, 1.0);
  std::vector<std::complex<double>> spectrum(n * (n / 2 + 1));
  int repeats = 0;
  const auto start = std::chrono::steady_clock::now();
  do {
    detail::forward_2d(field.data(), spectrum.data(), n, n);
    detail::inverse_2d(spectrum.data(), field.data(), n, n);
    ++repeats;
  } while (seconds_since(start) < 0.5);
  return seconds_since(start) / repeats;
}

void steps(benchmark::State& state, ContactBoundary boundary, ContactKernel kernel, bool warm, int threads,
           ContactSolver method = ContactSolver::preconditioned, bool coarse_start = true) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const HeightMap map = surface(n);
  const double unit = 1e11 * spectral_rms_gradient(map);
  const std::vector<double> loads{0.01, 0.02, 0.05, 0.1};
  const std::size_t grid = boundary == ContactBoundary::padded ? 2 * n : n;
  const double pair = fft_pair_seconds(grid);
  double total = 0, setup = 0, cpu = 0;
  long iterations = 0, stiffness_iterations = 0, coarse_iterations = 0, count = 0;
  for (auto _ : state) {
    ExactContactOptions options;
    options.contact_modulus = 1e11;
    options.boundary = boundary;
    options.kernel = kernel;
    options.threads = threads;
    options.solver = method;
    options.coarse_start = coarse_start;
    const auto built = std::chrono::steady_clock::now();
    ExactContact solver(map, options);
    setup += seconds_since(built);
    for (double load : loads) {
      const auto start = std::chrono::steady_clock::now();
      const std::clock_t cpu_start = std::clock();
      if (!warm) solver = ExactContact(map, options);
      const ContactStep step = solver.at_pressure(load * unit);
      const double seconds = seconds_since(start);
      cpu += static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
      total += seconds;
      iterations += step.iterations;
      stiffness_iterations += step.stiffness_iterations;
      coarse_iterations += step.coarse_iterations;
      ++count;
      std::fprintf(stderr, "  %zu^2 %s %s %s%s: p/(E* h') %.2f, area %.4f, %d + %d iterations (+ %d coarse), %.2f s\n", n,
                   contact_boundary_name(boundary), contact_kernel_name(kernel), contact_solver_name(method),
                   coarse_start ? " coarse start" : "", load, step.area_fraction, step.iterations,
                   step.stiffness_iterations, step.coarse_iterations, seconds);
    }
  }
  // an iteration of either kind is about two convolutions (the constrained one) or one (the
  // stiffness one): count both as their convolutions; a coarse start's iteration as two on a
  // grid of a quarter the points (those on coarser grids cost less still)
  const double convolutions = 2.0 * static_cast<double>(iterations) + static_cast<double>(stiffness_iterations) +
                              0.5 * static_cast<double>(coarse_iterations);
  state.counters["s_per_step"] = total / static_cast<double>(count);
  // the process's CPU time over all threads: on a machine shared with other work the wall time
  // above grows, this one less so
  state.counters["cpu_s_per_step"] = cpu / static_cast<double>(count);
  state.counters["iterations_per_step"] = static_cast<double>(iterations) / static_cast<double>(count);
  state.counters["stiffness_iterations_per_step"] = static_cast<double>(stiffness_iterations) / static_cast<double>(count);
  state.counters["coarse_iterations_per_step"] = static_cast<double>(coarse_iterations) / static_cast<double>(count);
  state.counters["s_per_convolution"] = total / convolutions;
  state.counters["convolution_over_fft_pair"] = total / convolutions / pair;
  state.counters["s_fft_pair"] = pair;
  state.counters["s_setup"] = setup / static_cast<double>(state.iterations());
}

void periodic_fourier(benchmark::State& state) { steps(state, ContactBoundary::periodic, ContactKernel::fourier, true, 0); }
void periodic_fourier_polonsky_keer(benchmark::State& state) {
  steps(state, ContactBoundary::periodic, ContactKernel::fourier, true, 0, ContactSolver::polonsky_keer, false);
}
void periodic_fourier_no_coarse_start(benchmark::State& state) {
  steps(state, ContactBoundary::periodic, ContactKernel::fourier, true, 0, ContactSolver::preconditioned, false);
}
void periodic_fourier_one_thread(benchmark::State& state) {
  steps(state, ContactBoundary::periodic, ContactKernel::fourier, true, 1);
}
void periodic_fourier_cold(benchmark::State& state) { steps(state, ContactBoundary::periodic, ContactKernel::fourier, false, 0); }
void periodic_love(benchmark::State& state) { steps(state, ContactBoundary::periodic, ContactKernel::love, true, 0); }
void padded_love(benchmark::State& state) { steps(state, ContactBoundary::padded, ContactKernel::love, true, 0); }

BENCHMARK(periodic_fourier)->RangeMultiplier(2)->Range(128, 2048)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(periodic_fourier_polonsky_keer)->RangeMultiplier(2)->Range(128, 2048)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(periodic_fourier_no_coarse_start)->RangeMultiplier(4)->Range(512, 2048)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(periodic_fourier_one_thread)->Arg(512)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(periodic_fourier_cold)->Arg(512)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(periodic_love)->Arg(512)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(padded_love)->Arg(512)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
