// The separation datum (asperity/separation_datum.hpp) in ContactModel: where each datum lies
// against closed forms (the mean of the Weibull summit heights is Gamma(1 + 1/a) sigma_s above
// the origin on the tail side and below it on the bounded side; the Gaussian's mean is its
// origin; the mean plane is the mean summit height less the height the user gives), forward and
// inverse queries in each datum against the origin model, round trips, the default (origin,
// unchanged bits), the names, and the errors for a mean plane the inputs do not fix.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "asperity/contact_model.hpp"
#include "asperity/error.hpp"
#include "asperity/number_text.hpp"
#include "asperity/pressure_overclosure.hpp"
#include "asperity/separation_datum.hpp"

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

RoughSurface surface_of(Distribution distribution, Side side, double shape) {
  RoughSurface surface;
  surface.distribution = distribution;
  surface.side = side;
  surface.shape = shape;
  surface.height_scale = 2e-6;
  surface.summit_radius = 5e-5;
  surface.summit_density = 4e9;
  surface.nominal_area = 3e-4;
  surface.contact_modulus = 1.1e11;
  return surface;
}

// the mean summit height from the origin, in m: std::tgamma, independent of the library's weibull_mean
double mean_summit_closed_form(const RoughSurface& s) {
  if (s.distribution == Distribution::gaussian) return 0;
  return (s.side == Side::bounded ? -1 : 1) * std::tgamma(1 + 1 / s.shape) * s.height_scale;
}

