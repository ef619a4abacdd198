// FE export (asperity/pressure_overclosure.hpp): the card is read back as CalculiX and
// Abaqus read it, and linear interpolation between its points is checked against the library's
// law (ContactModel at the separation the overclosure names) at points the writer never used.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/contact_model.hpp"
#include "asperity/error.hpp"
#include "asperity/pressure_overclosure.hpp"

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

RoughSurface surface(Distribution distribution, Side side, double shape, double sigma) {
  RoughSurface s;
  s.distribution = distribution;
  s.side = side;
  s.shape = shape;
  s.height_scale = sigma;
  s.summit_radius = 1e-4;
  s.summit_density = 1e10;
  s.nominal_area = 1e-4;
  s.contact_modulus = 1.15e11;
  return s;
}

struct Card {
  bool keyword = false;
  std::vector<double> pressure, overclosure;  // as written
};

// What a reader of the input deck sees: "**" comments, the keyword line, then pressure,overclosure pairs.
Card parse_card(const std::string& text) {
  Card card;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("**", 0) == 0) continue;
    if (line[0] == '*') {
      EXPECT_EQ(line, "*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=TABULAR");
      card.keyword = true;
      continue;
    }
    EXPECT_TRUE(card.keyword) << "data before the keyword: " << line;
    const std::size_t comma = line.find(',');
    EXPECT_NE(comma, std::string::npos) << line;
    EXPECT_LE(comma, 20u) << "CalculiX reads 20 characters a field: " << line;
    EXPECT_LE(line.size() - comma - 1, 20u) << line;
    card.pressure.push_back(std::stod(line.substr(0, comma)));
    card.overclosure.push_back(std::stod(line.substr(comma + 1)));
  }
  return card;
}

Card parse_csv(const std::string& text, const std::string& header) {
  Card card;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, header);
  while (std::getline(lines, line)) {
    const std::size_t comma = line.find(',');
    card.pressure.push_back(std::stod(line.substr(0, comma)));
    card.overclosure.push_back(std::stod(line.substr(comma + 1)));
  }
  return card;
}

// Checks the shape of the table and interpolation against the law; returns the largest error seen.
double check_against_law(const ContactModel& model, const Card& card, double length, double pressure_unit,
                         double pressure_min, double pressure_max, double tolerance) {
  const std::size_t n = card.pressure.size();
  EXPECT_GE(n, 3u);
  EXPECT_EQ(card.pressure[0], 0.0);  // both codes: no pressure below the first point
  for (std::size_t i = 1; i < n; ++i) {
    EXPECT_GT(card.overclosure[i], card.overclosure[i - 1]) << "ascending overclosure, row " << i;
    EXPECT_GT(card.pressure[i], card.pressure[i - 1]) << "ascending pressure, row " << i;
  }
  EXPECT_NEAR(card.pressure[1] * pressure_unit, pressure_min, 1e-9 * pressure_min);
  EXPECT_NEAR(card.pressure[n - 1] * pressure_unit, pressure_max, 1e-9 * pressure_max);
  double worst = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    // every written point is on the law, and 37 points inside each interval (never the writer's 7 or 32)
    for (int k = 0; k < 37; ++k) {
      const double fraction = k / 37.0;
      const double h = card.overclosure[i] + fraction * (card.overclosure[i + 1] - card.overclosure[i]);
      const double p = card.pressure[i] + fraction * (card.pressure[i + 1] - card.pressure[i]);
      const double law = law_pressure(model, h / length) / pressure_unit;
      worst = std::max(worst, std::fabs(p - law) / law);
    }
  }
  EXPECT_LE(worst, tolerance);
  // Below the lowest pressure the card follows the law's tangent to zero: the law lies above it.
  const double h_low = card.overclosure[1], h_zero = card.overclosure[0];
  EXPECT_LT(h_zero, h_low);
  const double law_middle = law_pressure(model, 0.5 * (h_zero + h_low) / length) / pressure_unit;
  EXPECT_GE(law_middle, 0.5 * card.pressure[1]);
  return worst;
}

struct Case {
  Distribution distribution;
  Side side;
  double shape, sigma, pressure_min, pressure_max, tolerance;
};

TEST(PressureOverclosure, CardsReadBackAgreeWithTheLibrary) {
  const Case cases[] = {
      {Distribution::weibull, Side::tail, 2, 1e-6, 1e3, 1e8, 1e-3},
      {Distribution::weibull, Side::tail, 1.6, 5e-7, 1, 1e7, 1e-4},
      {Distribution::weibull, Side::bounded, 3, 2e-6, 1e2, 1e6, 1e-3},
      {Distribution::gaussian, Side::tail, 2, 1e-6, 1e3, 1e7, 1e-2},
  };
  for (const Case& c : cases) {
    const ContactModel model(table(), surface(c.distribution, c.side, c.shape, c.sigma));
    const PressureOverclosureTable law =
        tabulate_pressure_overclosure(model, c.pressure_min, c.pressure_max, c.tolerance);
    EXPECT_LE(law.max_error, c.tolerance);
    EXPECT_GT(law.checked_points, 0);
    for (CardFormat format : {CardFormat::calculix, CardFormat::abaqus})
      for (CardUnits units : {CardUnits::si, CardUnits::mm}) {
        std::ostringstream out;
        write_pressure_overclosure(out, law, format, units, "test card\nsecond line");
        SCOPED_TRACE(out.str().substr(0, 1200));
        const Card card = parse_card(out.str());
        EXPECT_EQ(card.pressure.size(), law.points.size());
        const double length = units == CardUnits::mm ? 1e3 : 1, pressure_unit = units == CardUnits::mm ? 1e6 : 1;
        check_against_law(model, card, length, pressure_unit, c.pressure_min, c.pressure_max, c.tolerance);
        EXPECT_NE(out.str().find(units == CardUnits::mm ? "overclosure in mm, pressure in MPa"
                                                             : "overclosure in m, pressure in Pa"),
                  std::string::npos);
      }
    std::ostringstream csv;
    write_pressure_overclosure(csv, law, CardFormat::csv, CardUnits::si, "");
    check_against_law(model, parse_csv(csv.str(), "pressure_Pa,overclosure_m"), 1, 1, c.pressure_min, c.pressure_max,
                      c.tolerance);
  }
}

