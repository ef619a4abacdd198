#include "asperity/integrals.hpp"

#include <cmath>
#include <limits>

namespace asperity {

const char* to_string(Distribution distribution) {
  return distribution == Distribution::weibull ? "weibull" : "gaussian";
}
const char* to_string(Side side) { return side == Side::tail ? "tail" : "bounded"; }

bool parse_distribution(std::string_view name, Distribution& out) {
  if (name == "weibull") { out = Distribution::weibull; return true; }
  if (name == "gaussian") { out = Distribution::gaussian; return true; }
  return false;
}
bool parse_side(std::string_view name, Side& out) {
  if (name == "tail") { out = Side::tail; return true; }
  if (name == "bounded") { out = Side::bounded; return true; }
  return false;
}

double weibull_log_density(double shape, double height) {
  if (height < 0) return -std::numeric_limits<double>::infinity();
  if (height == 0) {
    if (shape < 1) return std::numeric_limits<double>::infinity();
    return shape == 1 ? 0.0 : -std::numeric_limits<double>::infinity();
  }
  return std::log(shape) + (shape - 1) * std::log(height) - std::pow(height, shape);
}

double gaussian_log_density(double height) {
  return -0.5 * height * height - 0.91893853320467274178;  // ln sqrt(2 pi)
}

double weibull_moment(double shape, double power) { return std::tgamma(1 + power / shape); }
double weibull_mean(double shape) { return weibull_moment(shape, 1); }
double weibull_rms(double shape) {
  const double mean = weibull_mean(shape);
  return std::sqrt(weibull_moment(shape, 2) - mean * mean);
}

}  // namespace asperity
