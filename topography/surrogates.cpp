#include "asperity/topography/surrogates.hpp"

#include <algorithm>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <numeric>

#include "asperity/error.hpp"
#include "fft.hpp"

namespace asperity::topography {
namespace {

constexpr double pi = 3.14159265358979323846;

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// xoshiro256** (Blackman & Vigna 2018): a few integer operations a draw (the ensemble draws a
// complex normal for every wavevector of every surrogate), its sequence defined by its code, so
// the same on every platform.
class Xoshiro256 {
 public:
  explicit Xoshiro256(std::uint64_t seed) {
    for (std::uint64_t& word : state_) word = seed = splitmix64(seed);
  }
  std::uint64_t operator()() noexcept {
    const std::uint64_t result = rotate(state_[1] * 5, 7) * 9, t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotate(state_[3], 45);
    return result;
  }
  // a uniform in (-1, 1), never 0... from 53 bits
  double symmetric() noexcept { return (static_cast<double>((*this)() >> 11) + 0.5) * 0x1p-52 - 1; }

 private:
  static std::uint64_t rotate(std::uint64_t x, int k) noexcept { return (x << k) | (x >> (64 - k)); }
  std::uint64_t state_[4];
};

// Hann window of n points, sampled at the centres
std::vector<double> hann(std::size_t n) {
  std::vector<double> w(n);
  for (std::size_t k = 0; k < n; ++k) w[k] = 0.5 * (1 - std::cos(2 * pi * (static_cast<double>(k) + 0.5) / static_cast<double>(n)));
  return w;
}

}  // namespace

double normal_quantile(double p) { return -std::sqrt(2.0) * boost::math::erfc_inv(2 * p); }
double normal_cdf(double z) { return 0.5 * boost::math::erfc(-z / std::sqrt(2.0)); }

SurrogateFields::SurrogateFields(const HeightMap& map, const CorrelationLengths& lengths)
    : nx_(map.nx), ny_(map.ny) {
  if (nx_ < 3 || ny_ < 3 || map.heights.size() != nx_ * ny_)
    throw Error(map.source + ": surrogates need a map of at least 3 x 3 points");
  // normal scores: Phi^-1 of each valid height's mid-rank (ties share their mean rank)
  const std::size_t n = map.heights.size();
  std::vector<std::size_t> order;
  order.reserve(n);
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isnan(map.heights[k])) order.push_back(k);
  if (order.empty()) throw Error(map.source + ": no valid point for surrogates");
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return map.heights[a] < map.heights[b]; });
  scores_.assign(n, std::numeric_limits<double>::quiet_NaN());
  valid_.assign(n, 0);
  const double count = static_cast<double>(order.size());
  for (std::size_t first = 0; first < order.size();) {
    std::size_t last = first;
    while (last + 1 < order.size() && map.heights[order[last + 1]] == map.heights[order[first]]) ++last;
    const double rank = 0.5 * static_cast<double>(first + last) + 0.5;  // mid-rank, from 0.5
    const double score = normal_quantile(rank / count);
    for (std::size_t k = first; k <= last; ++k) {
      scores_[order[k]] = score;
      valid_[order[k]] = 1;
    }
    first = last + 1;
  }
  // the padded grid: two correlation lengths beyond the map (the autocorrelation is below 0.1
  // across the wrap), at most half the map, rounded up to a size of factors 2, 3 and 5 (the
  // FFT's fastest)
  const auto smooth = [](std::size_t n) {
    for (;; ++n) {
      std::size_t m = n;
      for (std::size_t f : {2, 3, 5})
        while (m % f == 0) m /= f;
      if (m == 1) return n;
    }
  };
  const auto pad = [&](std::size_t size, std::size_t length) {
    return smooth(size + std::min(std::max<std::size_t>(size / 2, 4), std::max<std::size_t>(8, 2 * length)));
  };
  px_ = pad(nx_, lengths.x);
  py_ = pad(ny_, lengths.y);
  // the Hann-windowed scores, zero-padded, and their periodogram
  const std::vector<double> wx = hann(nx_), wy = hann(ny_);
  std::vector<double> padded(px_ * py_, 0.0);
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i)
      if (valid_[j * nx_ + i]) padded[j * px_ + i] = wx[i] * wy[j] * scores_[j * nx_ + i];
  const std::size_t half = px_ / 2 + 1;
  std::vector<detail::Complex> spectrum(py_ * half);
  detail::forward_2d(padded.data(), spectrum.data(), py_, px_);
  std::vector<double> power(py_ * half);
  for (std::size_t k = 0; k < power.size(); ++k) power[k] = std::norm(spectrum[k]);
  // smoothed over the 3 x 3 nearest wavevectors: ky wraps around; kx = -1 is the mirror of kx = 1
  amplitude_.assign(py_ * half, 0.0);
  for (std::size_t j = 0; j < py_; ++j)
    for (std::size_t i = 0; i < half; ++i) {
      double sum = 0;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          long ii = static_cast<long>(i) + di;
          std::size_t jj = (j + py_ + static_cast<std::size_t>(dj + 1) - 1) % py_;
          if (ii < 0) {  // the conjugate of (1, -ky)
            ii = 1;
            jj = (py_ - jj) % py_;
          }
          if (ii >= static_cast<long>(half)) ii = static_cast<long>(half) - 1;
          sum += power[jj * half + static_cast<std::size_t>(ii)];
        }
      amplitude_[j * half + i] = std::sqrt(sum / 9);
    }
  amplitude_[0] = 0;  // the mean is set by standardizing
}

void SurrogateFields::generate(std::uint64_t seed, std::size_t index, std::vector<double>& field) const {
  Xoshiro256 engine(splitmix64(splitmix64(seed) ^ splitmix64(0x5D0BA7Eull + index)));
  const std::size_t half = px_ / 2 + 1;
  // buffers kept by each thread: a surrogate allocates nothing after the first
  thread_local std::vector<detail::Complex> coefficients;
  thread_local std::vector<double> padded;
  coefficients.resize(py_ * half);
  padded.resize(px_ * py_);
  for (std::size_t k = 0; k < coefficients.size(); ++k) {
    // a complex normal (Marsaglia's polar method: no trigonometry), times the spectrum's amplitude
    double u, v, s;
    do {
      u = engine.symmetric();
      v = engine.symmetric();
      s = u * u + v * v;
    } while (s >= 1 || s == 0);
    const double factor = amplitude_[k] * std::sqrt(-std::log(s) / s);
    coefficients[k] = detail::Complex(factor * u, factor * v);
  }
  detail::inverse_2d(coefficients.data(), padded.data(), py_, px_);
  field.assign(nx_ * ny_, std::numeric_limits<double>::quiet_NaN());
  long double sum = 0, squares = 0;
  std::size_t count = 0;
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i)
      if (valid_[j * nx_ + i]) {
        const double v = padded[j * px_ + i];
        sum += v;
        squares += static_cast<long double>(v) * v;
        ++count;
      }
  const double mean = static_cast<double>(sum / count);
  const double sd = std::sqrt(std::max(0.0L, squares / count - static_cast<long double>(mean) * mean));
  const double scale = sd > 0 ? 1 / sd : 0;
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i)
      if (valid_[j * nx_ + i]) field[j * nx_ + i] = (padded[j * px_ + i] - mean) * scale;
}

}  // namespace asperity::topography
