#include "asperity/topography/surrogates.hpp"

#include <algorithm>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "asperity/detail/parallel_for.hpp"
#include "asperity/error.hpp"
#include "statistics/fft.hpp"
#include "vector_math.hpp"

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

// the least size >= n of factors 2, 3 and 5 (the FFT's fastest)
std::size_t smooth(std::size_t n) {
  for (;; ++n) {
    std::size_t m = n;
    for (std::size_t f : {2, 3, 5})
      while (m % f == 0) m /= f;
    if (m == 1) return n;
  }
}

// the largest lag along an axis of `points` points and correlation length `length` (points)
std::size_t largest_lag(std::size_t points, std::size_t length) {
  using S = SurrogateSpectrum;
  return std::max<std::size_t>(2, std::min(S::largest_lag_map_numerator * points / S::largest_lag_map_denominator,
                                           S::largest_lag_lengths * std::max<std::size_t>(1, length)));
}

}  // namespace

double surrogate_lag_window(double u) noexcept {
  constexpr double flat = SurrogateSpectrum::window_flat;
  if (!(u < 1)) return 0;
  return u <= flat ? 1 : 0.5 * (1 + std::cos(pi * (u - flat) / (1 - flat)));
}

std::string surrogate_method() {
  using S = SurrogateSpectrum;
  const auto text = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return std::string(buffer);
  };
  return "Gaussian random fields with the spectrum of the map's normal scores estimated by Blackman and Tukey: "
         "the unbiased autocovariance (each lag over its pairs of valid points, the variance the mean and the "
         "leveling took restored) times Tukey's lag window (1 to " +
         text(S::window_flat) + " of the largest lag, a cosine taper to 0 at it; the largest lag " +
         std::to_string(S::largest_lag_lengths) + " correlation lengths, at most " +
         std::to_string(S::largest_lag_map_numerator) + "/" + std::to_string(S::largest_lag_map_denominator) +
         " of the map), on a grid the map plus the largest lag wide, cut to the map; each model's marginal by "
         "F^-1(Phi(g))";
}

double normal_quantile(double p) { return -std::sqrt(2.0) * boost::math::erfc_inv(2 * p); }
double normal_cdf(double z) { return 0.5 * boost::math::erfc(-z / std::sqrt(2.0)); }