TEST(PressureOverclosure, OverclosureIsMeasuredFromTheMeanSummitHeight) {
  const ContactModel model(table(), surface(Distribution::weibull, Side::tail, 2, 1e-6));
  for (double pressure : {1e3, 1e5, 1e7}) {
    const PhysicalState state = model.at_pressure(pressure);
    EXPECT_NEAR(law_overclosure(model, pressure), -state.mean_separation, 1e-12 * 1e-6);
    EXPECT_NEAR(law_pressure(model, -state.mean_separation), pressure, 1e-9 * pressure);
  }
}

TEST(PressureOverclosure, RefusesWhatItCannotDo) {
  const ContactModel model(table(), surface(Distribution::weibull, Side::tail, 2, 1e-6));
  EXPECT_THROW(tabulate_pressure_overclosure(model, 0, 1e6, 1e-3), Error);
  EXPECT_THROW(tabulate_pressure_overclosure(model, 1e6, 1e3, 1e-3), Error);
  EXPECT_THROW(tabulate_pressure_overclosure(model, 1e3, INFINITY, 1e-3), Error);
  EXPECT_THROW(tabulate_pressure_overclosure(model, 1e3, 1e6, 1e-9), Error);
  EXPECT_THROW(tabulate_pressure_overclosure(model, 1e3, 1e6, 0.5), Error);
  // Points 1e-10 m apart or closer are moved by CalculiX: refused in m, written in mm.
  const ContactModel fine(table(), surface(Distribution::weibull, Side::tail, 2, 1e-9));
  const PressureOverclosureTable law = tabulate_pressure_overclosure(fine, 1e3, 1e8, 1e-6);
  std::ostringstream out;
  EXPECT_THROW(write_pressure_overclosure(out, law, CardFormat::calculix, CardUnits::si, ""), Error);
  EXPECT_NO_THROW(write_pressure_overclosure(out, law, CardFormat::calculix, CardUnits::mm, ""));
  EXPECT_NO_THROW(write_pressure_overclosure(out, law, CardFormat::abaqus, CardUnits::si, ""));
}

// A tabulated curve (asperity exact-contact): its points as given, rounded to the card's digits,
// in the law's card with its own notes; points out of order refused.
TEST(PressureOverclosure, TabulatedCurve) {
  const std::vector<PressureOverclosurePoint> points{{0, -2e-7}, {1e6, -1.5e-7}, {1e7, -1.0000000000001234e-7}};
  std::ostringstream out;
  write_tabulated_pressure_overclosure(out, points, CardFormat::calculix, CardUnits::mm, "a curve",
                                            "points: 2 solutions\nfirst point: first contact");
  EXPECT_EQ(out.str(),
            "** a curve\n"
            "** units: overclosure in mm, pressure in MPa\n"
            "** overclosure: interpenetration of the contact surfaces (a clearance is negative), measured\n"
            "**   from the rough surface's mean summit height to the flat\n"
            "** points: 2 solutions\n"
            "** first point: first contact\n"
            "** CalculiX: use this card with node-to-surface contact (*CONTACT PAIR, TYPE=NODE TO SURFACE),\n"
            "**   which holds at most 200 points. Face-to-face contact (ccx 2.20) does not work with it: above\n"
            "**   41 points ccx crashes, and it starts contact only at positive overclosure, so clearances give\n"
            "**   zero force, silently.\n"
            "** node-to-surface contact makes a contact spring only where the clearance is below 1e-3 sqrt(A),\n"
            "**   A the slave node's area (1e-3 L for faces of edge L);\n"
            "**   this card reaches a clearance of 0.0002 mm: beyond the cut-off its pressures never act\n"
            "** beyond the last point CalculiX keeps the last pressure\n"
            "*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=TABULAR\n"
            "0,-0.0002\n1,-0.00015\n10,-0.0001\n");
  std::ostringstream csv;
  write_tabulated_pressure_overclosure(csv, points, CardFormat::csv, CardUnits::si, "", "");
  EXPECT_EQ(csv.str(), "pressure_Pa,overclosure_m\n0,-2e-07\n1000000,-1.5e-07\n10000000,-1e-07\n");
  std::ostringstream refused;
  const auto write = [&](const std::vector<PressureOverclosurePoint>& p) {
    write_tabulated_pressure_overclosure(refused, p, CardFormat::abaqus, CardUnits::si, "", "");
  };
  EXPECT_THROW(write({{0, -2e-7}}), Error);                            // one point
  EXPECT_THROW(write({{0, -1e-7}, {1e6, -2e-7}}), Error);              // overclosure falling
  EXPECT_THROW(write({{1e6, -2e-7}, {1e5, -1e-7}}), Error);            // pressure falling
  EXPECT_THROW(write({{0, -2e-7}, {NAN, -1e-7}}), Error);              // not finite
  EXPECT_THROW(write({{-1, -2e-7}, {1e6, -1e-7}}), Error);             // negative pressure
}

}  // namespace