std::string error_of(const RoughSurface& surface, SeparationDatum datum, double height) {
  try {
    ContactModel(table(), surface, datum, height);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(SeparationDatum, NamesRoundTripAndTheDefaultIsTheOrigin) {
  for (SeparationDatum datum : {SeparationDatum::origin, SeparationDatum::mean_summit, SeparationDatum::mean_plane}) {
    SeparationDatum parsed = SeparationDatum::origin;
    ASSERT_TRUE(parse_separation_datum(separation_datum_name(datum), parsed));
    EXPECT_EQ(parsed, datum);
  }
  EXPECT_STREQ(separation_datum_name(SeparationDatum::mean_summit), "mean-summit");
  EXPECT_STREQ(separation_datum_name(SeparationDatum::mean_plane), "mean-plane");
  SeparationDatum parsed;
  EXPECT_FALSE(parse_separation_datum("mean", parsed));
  EXPECT_FALSE(parse_separation_datum("zero-pressure", parsed));  // the card's own datum
  EXPECT_EQ(default_separation_datum, SeparationDatum::origin);
  const ContactModel model(table(), surface_of(Distribution::weibull, Side::tail, 2.0));
  EXPECT_EQ(model.datum(), SeparationDatum::origin);
  EXPECT_NE(describe_separation_datum(SeparationDatum::origin, NAN).find("the default"), std::string::npos);
  EXPECT_EQ(describe_separation_datum(SeparationDatum::mean_summit, NAN).find("the default"), std::string::npos);
}

TEST(SeparationDatum, PositionsAgainstClosedForms) {
  const RoughSurface surfaces[] = {
      surface_of(Distribution::weibull, Side::tail, 2.0), surface_of(Distribution::weibull, Side::tail, 0.5),
      surface_of(Distribution::weibull, Side::tail, 17.0), surface_of(Distribution::weibull, Side::bounded, 1.3),
      surface_of(Distribution::gaussian, Side::tail, 2.0)};
  for (const RoughSurface& s : surfaces) {
    const double mean = mean_summit_closed_form(s);
    EXPECT_EQ(separation_datum_position(s, SeparationDatum::origin, NAN), 0.0);
    EXPECT_NEAR(separation_datum_position(s, SeparationDatum::mean_summit, NAN), mean, 1e-15 * s.height_scale);
    EXPECT_NEAR(separation_datum_position(s, SeparationDatum::mean_plane, 3e-6), mean - 3e-6, 1e-15 * s.height_scale);
    const ContactModel model(table(), s, SeparationDatum::mean_plane, 3e-6);
    EXPECT_NEAR(model.datum_position(), mean - 3e-6, 1e-15 * s.height_scale);
    EXPECT_EQ(model.mean_summit_height(), 3e-6);
  }
  // a = 2: Gamma(3/2) = sqrt(pi)/2
  EXPECT_NEAR(separation_datum_position(surfaces[0], SeparationDatum::mean_summit, NAN),
              std::sqrt(3.14159265358979323846) / 2 * 2e-6, 1e-21);
}

TEST(SeparationDatum, EveryQueryIsTheOriginModelsShifted) {
  const RoughSurface surfaces[] = {
      surface_of(Distribution::weibull, Side::tail, 2.0), surface_of(Distribution::weibull, Side::tail, 0.5),
      surface_of(Distribution::weibull, Side::bounded, 1.3), surface_of(Distribution::gaussian, Side::tail, 2.0)};
  double worst_trip = 0;
  for (const RoughSurface& s : surfaces) {
    const ContactModel origin(table(), s);
    const double sigma = s.height_scale;
    for (SeparationDatum datum : {SeparationDatum::mean_summit, SeparationDatum::mean_plane}) {
      const double height = datum == SeparationDatum::mean_plane ? 1.5e-6 : NAN;
      const ContactModel model(table(), s, datum, height);
      const double shift = mean_summit_closed_form(s) - (datum == SeparationDatum::mean_plane ? height : 0);
      for (double s_origin : {-2.0, -0.7, -0.1, 0.4, 1.0, 2.2, 3.5}) {
        const double d_origin = s_origin * sigma;
        if (s.side == Side::bounded && s_origin >= 0) continue;
        const PhysicalState a = origin.at_separation(d_origin);
        const PhysicalState b = model.at_separation(d_origin - shift);
        // the same point: the same state (one rounding in the separation's shift)
        const double tolerance = 1e-13 * (1 + std::fabs(std::log(a.load)));
        EXPECT_NEAR(b.load, a.load, tolerance * a.load) << s_origin;
        EXPECT_NEAR(b.count, a.count, tolerance * a.count);
        EXPECT_NEAR(b.real_area, a.real_area, tolerance * a.real_area);
        EXPECT_NEAR(b.stiffness, a.stiffness, tolerance * a.stiffness);
        EXPECT_NEAR(b.separation, d_origin - shift, 1e-15 * sigma);
        EXPECT_NEAR(b.mean_separation, a.mean_separation, 1e-15 * sigma);
        // round trip: separation -> load (pressure, area) -> separation, in the datum: as close as the
        // origin model's own round trip (the inverses' accuracy, test_physical), plus the shift's rounding
        const PhysicalState back = model.at_load(b.load);
        const double load_trip = std::fabs(origin.at_load(a.load).separation - d_origin);
        const double area_trip = std::fabs(origin.at_real_area(a.real_area).separation - d_origin);
        EXPECT_NEAR(back.separation, b.separation, load_trip + 2e-15 * sigma) << s_origin;
        EXPECT_NEAR(model.at_real_area(b.real_area).separation, b.separation, area_trip + 2e-15 * sigma) << s_origin;
        EXPECT_NEAR(model.at_pressure(b.pressure).separation, b.separation, load_trip + 2e-15 * sigma) << s_origin;
        worst_trip = std::max(worst_trip, load_trip / sigma);
        // the inverse answers in the datum: the origin model's answer less the shift
        EXPECT_NEAR(back.separation, origin.at_load(b.load).separation - shift, 1e-15 * sigma);
        EXPECT_NEAR(model.dimensionless(b.separation), s_origin, 1e-12);
      }
      // mean-summit: separation and mean_separation are one number
      if (datum == SeparationDatum::mean_summit) {
        const PhysicalState state = model.at_load(0.3);
        EXPECT_NEAR(state.separation, state.mean_separation, 1e-15 * sigma);
      }
      // no contact on the bounded side: the highest summit, seen from the datum
      if (s.side == Side::bounded) EXPECT_NEAR(model.at_load(0).separation, -shift, 1e-15 * sigma);
      else EXPECT_EQ(model.at_load(0).separation, INFINITY);
      EXPECT_EQ(model.at_load(INFINITY).separation, -INFINITY);
      EXPECT_TRUE(std::isnan(model.at_separation(NAN).load));
    }
  }
  // the origin model's own load round trip, in units of sigma_s (a = 0.5 near s = 0 is the worst)
  RecordProperty("origin_load_round_trip_separation_per_sigma", format_double(worst_trip));
}

TEST(SeparationDatum, TheOriginDatumKeepsTheFormerBits) {
  const RoughSurface s = surface_of(Distribution::weibull, Side::bounded, 1.3);
  const ContactModel implicit(table(), s), explicit_origin(table(), s, SeparationDatum::origin);
  for (double d : {-3e-6, -1e-7, -0.0}) {  // in contact (the bounded side's first contact is at 0)
    const PhysicalState a = implicit.at_separation(d), b = explicit_origin.at_separation(d);
    EXPECT_EQ(a.separation, (d / s.height_scale) * s.height_scale);  // d = sigma_s s, as before the datum
    EXPECT_EQ(std::signbit(a.separation), std::signbit(b.separation));
    EXPECT_EQ(a.separation, b.separation);
    EXPECT_EQ(a.load, b.load);
    EXPECT_EQ(implicit.dimensionless(d), d / s.height_scale);
  }
  EXPECT_EQ(implicit.at_load(0).separation, 0.0);
  EXPECT_FALSE(std::signbit(implicit.at_load(0).separation));
}

TEST(SeparationDatum, TheMeanPlaneIsTheUsersOrRefused) {
  const RoughSurface s = surface_of(Distribution::weibull, Side::tail, 2.0);
  EXPECT_NE(error_of(s, SeparationDatum::mean_plane, NAN).find("needs the mean summit height above the mean plane"),
            std::string::npos);
  EXPECT_NE(error_of(s, SeparationDatum::mean_plane, INFINITY).find("got inf"), std::string::npos);
  EXPECT_NE(error_of(s, SeparationDatum::origin, 1e-6).find("goes with the mean-plane datum"), std::string::npos);
  EXPECT_NE(error_of(s, SeparationDatum::mean_summit, 1e-6).find("goes with the mean-plane datum"), std::string::npos);
  EXPECT_EQ(error_of(s, SeparationDatum::mean_plane, 0.0), "");  // the mean summit on the mean plane: allowed
}

// The FE export measures overclosure from its own datum, whatever the model's: the same card from
// a model of each datum; the mean-plane card is the mean-summit card shifted by the height given.
TEST(SeparationDatum, TheCardDoesNotDependOnTheModelsDatum) {
  const RoughSurface s = surface_of(Distribution::weibull, Side::tail, 1.6);
  const ContactModel origin(table(), s), summit(table(), s, SeparationDatum::mean_summit),
      plane(table(), s, SeparationDatum::mean_plane, 4e-7);
  for (OverclosureDatum datum : {OverclosureDatum::mean_summit, OverclosureDatum::origin, OverclosureDatum::zero_pressure}) {
    const PressureOverclosureTable a = tabulate_pressure_overclosure(origin, 1e3, 1e8, 1e-3, datum);
    for (const ContactModel* other : {&summit, &plane}) {
      const PressureOverclosureTable b = tabulate_pressure_overclosure(*other, 1e3, 1e8, 1e-3, datum);
      ASSERT_EQ(a.points.size(), b.points.size());
      for (std::size_t i = 0; i < a.points.size(); ++i) {
        EXPECT_NEAR(b.points[i].overclosure, a.points[i].overclosure, 1e-12 * std::fabs(a.points[i].overclosure));
        EXPECT_NEAR(b.points[i].pressure, a.points[i].pressure, 1e-12 * a.points[i].pressure);
      }
    }
  }
  EXPECT_THROW(tabulate_pressure_overclosure(summit, 1e3, 1e8, 1e-3, OverclosureDatum::mean_plane), Error);
  const PressureOverclosureTable mean = tabulate_pressure_overclosure(plane, 1e3, 1e8, 1e-3, OverclosureDatum::mean_summit);
  const PressureOverclosureTable from_plane =
      tabulate_pressure_overclosure(plane, 1e3, 1e8, 1e-3, OverclosureDatum::mean_plane);
  EXPECT_EQ(from_plane.mean_summit_overclosure, -4e-7);  // the flat at the mean summit: 0.4 um clear of the plane
  // the law (overclosure from the mean summit) is the model's, whatever its datum
  EXPECT_EQ(law_pressure(plane, 1e-7), law_pressure(summit, 1e-7));
  EXPECT_NEAR(law_overclosure(plane, 1e6), law_overclosure(summit, 1e6), 1e-20);
  // a pressure's overclosure from the mean plane is its overclosure from the mean summit less 0.4 um
  EXPECT_NEAR(from_plane.points[1].overclosure, mean.points[1].overclosure - 4e-7, 1e-18);
  EXPECT_EQ(from_plane.points[1].pressure, mean.points[1].pressure);
  SeparationDatum unused;
  OverclosureDatum parsed;
  ASSERT_TRUE(parse_overclosure_datum("mean-plane", parsed));
  EXPECT_EQ(parsed, OverclosureDatum::mean_plane);
  EXPECT_STREQ(datum_name(OverclosureDatum::origin), separation_datum_name(SeparationDatum::origin));
  EXPECT_FALSE(parse_separation_datum("zero-pressure", unused));
}

}  // namespace