SurrogateFields::SurrogateFields(const HeightMap& map, const CorrelationLengths& lengths, bool leveled, int threads)
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
  // The spectrum by Blackman and Tukey: the scores' autocovariance at every lag (x, y) by FFT,
  // each lag divided by the pairs of valid points it has (unbiased: the periodogram's own
  // division by N tapers the long lags, and took 2-4x from the spread of a surrogate's mean),
  // times a lag window (Tukey's, surrogate_lag_window: radial, zero beyond the largest lag), laid on the
  // surrogates' periodic grid and transformed: a spectrum whose surrogates have that
  // autocovariance at every lag up to the largest. The largest lag is six correlation lengths
  // (the autocorrelation is then ~1e-6 for an exponential one), at most three quarters of the
  // map (half the map cut the longest correlations: a surrogate's mean then spread 0.7-0.8 of the
  // process's; at three quarters 0.8-1.1, the variance's 1.0-1.2: measured over 8 maps in
  // test_topography_ensemble); the grid is the map plus that lag (so the periodic wrap adds no
  // correlation inside the map), rounded up to sizes of factors 2, 3 and 5 (the FFT's fastest).
  const std::size_t lag_x = largest_lag(nx_, lengths.x), lag_y = largest_lag(ny_, lengths.y);
  px_ = smooth(nx_ + lag_x);
  py_ = smooth(ny_ + lag_y);
  // Autocorrelations on a grid twice the map (no lag wraps onto another), by FFT: of a field
  // f(x) defined on the valid points, sum_x f(x) f(x + r) at every lag r.
  const std::size_t ax = smooth(2 * nx_), ay = smooth(2 * ny_), a_half = ax / 2 + 1;
  const auto autocorrelation = [&](const auto& value_at) {
    std::vector<detail::Complex> spectrum(ay * a_half);  // each call its own: they run side by side
    std::vector<double> field(ax * ay, 0.0);
    for (std::size_t j = 0; j < ny_; ++j)
      for (std::size_t i = 0; i < nx_; ++i)
        if (valid_[j * nx_ + i]) field[j * ax + i] = value_at(i, j);
    detail::forward_2d(field.data(), spectrum.data(), ay, ax);
    for (detail::Complex& c : spectrum) c = std::norm(c);
    detail::inverse_2d(spectrum.data(), field.data(), ay, ax);
    return field;
  };
  const auto at = [&](const std::vector<double>& field, long rx, long ry) {
    const std::size_t sx = static_cast<std::size_t>((rx + static_cast<long>(ax)) % static_cast<long>(ax));
    const std::size_t sy = static_cast<std::size_t>((ry + static_cast<long>(ay)) % static_cast<long>(ay));
    return field[sy * ax + sx];
  };
  const auto within = [&](long rx, long ry) {
    return std::hypot(static_cast<double>(rx) / static_cast<double>(lag_x),
                      static_cast<double>(ry) / static_cast<double>(lag_y)) < 1;
  };
  // The scores lack what the analysis took out of the map: their mean (0 by construction: ranks)
  // and, when the map was leveled, its plane. So every lag's autocovariance is low: with the
  // removed parts as coefficients of variances V_k on the functions phi_0 = 1, phi_1 = x - <x>,
  // phi_2 = y - <y>,
  //   E c(r) ~ C(r) - sum_k V_k mu_k(r),  mu_k(r) = the mean of phi_k(x) phi_k(x + r) over r's pairs,
  // and the scores are exactly orthogonal to each phi_b: sum over all pairs of
  // phi_b(x) phi_b(y) s(x) s(y) = 0. Taking C(r) = 0 beyond the largest lag makes these the
  // linear equations sum_k A_bk V_k = B_b, with B_b the sum over the pairs within the largest lag
  // of phi_b(x) phi_b(y) s(x) s(y) and A_bk the sum over the pairs beyond it of
  // (phi_b phi_k)(x) (phi_b phi_k)(y): the long lags' negative bias turned back into the
  // variance a surrogate must carry (without it a surrogate's mean over the map spread 2-4x too
  // little, and a leveled map's Weibull shape intervals missed the truth in a quarter of maps).
  double mean_i = 0, mean_j = 0;
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i)
      if (valid_[j * nx_ + i]) {
        mean_i += static_cast<double>(i);
        mean_j += static_cast<double>(j);
      }
  mean_i /= count;
  mean_j /= count;
  const int basis = leveled ? 3 : 1;
  const auto phi = [&](int k, std::size_t i, std::size_t j) {
    return k == 0 ? 1.0 : k == 1 ? static_cast<double>(i) - mean_i : static_cast<double>(j) - mean_j;
  };
  // The autocorrelations the equations need, independent of each other: computed side by side
  // (before the ensemble, the one part of the analysis that ran on one core). Kept: the scores', the mask's and each
  // phi_k's; the others reduced at once to the sums within the largest lag.
  const auto within_sum = [&](const std::vector<double>& field) {
    double sum = 0;
    for (long ry = -static_cast<long>(lag_y); ry <= static_cast<long>(lag_y); ++ry)
      for (long rx = -static_cast<long>(lag_x); rx <= static_cast<long>(lag_x); ++rx)
        if (within(rx, ry)) sum += at(field, rx, ry);
    return sum;
  };
  std::vector<double> values, mask;
  std::vector<std::vector<double>> mu(static_cast<std::size_t>(basis));  // autocorrelations of phi_k
  double weighted_within[3] = {0, 0, 0}, product_within[3][3] = {};
  struct Job {
    int kind, b, k;  // 0: the scores, 1: the mask, 2: phi_b, 3: phi_b scores, 4: phi_b phi_k (b <= k)
  };
  std::vector<Job> jobs = {{0, 0, 0}, {1, 0, 0}};
  for (int b = 1; b < basis; ++b) {
    jobs.push_back({2, b, 0});
    jobs.push_back({3, b, 0});
  }
  for (int b = 0; b < basis; ++b)
    for (int k = b; k < basis; ++k)
      if (b + k > 0) jobs.push_back({4, b, k});
  asperity::detail::parallel_for(jobs.size(), threads, [&](std::size_t j) {
    const Job job = jobs[j];
    switch (job.kind) {
      case 0: values = autocorrelation([&](std::size_t i, std::size_t jj) { return scores_[jj * nx_ + i]; }); break;
      case 1: mask = autocorrelation([](std::size_t, std::size_t) { return 1.0; }); break;
      case 2: mu[static_cast<std::size_t>(job.b)] = autocorrelation([&](std::size_t i, std::size_t jj) { return phi(job.b, i, jj); }); break;
      case 3:
        weighted_within[job.b] =
            within_sum(autocorrelation([&](std::size_t i, std::size_t jj) { return phi(job.b, i, jj) * scores_[jj * nx_ + i]; }));
        break;
      default:
        product_within[job.b][job.k] = product_within[job.k][job.b] = within_sum(
            autocorrelation([&](std::size_t i, std::size_t jj) { return phi(job.b, i, jj) * phi(job.k, i, jj); }));
    }
  });
  mu[0] = mask;
  weighted_within[0] = within_sum(values);
  product_within[0][0] = within_sum(mask);
  double lost[3] = {0, 0, 0};
  {
    double A[3][3] = {}, B[3] = {};
    for (int b = 0; b < basis; ++b) {
      B[b] = weighted_within[b];
      for (int k = 0; k < basis; ++k) {
        // beyond = all pairs - the pairs within; all pairs: (sum_x phi_b phi_k)^2
        double total = 0;
        for (std::size_t j = 0; j < ny_; ++j)
          for (std::size_t i = 0; i < nx_; ++i)
            if (valid_[j * nx_ + i]) total += phi(b, i, j) * phi(k, i, j);
        A[b][k] = total * total - product_within[b][k];
      }
    }
    // Gaussian elimination with partial pivoting (at most 3 x 3); a singular system (a map with
    // no pair beyond the largest lag) leaves nothing added
    int order[3] = {0, 1, 2};
    bool solved = true;
    for (int c = 0; c < basis && solved; ++c) {
      int pivot = c;
      for (int r = c + 1; r < basis; ++r)
        if (std::fabs(A[r][c]) > std::fabs(A[pivot][c])) pivot = r;
      if (!(std::fabs(A[pivot][c]) > 0)) solved = false;
      if (!solved) break;
      std::swap(A[c], A[pivot]);
      std::swap(B[c], B[pivot]);
      std::swap(order[c], order[pivot]);
      for (int r = c + 1; r < basis; ++r) {
        const double f = A[r][c] / A[c][c];
        for (int k = c; k < basis; ++k) A[r][k] -= f * A[c][k];
        B[r] -= f * B[c];
      }
    }
    if (solved)
      for (int c = basis - 1; c >= 0; --c) {
        double v = B[c];
        for (int k = c + 1; k < basis; ++k) v -= A[c][k] * lost[k];
        lost[c] = v / A[c][c];
      }
    for (double& v : lost) v = std::isfinite(v) ? std::max(0.0, v) : 0.0;
  }
  // the windowed autocovariance on the surrogates' grid
  const std::size_t half = px_ / 2 + 1;
  std::vector<double> covariance(px_ * py_, 0.0);
  for (long ry = -static_cast<long>(lag_y); ry <= static_cast<long>(lag_y); ++ry)
    for (long rx = -static_cast<long>(lag_x); rx <= static_cast<long>(lag_x); ++rx) {
      const double u = std::hypot(static_cast<double>(rx) / static_cast<double>(lag_x),
                                  static_cast<double>(ry) / static_cast<double>(lag_y));
      if (u >= 1) continue;
      // a flat-topped window (Tukey's: 1 to half the largest lag, a cosine to 0 beyond), so that
      // the correlation a surrogate carries is the map's at every lag that matters
      const double window = surrogate_lag_window(u);
      const std::size_t sx = static_cast<std::size_t>((rx + static_cast<long>(ax)) % static_cast<long>(ax));
      const std::size_t sy = static_cast<std::size_t>((ry + static_cast<long>(ay)) % static_cast<long>(ay));
      const double pairs = std::round(mask[sy * ax + sx]);
      if (pairs < 1) continue;
      const std::size_t tx = static_cast<std::size_t>((rx + static_cast<long>(px_)) % static_cast<long>(px_));
      const std::size_t ty = static_cast<std::size_t>((ry + static_cast<long>(py_)) % static_cast<long>(py_));
      double restored = values[sy * ax + sx] / pairs;
      for (int k = 0; k < basis; ++k) restored += lost[k] * mu[static_cast<std::size_t>(k)][sy * ax + sx] / pairs;
      covariance[ty * px_ + tx] = window * restored;
    }
  std::vector<detail::Complex> transformed(py_ * half);
  detail::forward_2d(covariance.data(), transformed.data(), py_, px_);
  // the spectrum is real (the autocovariance is even); a negative value is estimation noise
  amplitude_.assign(py_ * half, 0.0);
  for (std::size_t k = 0; k < amplitude_.size(); ++k) amplitude_[k] = std::sqrt(std::max(0.0, transformed[k].real()));
  // The scale that gives the field unit variance in expectation over the padded grid (the map's
  // normal scores have unit variance). Not each surrogate's own: a realization's mean and variance
  // over the map fluctuate as the measured map's do, and a Weibull marginal turns that
  // fluctuation into one of the shape (standardizing each surrogate made its intervals too narrow).
  // A coefficient is a complex normal of variance amplitude^2; it and its conjugate make the
  // field's sum, but in the columns kx = 0 and Nyquist (self-conjugate after the transform along
  // y), where only the real part counts.
  double total = 0;
  for (std::size_t j = 0; j < py_; ++j)
    for (std::size_t i = 0; i < half; ++i) {
      const bool self_conjugate = i == 0 || (px_ % 2 == 0 && i == half - 1);
      total += (self_conjugate ? 1.0 : 2.0) * amplitude_[j * half + i] * amplitude_[j * half + i];
    }
  const double points = static_cast<double>(px_) * static_cast<double>(py_);
  const double scale = total > 0 ? points / std::sqrt(total) : 0;
  for (double& a : amplitude_) a *= scale;
}

