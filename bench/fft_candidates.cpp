// The FFT libraries Debian offers, measured on what asperity needs: a 2-d real-to-complex
// transform and back (surface spectra, Gaussian random fields, the elastic half-space's
// Green's function), in double precision. Built and run by scripts/fft-candidates.sh, outside
// the project's build: FFTW is GPL (asperity is MIT) and is measured here only as the reference
// a choice is weighed against; it is never linked into asperity.
//   kissfft.hh   libkissfft-dev, BSD-3-Clause, header-only C++ template (double)
//   Eigen FFT    libeigen3-dev, MPL-2.0, unsupported/Eigen/FFT (kissfft-derived, double)
//   pocketfft    python3-pythran (pythran/pythonic/numpy/fft/pocketfft.hpp: pocketfft_hdronly,
//                numpy's and scipy's FFT), BSD-3-Clause, header-only C++ (double), one thread
//   FFTW 3       libfftw3-dev, GPL-2+, fftw_plan_dft_r2c_2d (FFTW_ESTIMATE and FFTW_MEASURE)
#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <complex>
#include <kissfft/kissfft.hh>
#include <pythran/pythonic/numpy/fft/pocketfft.hpp>
#include <random>
#include <unsupported/Eigen/FFT>
#include <vector>

namespace {
using cpx = std::complex<double>;

std::vector<double> field(std::size_t n) {
  std::mt19937_64 random(1);
  std::normal_distribution<double> normal;
  std::vector<double> h(n * n);
  for (double& v : h) v = normal(random);
  return h;
}

// rows by the real transform, then each of the n/2+1 columns by a complex one
template <class RowReal, class Column>
void forward_2d(std::size_t n, const std::vector<double>& in, std::vector<cpx>& out, std::vector<cpx>& row,
                std::vector<cpx>& column, std::vector<cpx>& column_out, RowReal row_real, Column column_fft) {
  const std::size_t half = n / 2 + 1;
  for (std::size_t j = 0; j < n; ++j) {
    row_real(in.data() + j * n, row.data());
    for (std::size_t i = 0; i < half; ++i) out[j * half + i] = row[i];
  }
  for (std::size_t i = 0; i < half; ++i) {
    for (std::size_t j = 0; j < n; ++j) column[j] = out[j * half + i];
    column_fft(column.data(), column_out.data());
    for (std::size_t j = 0; j < n; ++j) out[j * half + i] = column_out[j];
  }
}

void BM_KissFFT(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const std::vector<double> h = field(n);
  std::vector<cpx> out(n * (n / 2 + 1)), row(n), column(n), column_out(n);
  kissfft<double> real_rows(n / 2, false), columns(n, false);
  for (auto _ : state) {
    forward_2d(
        n, h, out, row, column, column_out, [&](const double* src, cpx* dst) { real_rows.transform_real(src, dst); },
        [&](const cpx* src, cpx* dst) { columns.transform(src, dst); });
    benchmark::DoNotOptimize(out.data());
  }
  state.SetLabel("kissfft.hh (BSD)");
}

void BM_EigenFFT(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const std::vector<double> h = field(n);
  std::vector<cpx> out(n * (n / 2 + 1)), row(n), column(n), column_out(n);
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  for (auto _ : state) {
    forward_2d(
        n, h, out, row, column, column_out, [&](const double* src, cpx* dst) { fft.fwd(dst, src, static_cast<int>(n)); },
        [&](const cpx* src, cpx* dst) { fft.fwd(dst, src, static_cast<int>(n)); });
    benchmark::DoNotOptimize(out.data());
  }
  state.SetLabel("Eigen FFT (MPL-2.0)");
}

void BM_PocketFFT(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const std::vector<double> h = field(n);
  std::vector<cpx> out(n * (n / 2 + 1));
  const pocketfft::shape_t shape{n, n};
  const pocketfft::stride_t in_stride{static_cast<std::ptrdiff_t>(n * sizeof(double)), sizeof(double)};
  const pocketfft::stride_t out_stride{static_cast<std::ptrdiff_t>((n / 2 + 1) * sizeof(cpx)), sizeof(cpx)};
  for (auto _ : state) {
    pocketfft::r2c(shape, in_stride, out_stride, {0, 1}, pocketfft::FORWARD, h.data(), out.data(), 1.0, 1);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetLabel("pocketfft (BSD)");
}

void fftw(benchmark::State& state, unsigned flags, const char* label) {
  const int n = static_cast<int>(state.range(0));
  std::vector<double> h = field(static_cast<std::size_t>(n));
  std::vector<double> in(h.size());
  std::vector<cpx> out(static_cast<std::size_t>(n) * (n / 2 + 1));
  fftw_plan plan =
      fftw_plan_dft_r2c_2d(n, n, in.data(), reinterpret_cast<fftw_complex*>(out.data()), flags);  // may overwrite in
  in = h;
  for (auto _ : state) {
    fftw_execute(plan);
    benchmark::DoNotOptimize(out.data());
  }
  fftw_destroy_plan(plan);
  state.SetLabel(label);
}
void BM_FFTW_Estimate(benchmark::State& state) { fftw(state, FFTW_ESTIMATE, "FFTW 3 estimate (GPL)"); }
void BM_FFTW_Measure(benchmark::State& state) { fftw(state, FFTW_MEASURE, "FFTW 3 measure (GPL)"); }

}  // namespace

#define SIZES Arg(256)->Arg(512)->Arg(650)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_KissFFT)->SIZES;
BENCHMARK(BM_EigenFFT)->SIZES;
BENCHMARK(BM_PocketFFT)->SIZES;
BENCHMARK(BM_FFTW_Estimate)->SIZES;
BENCHMARK(BM_FFTW_Measure)->SIZES;
BENCHMARK_MAIN();
