// The physical layer: surfaces and their validation, E* and the Nayak-McCool Gaussian surface,
// forward contact against the dimensionless integrals, and the inverses (separation at a load,
// a pressure, a real area) round-tripped across the whole range; Persson's law.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "asperity/contact.hpp"
#include "asperity/contact_model.hpp"
#include "asperity/error.hpp"
#include "asperity/inverse.hpp"
#include "asperity/number_text.hpp"
#include "asperity/persson.hpp"
#include "asperity/surface.hpp"

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

std::string error_of(const RoughSurface& surface) {
  try {
    surface.validate();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

// A complete surface (the values the struct once defaulted to)
RoughSurface example_surface() {
  RoughSurface surface;
  surface.shape = 2;
  surface.height_scale = 1e-6;
  surface.summit_radius = 1e-4;
  surface.summit_density = 1e10;
  surface.nominal_area = 1e-4;
  surface.contact_modulus = 1e11;
  return surface;
}

TEST(RoughSurface, ValidationNamesTheParameter) {
  RoughSurface surface = example_surface();
  EXPECT_EQ(error_of(surface), "");
  surface.height_scale = -1e-6;
  EXPECT_NE(error_of(surface).find("height scale"), std::string::npos);
  surface = example_surface();
  surface.summit_radius = 0;
  EXPECT_NE(error_of(surface).find("summit radius"), std::string::npos);
  surface = example_surface();
  surface.summit_density = INFINITY;
  EXPECT_NE(error_of(surface).find("summit density"), std::string::npos);
  surface = example_surface();
  surface.nominal_area = -2;
  EXPECT_NE(error_of(surface).find("nominal area"), std::string::npos);
  surface = example_surface();
  surface.contact_modulus = INFINITY;
  EXPECT_NE(error_of(surface).find("contact modulus"), std::string::npos);
  surface = example_surface();
  surface.shape = 0.2;
  EXPECT_NE(error_of(surface).find("shape"), std::string::npos);
  surface = example_surface();
  surface.distribution = Distribution::gaussian;
  surface.side = Side::bounded;
  EXPECT_NE(error_of(surface).find("no bounded side"), std::string::npos);
}

// No physical value has a default (issue 39): each left out is named, never silently the example's
TEST(RoughSurface, PhysicalValuesHaveNoDefault) {
  EXPECT_EQ(error_of(RoughSurface{}), "surface: shape is not given (a RoughSurface's physical values have no default)");
  double RoughSurface::*const values[] = {&RoughSurface::height_scale, &RoughSurface::summit_radius,
                                          &RoughSurface::summit_density, &RoughSurface::nominal_area,
                                          &RoughSurface::contact_modulus};
  const char* names[] = {"height scale", "summit radius", "summit density", "nominal area", "contact modulus"};
  for (int i = 0; i < 5; ++i) {
    RoughSurface surface = example_surface();
    surface.*values[i] = RoughSurface{}.*values[i];
    const std::string error = error_of(surface);
    EXPECT_NE(error.find(names[i]), std::string::npos) << error;
    EXPECT_NE(error.find("is not given"), std::string::npos) << error;
  }
  RoughSurface gaussian = example_surface();  // the Gaussian needs no shape
  gaussian.distribution = Distribution::gaussian;
  gaussian.shape = RoughSurface{}.shape;
  EXPECT_EQ(error_of(gaussian), "");
}

TEST(RoughSurface, ContactModulusAndMoments) {
  // steel on steel: E / (2 (1 - nu^2))
  EXPECT_NEAR(contact_modulus_from(210e9, 0.3, 210e9, 0.3), 210e9 / (2 * 0.91), 1e-3);
  EXPECT_NEAR(contact_modulus_from(1e9, 0.5, 1e15, 0.0), 1e9 / 0.75, 1e-3 * 1e9);  // rubber on a rigid flat
  EXPECT_THROW(contact_modulus_from(-1, 0.3, 1, 0.3), Error);
  EXPECT_THROW(contact_modulus_from(1, 0.6, 1, 0.3), Error);

  const double m0 = 1e-12, m2 = 1e-4, m4 = 1e4, pi = 3.14159265358979323846;
  const double alpha = bandwidth_alpha(m0, m2, m4);
  EXPECT_DOUBLE_EQ(alpha, 1.0);
  const RoughSurface surface = gaussian_surface_from_moments(m0, m2, m4, 1e-4, 1e11);
  EXPECT_NEAR(surface.summit_density, m4 / (6 * pi * std::sqrt(3.0) * m2), 1e-9 * surface.summit_density);
  EXPECT_NEAR(1 / surface.summit_radius, (8.0 / 3.0) * std::sqrt(m4 / pi), 1e-9 / surface.summit_radius);
  EXPECT_NEAR(surface.height_scale, std::sqrt(m0 * (1 - 0.8968 / alpha)), 1e-15);
  // McCool's product, which needs the square root form of sigma (the paper prints it without):
  // R sigma D = sqrt(alpha - 0.8968) / (16 sqrt(3 pi)) = (1/48) sqrt((3/pi)(alpha - 0.8968))
  const double product = surface.summit_radius * surface.height_scale * surface.summit_density;
  EXPECT_NEAR(product, std::sqrt((3 / pi) * (alpha - 0.8968)) / 48, 1e-12 * product);
  EXPECT_THROW(gaussian_surface_from_moments(1, 1, 0.9, 1, 1), Error);  // alpha = 0.9
  EXPECT_THROW(gaussian_surface_from_moments(0, 1, 1, 1, 1), Error);
}

RoughSurface weibull_surface(Side side, double shape) {
  RoughSurface surface;
  surface.side = side;
  surface.shape = shape;
  surface.height_scale = 2e-6;
  surface.summit_radius = 5e-5;
  surface.summit_density = 4e9;
  surface.nominal_area = 3e-4;
  surface.contact_modulus = contact_modulus_from(210e9, 0.3, 70e9, 0.33);
  return surface;
}

TEST(ContactModel, ForwardIsTheScaledIntegrals) {
  const RoughSurface surface = weibull_surface(Side::tail, 2.0);
  const ContactModel model(table(), surface);
  const Curve curve = table().curve(Distribution::weibull, Side::tail, 2.0);
  for (double s : {-1.0, 0.0, 0.3, 1.2, 2.5}) {
    const PhysicalState state = model.at_separation(s * surface.height_scale);
    ContactState reference;
    contact_at(curve, SurfaceScales{surface.summit_count(), surface.summit_radius, surface.height_scale, surface.contact_modulus},
               s, reference);
    EXPECT_NEAR(state.count, reference.count, 1e-13 * reference.count);
    EXPECT_NEAR(state.real_area, reference.area, 1e-13 * reference.area);
    EXPECT_NEAR(state.load, reference.load, 1e-13 * reference.load);
    EXPECT_NEAR(state.stiffness, reference.stiffness, 1e-13 * reference.stiffness);
    EXPECT_NEAR(state.stiffness_over_load, reference.stiffness_ratio / surface.height_scale,
                1e-12 * state.stiffness_over_load);
    EXPECT_NEAR(state.pressure, state.load / surface.nominal_area, 1e-15 * state.pressure);
    EXPECT_NEAR(state.mean_separation, (s - weibull_mean(2.0)) * surface.height_scale, 1e-20);
  }
  EXPECT_TRUE(std::isnan(model.at_separation(NAN).load));
}

TEST(ContactModel, InversesRoundTripAcrossTheRange) {
  struct Case {
    RoughSurface surface;
    const char* label;
  };
  RoughSurface gaussian = gaussian_surface_from_moments(1e-12, 1e-4, 3e4, 1e-4, 1e11);
  const Case cases[] = {{weibull_surface(Side::tail, 2.0), "tail a=2"},
                        {weibull_surface(Side::tail, 0.5), "tail a=0.5"},
                        {weibull_surface(Side::bounded, 1.73), "bounded a=1.73"},
                        {weibull_surface(Side::tail, 17.0), "tail a=17"},
                        {gaussian, "gaussian"}};
  for (const Case& c : cases) {
    const ContactModel model(table(), c.surface);
    double previous_separation = INFINITY, worst = 0, worst_area = 0;
    for (double exponent = -40; exponent <= 6; exponent += 0.37) {
      const double load = std::pow(10.0, exponent);
      const PhysicalState state = model.at_load(load);
      worst = std::max(worst, std::fabs(state.load - load) / load);
      EXPECT_LT(state.separation, previous_separation) << c.label << " load " << load;  // monotone
      previous_separation = state.separation;
      if (state.real_area > 0) {
        const PhysicalState by_area = model.at_real_area(state.real_area);
        worst_area = std::max(worst_area, std::fabs(by_area.real_area - state.real_area) / state.real_area);
        EXPECT_NEAR(by_area.separation, state.separation, 1e-9 * (std::fabs(state.separation) + c.surface.height_scale));
      }
      const PhysicalState by_pressure = model.at_pressure(load / c.surface.nominal_area);
      EXPECT_NEAR(by_pressure.separation, state.separation, 1e-12 * (std::fabs(state.separation) + 1e-12));
    }
    RecordProperty(std::string(c.label) + "_load_round_trip", format_double(worst));
    EXPECT_LT(worst, 1e-11) << c.label;  // the table's own error level
    EXPECT_LT(worst_area, 1e-11) << c.label;
    EXPECT_TRUE(std::isnan(model.at_load(NAN).separation));
    const PhysicalState none = model.at_load(0);
    if (c.surface.side == Side::bounded) EXPECT_EQ(none.separation, 0.0);
    else EXPECT_EQ(none.separation, INFINITY);
  }
}

// The inverse where it is weakest. On the Weibull tail side the density starts at s = 0 as
// z^(a-1): ln X_n is not smooth there, and one Newton step from the table left errors up to 5.6e-5
// in s (a = 0.5, the area) before those intervals iterated. On the bounded side near first
// contact X_n ~ |s|^(n+a) falls past 1e-300 within |s| ~ 1e-150: the inverse there solves in ln|s|
// (a linear step from 1e-167 toward 1e-250 used to land past first contact, at s ~ +1e-165).
// Round trips: ln X_n within 1e-13 (1 + |ln X_n|), what the inverse promises (inverse.hpp), and s
// to what ln X_n resolves (the forward curve is flat within ~2e-12 of s = 0).
TEST(InverseCurve, RoundTripsWhereTheDensityStartsAndNearFirstContact) {
  for (double shape : {0.5, 0.7, 1.0, 1.5, 2.0, 3.0}) {
    const Curve tail = table().curve(Distribution::weibull, Side::tail, shape);
    const Curve bounded = table().curve(Distribution::weibull, Side::bounded, shape);
    for (int twice_order : {2, 3}) {
      const InverseCurve tail_inverse(tail, twice_order), bounded_inverse(bounded, twice_order);
      double worst_log = 0, worst_s = 0;
      std::vector<double> separations;
      for (int i = -2000; i <= 2000; ++i) separations.push_back(i * 1.5e-4);  // dense across s = 0
      for (double e = -13; e <= 0.5; e += 0.0625) separations.push_back(std::pow(10.0, e)), separations.push_back(-std::pow(10.0, e));
      for (double s : separations) {
        const double y = tail.log_value(twice_order, s), back = tail_inverse.separation_at_log(y);
        worst_log = std::max(worst_log, std::fabs(tail.log_value(twice_order, back) - y) / (1 + std::fabs(y)));
        worst_s = std::max(worst_s, std::fabs(back - s) / (1 + std::fabs(s)));
      }
      EXPECT_LT(worst_log, 1e-13) << "tail a=" << shape << " twice order " << twice_order;
      EXPECT_LT(worst_s, 4e-12) << "tail a=" << shape << " twice order " << twice_order;

      double worst_bounded_log = 0, worst_relative = 0;
      for (double e = -299; e <= 0.5; e += 0.37) {  // from first contact's neighbourhood to s = -3
        const double s = -std::pow(10.0, e);
        const double y = bounded.log_value(twice_order, s), back = bounded_inverse.separation_at_log(y);
        ASSERT_LT(back, 0) << "bounded a=" << shape << " s=" << s << ": past first contact";
        worst_bounded_log =
            std::max(worst_bounded_log, std::fabs(bounded.log_value(twice_order, back) - y) / (1 + std::fabs(y)));
        worst_relative = std::max(worst_relative, std::fabs(back / s - 1));
      }
      EXPECT_LT(worst_bounded_log, 1e-13) << "bounded a=" << shape << " twice order " << twice_order;
      // ln X_n ~ (n + a) ln|s| + c: s relative to what ln X_n ~ -1000 resolves there
      EXPECT_LT(worst_relative, 1e-11) << "bounded a=" << shape << " twice order " << twice_order;
    }
  }
}

TEST(ContactModel, CopiesAndMovesKeepTheirCurvesAndInverses) {
  ContactModel copy;
  double expected;
  {
    // the model shares its curve and inverses: copies outlive the original and the table
    const Table local = Table::open(ASPERITY_TEST_TABLE);
    ContactModel first(local, weibull_surface(Side::tail, 3.0));
    expected = first.at_load(0.5).separation;
    copy = first;
    ContactModel moved(std::move(first));
    EXPECT_DOUBLE_EQ(moved.at_load(0.5).separation, expected);
  }
  EXPECT_DOUBLE_EQ(copy.at_load(0.5).separation, expected);
  EXPECT_TRUE(std::isnan(ContactModel().at_load(1).load));  // no surface: NaN
  EXPECT_THROW(ContactModel(table(), weibull_surface(Side::tail, 25.0)), Error);  // beyond the default table
}

TEST(ContactModel, NoContactAndInfiniteContactAreStates) {
  for (Side side : {Side::tail, Side::bounded}) {
    const ContactModel model(table(), weibull_surface(side, 2.0));
    const double past = side == Side::tail ? INFINITY : 1e-6;  // past the last summit
    for (const PhysicalState& none : {model.at_load(0), model.at_load(-3), model.at_pressure(0), model.at_real_area(0),
                                      model.at_separation(past)}) {
      EXPECT_EQ(none.count, 0.0);
      EXPECT_EQ(none.real_area, 0.0);
      EXPECT_EQ(none.area_fraction, 0.0);
      EXPECT_EQ(none.load, 0.0);
      EXPECT_EQ(none.pressure, 0.0);
      EXPECT_EQ(none.stiffness, 0.0);
      EXPECT_TRUE(std::isnan(none.stiffness_over_load));  // 0/0
      EXPECT_EQ(none.separation, side == Side::tail ? INFINITY : 0.0);
    }
    for (const PhysicalState& all : {model.at_load(INFINITY), model.at_real_area(INFINITY), model.at_separation(-INFINITY)}) {
      EXPECT_DOUBLE_EQ(all.count, model.surface().summit_count());
      EXPECT_EQ(all.load, INFINITY);
      EXPECT_EQ(all.real_area, INFINITY);
      EXPECT_EQ(all.separation, -INFINITY);
    }
    EXPECT_TRUE(std::isnan(model.at_separation(NAN).load));
  }
}

// ContactModel::at_separations against at_separation, element by element: the batch lookup's
// rounding where the answer is a normal positive number, and the same bits where it is not.
double field(const PhysicalState& state, ContactQuantity quantity) {
  switch (quantity) {
    case ContactQuantity::count: return state.count;
    case ContactQuantity::real_area: return state.real_area;
    case ContactQuantity::area_fraction: return state.area_fraction;
    case ContactQuantity::load: return state.load;
    case ContactQuantity::pressure: return state.pressure;
    case ContactQuantity::stiffness: return state.stiffness;
  }
  return NAN;
}
int order_of_quantity(ContactQuantity quantity) {
  switch (quantity) {
    case ContactQuantity::count: return orders::count;
    case ContactQuantity::real_area:
    case ContactQuantity::area_fraction: return orders::area;
    case ContactQuantity::stiffness: return orders::stiffness;
    default: return orders::load;
  }
}
bool same_bits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ContactModel, BatchIsTheScalarAnswerForEveryElement) {
  RoughSurface gaussian = gaussian_surface_from_moments(1e-12, 1e-4, 3e4, 1e-4, 1e11);
  struct Case {
    RoughSurface surface;
    SeparationDatum datum;
    double height;
  };
  const Case cases[] = {{weibull_surface(Side::tail, 2.0), SeparationDatum::origin, NAN},
                        {weibull_surface(Side::tail, 0.5), SeparationDatum::mean_summit, NAN},
                        {weibull_surface(Side::tail, 20.0), SeparationDatum::origin, NAN},
                        {weibull_surface(Side::bounded, 1.3), SeparationDatum::mean_plane, 1e-6},
                        {weibull_surface(Side::bounded, 0.5), SeparationDatum::origin, NAN},
                        {gaussian, SeparationDatum::origin, NAN}};
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  double worst = 0;
  long exact = 0, rounded = 0;
  for (const Case& c : cases) {
    const ContactModel model(table(), c.surface, c.datum, c.height);
    const double sigma = c.surface.height_scale;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::vector<double> d;
    for (int i = 0; i < 1203; ++i) {  // not a multiple of the block
      switch (i % 3) {
        case 0: d.push_back(6 * unit(rng) * sigma); break;               // across contact
        case 1: d.push_back(std::sinh(7 * unit(rng)) * sigma); break;    // all touching to beyond the table
        default: d.push_back(0.05 * unit(rng) * sigma); break;           // near the origin
      }
    }
    // NaN, the infinities, zeros, far beyond the table (X underflows to 0 or is subnormal), huge
    for (double special : {nan, inf, -inf, 0.0, -0.0, 30 * sigma, 60 * sigma, 1e4 * sigma, 1e300, -1e300,
                           model.datum_position() == 0 ? 1e-300 : -model.datum_position()})
      d.insert(d.begin() + static_cast<long>(d.size() / 2), special);
    for (int k = 0; k < contact_quantity_count; ++k) {
      const ContactQuantity quantity = static_cast<ContactQuantity>(k);
      std::vector<double> out(d.size()), in_place = d;
      model.at_separations(quantity, d.data(), out.data(), d.size());
      model.at_separations(quantity, in_place.data(), in_place.data(), in_place.size());  // out = separations
      for (std::size_t i = 0; i < d.size(); ++i) {
        const double scalar = field(model.at_separation(d[i]), quantity);
        EXPECT_TRUE(same_bits(in_place[i], out[i])) << i;
        const double x = model.curve().value(order_of_quantity(quantity), model.dimensionless(d[i]));
        if (!(std::isnormal(scalar) && scalar > 0 && std::isnormal(x))) {  // (count at -inf: N, X_0 not looked up)
          EXPECT_TRUE(same_bits(out[i], scalar))
              << contact_quantity_name(quantity) << " at " << d[i] << ": " << out[i] << " against " << scalar;
          ++exact;
          continue;
        }
        // the bound of the batch lookup against the scalar one (test_batch): ulp of ln X
        const double error = std::fabs(out[i] - scalar) / scalar;
        const double bound = 2e-14 * (1 + std::fabs(std::log(x)));
        EXPECT_LE(error, bound) << contact_quantity_name(quantity) << " at " << d[i];
        worst = std::max(worst, error / (1 + std::fabs(std::log(x))));
        ++rounded;
      }
    }
    std::vector<double> none;
    model.at_separations(ContactQuantity::load, none.data(), none.data(), 0);  // empty: nothing touched
  }
  RecordProperty("batch_vs_scalar_worst_relative_per_1_plus_abs_ln_x", format_double(worst));
  RecordProperty("elements_same_bits", std::to_string(exact));
  RecordProperty("elements_to_rounding", std::to_string(rounded));
  EXPECT_GT(exact, 100);
  // a model without a surface answers NaN, as its scalar queries do
  double x = 1e-6, y = 0;
  ContactModel().at_separations(ContactQuantity::load, &x, &y, 1);
  EXPECT_TRUE(std::isnan(y));
}

TEST(ContactModel, QuantityNamesRoundTrip) {
  for (int k = 0; k < contact_quantity_count; ++k) {
    ContactQuantity parsed;
    ASSERT_TRUE(parse_contact_quantity(contact_quantity_name(static_cast<ContactQuantity>(k)), parsed));
    EXPECT_EQ(static_cast<int>(parsed), k);
  }
  ContactQuantity parsed;
  EXPECT_FALSE(parse_contact_quantity("area", parsed));  // real-area or area-fraction
}

TEST(RoughSurface, RmsAndScaleAndTheFactorsOfTheModel) {
  // GW users measure the rms summit height: for a = 1.6 it is 0.574 of the Weibull scale
  EXPECT_NEAR(1e-6 / height_scale_from_rms(Distribution::weibull, 1.6, 1e-6), weibull_rms(1.6), 1e-15);
  EXPECT_NEAR(weibull_rms(1.6), 0.574, 5e-4);
  EXPECT_EQ(height_scale_from_rms(Distribution::gaussian, 0, 2e-6), 2e-6);
  EXPECT_THROW(height_scale_from_rms(Distribution::weibull, 1.6, -1), Error);
  // parameters whose products underflow or overflow are refused, naming the factor
  RoughSurface tiny = example_surface();
  tiny.height_scale = 1e-300;
  EXPECT_NE(error_of(tiny).find("factor"), std::string::npos) << error_of(tiny);
  RoughSurface stiff = example_surface();
  stiff.contact_modulus = 1e308;
  EXPECT_NE(error_of(stiff).find("factor"), std::string::npos) << error_of(stiff);
}

TEST(ContactModel, AgreesWithContactAtThroughOneComputation) {
  const RoughSurface surface = weibull_surface(Side::bounded, 1.73);
  const ContactModel model(table(), surface);
  const Curve curve = table().curve(Distribution::weibull, Side::bounded, 1.73);
  const SurfaceScales plain{surface.summit_count(), surface.summit_radius, surface.height_scale, surface.contact_modulus};
  // on the grid, and off it (|s| < 2^-70, past the table's end): both paths of each
  for (double s : {-1e-30, -1e-12, -1e-5, -0.01, -0.3, -1.0, -4.0, -1e3}) {
    ContactState state;
    ASSERT_TRUE(contact_at(curve, plain, s, state));
    const PhysicalState physical = model.at_separation(s * surface.height_scale);
    EXPECT_EQ(physical.load, state.load);
    EXPECT_EQ(physical.stiffness, state.stiffness);
    EXPECT_EQ(physical.real_area, state.area);
    EXPECT_EQ(physical.count, state.count);
    EXPECT_EQ(physical.stiffness_over_load, state.stiffness_ratio / surface.height_scale);
  }
}

TEST(Persson, ExponentialLaw) {
  const PerssonLaw law{0.5, 2.0};
  EXPECT_DOUBLE_EQ(law.pressure(0), 2.0);
  EXPECT_NEAR(law.pressure(1), 2.0 * std::exp(-2.0), 1e-15);
  EXPECT_NEAR(law.separation_at(law.pressure(1.7)), 1.7, 1e-14);
  EXPECT_DOUBLE_EQ(law.stiffness_over_load(), 2.0);
}

}  // namespace