void SurrogateFields::generate(std::uint64_t seed, std::size_t index, std::vector<double>& field) const {
  Xoshiro256 engine(splitmix64(splitmix64(seed) ^ splitmix64(0x5D0BA7Eull + index)));
  const std::size_t half = px_ / 2 + 1;
  // buffers kept by each thread: a surrogate allocates nothing after the first
  thread_local std::vector<detail::Complex> coefficients;
  thread_local std::vector<double> padded;
  coefficients.resize(py_ * half);
  padded.resize(px_ * py_);
  // complex normals (Marsaglia's polar method: no trigonometry) times the spectrum's amplitude,
  // a block at a time so that the logarithms go a vector at a time (vector_math.hpp)
  constexpr std::size_t block = 512;
  double u[block], v[block], s[block], log_s[block];
  for (std::size_t first = 0; first < coefficients.size(); first += block) {
    const std::size_t count = std::min(block, coefficients.size() - first);
    for (std::size_t k = 0; k < count; ++k) {
      do {
        u[k] = engine.symmetric();
        v[k] = engine.symmetric();
        s[k] = u[k] * u[k] + v[k] * v[k];
      } while (s[k] >= 1 || s[k] == 0);  // s >= 2^-105 otherwise: normal, in ln's range
    }
    detail::vector_log(s, log_s, count);
    for (std::size_t k = 0; k < count; ++k) {
      const double factor = amplitude_[first + k] * std::sqrt(-log_s[k] / s[k]);
      coefficients[first + k] = detail::Complex(factor * u[k], factor * v[k]);
    }
  }
  detail::make_hermitian_columns(coefficients.data(), py_, px_);
  detail::inverse_2d(coefficients.data(), padded.data(), py_, px_);
  field.assign(nx_ * ny_, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i)
      if (valid_[j * nx_ + i]) field[j * nx_ + i] = padded[j * px_ + i];
}

}  // namespace asperity::topography
