// The integrals' vocabulary (docs/model.md sections 1-2): which density, which side of
// approach, which order. Orders are carried as twice_order (0..5) so they stay integers.
#pragma once
#include <string_view>

namespace asperity {

enum class Distribution { weibull = 0, gaussian = 1 };
enum class Side { tail = 0, bounded = 1 };

// The Weibull shapes a the generator integrates and the library serves (docs/model.md): one range
// for every check of a shape (surfaces, scenes, fits, the command lines, Python).
inline constexpr double weibull_shape_min = 0.3;
inline constexpr double weibull_shape_max = 50.0;

// Orders n = 0, 1/2, 1, 3/2, 2, 5/2 (count, stiffness, area, load, F_2, F_5/2).
inline constexpr int order_count = 6;
constexpr double order_of(int twice_order) { return 0.5 * twice_order; }

// The orders by what they give (docs/model.md section 3), as twice_order: X_0 counts the summits in
// contact, X_1/2 the stiffness, X_1 the real area, X_3/2 the load; X_2 and X_5/2 are the
// Greenwood-Tripp F_2 and F_5/2 of mixed lubrication.
namespace orders {
inline constexpr int count = 0;
inline constexpr int stiffness = 1;
inline constexpr int area = 2;
inline constexpr int load = 3;
inline constexpr int f2 = 4;
inline constexpr int f5_2 = 5;
}  // namespace orders

// The bit of an order in an order mask (Curve, Table::curve).
constexpr unsigned order_bit(int twice_order) { return 1u << twice_order; }
// What the physical quantities need: count, stiffness, area, load.
inline constexpr unsigned contact_order_mask =
    order_bit(orders::count) | order_bit(orders::stiffness) | order_bit(orders::area) | order_bit(orders::load);

const char* to_string(Distribution distribution);
const char* to_string(Side side);
// False (and the output untouched) for a name that is not one of ours.
bool parse_distribution(std::string_view name, Distribution& out);
bool parse_side(std::string_view name, Side& out);

// Weibull density of unit scale, phi_a(z) = a z^(a-1) exp(-z^a), and its log.
double weibull_log_density(double shape, double height);
// Gaussian density exp(-z^2/2)/sqrt(2 pi) and its log.
double gaussian_log_density(double height);
// Raw moments of the unit Weibull density, E z^p = Gamma(1 + p/a).
double weibull_moment(double shape, double power);
// Mean and rms about the mean of the unit Weibull density (docs/model.md section 1).
double weibull_mean(double shape);
double weibull_rms(double shape);

}  // namespace asperity
