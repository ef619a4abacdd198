// FE export options (apps/asperity/pressure_overclosure.hpp): the overclosure datum, the cap on
// the card's rows and the cards' numbers. Each card, CalculiX's and Abaqus's, is parsed back as
// the solver reads it (the *SURFACE BEHAVIOR rows) and its rows and chords are checked against
// the library's law (ContactModel at the separation the overclosure names in its datum).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "asperity/asperity.h"
#include "asperity/contact_model.hpp"
#include "asperity/error.hpp"
#include "asperity/pressure_overclosure.hpp"

namespace {
using namespace asperity;

const Table& table() {
  static const Table instance = Table::open(ASPERITY_TEST_TABLE);
  return instance;
}

PhysicalSurface surface(Distribution distribution, Side side, double shape) {
  PhysicalSurface s;
  s.distribution = distribution;
  s.side = side;
  s.shape = shape;
  s.height_scale = 1e-6;
  s.summit_radius = 1e-4;
  s.summit_density = 1e10;
  s.nominal_area = 1e-4;
  s.contact_modulus = 1.15e11;
  return s;
}

struct Row {
  double pressure, overclosure;
  std::string text;
};

// The rows after the keyword; "**" lines are comments in both codes.
std::vector<Row> rows_of(const std::string& card) {
  std::vector<Row> rows;
  bool inside = false;
  std::istringstream lines(card);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("**", 0) == 0) continue;
    if (line[0] == '*') {
      inside = line == "*SURFACE BEHAVIOR,PRESSURE-OVERCLOSURE=TABULAR";
      continue;
    }
    if (!inside) continue;
    const std::size_t comma = line.find(',');
    EXPECT_NE(comma, std::string::npos) << line;
    EXPECT_LE(comma, 20u) << line;
    EXPECT_LE(line.size() - comma - 1, 20u) << line;
    rows.push_back({std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1)), line});
  }
  return rows;
}

// The law in the card's datum and units (mm, MPa): the pressure at overclosure h [mm].
double law_mpa(const ContactModel& model, const PressureOverclosureTable& law, double h_mm) {
  return law_pressure(model, h_mm * 1e-3 - law.mean_summit_overclosure) / 1e6;
}

// Rows on the law; chords within the tolerance met at 41 points an interval (never the writer's 7 or 32).
double check_card(const ContactModel& model, const PressureOverclosureTable& law, const std::vector<Row>& rows) {
  EXPECT_EQ(rows.size(), law.points.size());
  EXPECT_EQ(rows.front().pressure, 0.0);
  double worst = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_GT(rows[i].overclosure, rows[i - 1].overclosure) << rows[i].text;
    if (i + 1 == rows.size()) break;
    for (int k = 0; k <= 41; ++k) {
      const double f = k / 41.0;
      const double h = rows[i].overclosure + f * (rows[i + 1].overclosure - rows[i].overclosure);
      const double p = rows[i].pressure + f * (rows[i + 1].pressure - rows[i].pressure);
      const double exact = law_mpa(model, law, h);
      worst = std::max(worst, std::fabs(p - exact) / exact);
    }
  }
  EXPECT_LE(worst, law.tolerance);
  return worst;
}

TEST(CardOptions, EveryDatumInBothFormatsReadsBackOnTheLaw) {
  const struct {
    Distribution distribution;
    Side side;
    double shape;
  } surfaces[] = {{Distribution::weibull, Side::tail, 2}, {Distribution::weibull, Side::bounded, 3},
                  {Distribution::gaussian, Side::tail, 2}};
  for (const auto& s : surfaces) {
    const ContactModel model(table(), surface(s.distribution, s.side, s.shape));
    const double origin_from_mean = model.at_separation(0).mean_separation;  // the origin seen from the mean summit height
    for (OverclosureDatum datum :
         {OverclosureDatum::mean_summit, OverclosureDatum::origin, OverclosureDatum::zero_pressure}) {
      SCOPED_TRACE(datum_name(datum));
      const PressureOverclosureTable law = tabulate_pressure_overclosure(model, 1e4, 1e7, 1e-3, datum);
      if (datum == OverclosureDatum::mean_summit) {
        EXPECT_EQ(law.mean_summit_overclosure, 0.0);
      }
      if (datum == OverclosureDatum::origin) {
        EXPECT_EQ(law.mean_summit_overclosure, origin_from_mean);
      }
      for (CardFormat format : {CardFormat::calculix, CardFormat::abaqus}) {
        std::ostringstream out;
        write_pressure_overclosure(out, law, format, CardUnits::mm, "test");
        SCOPED_TRACE(out.str().substr(0, 2000));
        const std::vector<Row> rows = rows_of(out.str());
        check_card(model, law, rows);
        // the range's ends are the pressures asked, printed clean
        EXPECT_EQ(rows[1].text.substr(0, rows[1].text.find(',')), "0.01");
        EXPECT_EQ(rows.back().text.substr(0, rows.back().text.find(',')), "10");
        EXPECT_NE(out.str().find(std::string("--overclosure-datum ") + datum_name(datum)), std::string::npos);
        if (datum == OverclosureDatum::zero_pressure) {
          EXPECT_EQ(rows.front().text, "0,0");
          for (const Row& row : rows) EXPECT_GE(row.overclosure, 0.0);
          // the card's first point is where the law's tangent at 0.01 MPa reaches zero
          const double h = rows[1].overclosure, dh = 1e-9;
          const double slope = (law_mpa(model, law, h + dh) - law_mpa(model, law, h - dh)) / (2 * dh);
          EXPECT_NEAR(h, 0.01 / slope, 1e-5 * h);
        }
      }
    }
  }
}

TEST(CardOptions, MaxPointsLoosensTheToleranceToTheSmallestThatFits) {
  const ContactModel model(table(), surface(Distribution::weibull, Side::tail, 2));
  const PressureOverclosureTable full = tabulate_pressure_overclosure(model, 1e3, 1e8, 1e-3);
  ASSERT_GT(full.points.size(), 41u);
  EXPECT_EQ(full.tolerance, 1e-3);
  for (std::size_t cap : {std::size_t{41}, std::size_t{200}, full.points.size()}) {
    const PressureOverclosureTable law =
        tabulate_pressure_overclosure(model, 1e3, 1e8, 1e-3, OverclosureDatum::mean_summit, cap);
    EXPECT_LE(law.points.size(), cap);
    EXPECT_EQ(law.asked_tolerance, 1e-3);
    EXPECT_EQ(law.max_points, cap);
    EXPECT_LE(law.max_error, law.tolerance);
    if (cap >= full.points.size()) {
      EXPECT_EQ(law.tolerance, 1e-3);
      continue;
    }
    EXPECT_GT(law.tolerance, 1e-3);
    // stated with two digits, and the smallest such: a tolerance 10 % tighter does not fit
    EXPECT_EQ(card_number(law.tolerance).size() <= 6, true) << law.tolerance;
    const PressureOverclosureTable tighter = tabulate_pressure_overclosure(model, 1e3, 1e8, 0.9 * law.tolerance);
    EXPECT_GT(tighter.points.size(), cap);
    std::ostringstream out;
    write_pressure_overclosure(out, law, CardFormat::abaqus, CardUnits::mm, "capped");
    check_card(model, law, rows_of(out.str()));
    EXPECT_NE(out.str().find("loosened to fit at most " + std::to_string(cap) + " points"), std::string::npos);
  }
  EXPECT_THROW(tabulate_pressure_overclosure(model, 1e3, 1e8, 1e-3, OverclosureDatum::mean_summit, 2), Error);
  EXPECT_THROW(tabulate_pressure_overclosure(model, 1e3, 1e8, 1e-3, OverclosureDatum::mean_summit,
                                                  card_points_max + 1),
               Error);
}

// A tabulated curve's card (asperity exact-contact) under --max-points: at most the cap, the
// first and last points kept, every point dropped within the tolerance stated of the chord
// between the rows around it (checked here, from the curve), the tolerance the smallest of two
// digits that fits (10 % tighter needs more rows), the datum in the header.
TEST(CardOptions, TabulatedCurveKeepsAtMostMaxPointsWithinTheToleranceItStates) {
  std::vector<PressureOverclosurePoint> curve{{0.0, -2e-6}};  // first contact, then p = 1e6 (e^(h / 1e-7) - ...) rising
  for (int i = 1; i <= 300; ++i) {
    const double h = -2e-6 + i * 1e-8;
    curve.push_back({1e6 * std::expm1((h + 2e-6) / 4e-7), h});
  }
  const double mean_summit_overclosure = -3e-7;
  for (std::size_t cap : {std::size_t{12}, std::size_t{41}, std::size_t{200}, std::size_t{301}, std::size_t{400}}) {
    const TabulatedCard card = tabulate_points(curve, cap, OverclosureDatum::mean_plane, mean_summit_overclosure);
    EXPECT_EQ(card.given_points, curve.size());
    EXPECT_LE(card.points.size(), cap);
    EXPECT_EQ(card.points.front().overclosure, curve.front().overclosure);
    EXPECT_NEAR(card.points.back().overclosure, curve.back().overclosure, 1e-18);
    if (cap >= curve.size()) {
      EXPECT_EQ(card.points.size(), curve.size());
      EXPECT_EQ(card.tolerance, 0.0);
      continue;
    }
    ASSERT_GT(card.tolerance, 0.0);
    EXPECT_LE(card.max_error, card.tolerance);
    char two_digits[32];  // stated with two significant digits
    std::snprintf(two_digits, sizeof two_digits, "%.1e", card.tolerance);
    EXPECT_EQ(std::stod(two_digits), card.tolerance) << card.tolerance;
    // every point of the curve against the card's linear interpolation
    double worst = 0;
    for (std::size_t i = 1, row = 1; i < curve.size(); ++i) {
      while (row + 1 < card.points.size() && curve[i].overclosure > card.points[row].overclosure) ++row;  // (13 digits)
      const PressureOverclosurePoint &a = card.points[row - 1], &b = card.points[row];
      const double chord =
          a.pressure + (curve[i].overclosure - a.overclosure) / (b.overclosure - a.overclosure) * (b.pressure - a.pressure);
      const double error = std::fabs(chord - curve[i].pressure) / curve[i].pressure;
      worst = std::max(worst, error);
    }
    EXPECT_LE(worst, card.tolerance * (1 + 1e-9)) << cap;
    EXPECT_NEAR(worst, card.max_error, 1e-9 * card.max_error) << cap;
    // the smallest that fits: one row fewer needs a larger tolerance, or none fits
    try {
      EXPECT_GT(tabulate_points(curve, card.points.size() - 1, OverclosureDatum::mean_plane, 0).tolerance, card.tolerance);
    } catch (const Error&) {
    }
    std::ostringstream out;
    write_tabulated_pressure_overclosure(out, card, CardFormat::abaqus, CardUnits::mm, "a curve", "from a test");
    const std::vector<Row> rows = rows_of(out.str());
    ASSERT_EQ(rows.size(), card.points.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      EXPECT_NEAR(rows[i].pressure, card.points[i].pressure / 1e6, 1e-12 * card.points[i].pressure / 1e6 + 1e-300);
      EXPECT_NEAR(rows[i].overclosure, card.points[i].overclosure * 1e3, 1e-12 * std::fabs(card.points[i].overclosure) * 1e3);
    }
    EXPECT_NE(out.str().find("--overclosure-datum mean-plane; the mean\n**   summit height is 0.0003 mm above it"),
              std::string::npos)
        << out.str();
    EXPECT_NE(out.str().find("rows: " + std::to_string(card.points.size()) + " of the curve's 301 points (at most " +
                             std::to_string(cap) + ")"),
              std::string::npos)
        << out.str();
  }
  // the datum without a mean summit height (a map without summits): nothing said of it
  std::ostringstream none;
  write_tabulated_pressure_overclosure(none, tabulate_points(curve, 400, OverclosureDatum::zero_pressure, NAN),
                                       CardFormat::calculix, CardUnits::si, "", "");
  EXPECT_EQ(none.str().find("mean summit height"), std::string::npos) << none.str();
  EXPECT_NE(none.str().find("(--overclosure-datum zero-pressure,"), std::string::npos) << none.str();
  // a cap that even a tolerance of 0.1 cannot meet, and caps out of range
  EXPECT_THROW(tabulate_points(curve, 3, OverclosureDatum::mean_summit, 0), Error);
  EXPECT_THROW(tabulate_points(curve, 2, OverclosureDatum::mean_summit, 0), Error);
  EXPECT_THROW(tabulate_points(curve, card_points_max + 1, OverclosureDatum::mean_summit, 0), Error);
}

TEST(CardOptions, NumbersAreTheShortestThatReadBack) {
  EXPECT_EQ(card_number(1e6), "1000000");
  EXPECT_EQ(card_number(1e8 / 1e6), "100");
  EXPECT_EQ(card_number(999999.99999999994), "1000000");  // within the card's 13 digits of 1e6
  EXPECT_EQ(card_number(0.1 + 0.2), "0.3");
  EXPECT_EQ(card_number(-2e-7 * 1e3), "-0.0002");
  EXPECT_EQ(card_number(1e-7), "1e-07");
  EXPECT_EQ(card_number(0.0), "0");
  for (double value : {-1.2345678901234567e-5, 1.2345678901234567e-5, -9.87654321098765e-300, 1.2345678901234567e14,
                       -1.2345678901234567e15, 0.012345678901234567}) {
    const std::string text = card_number(value);
    EXPECT_LE(text.size(), 20u) << text;
    EXPECT_NEAR(std::stod(text), value, 5e-13 * std::fabs(value)) << text;
  }
  // the card's rows: shortest forms (no trailing zeros, no 17-digit tails)
  const ContactModel model(table(), surface(Distribution::weibull, Side::tail, 2));
  const PressureOverclosureTable law = tabulate_pressure_overclosure(model, 1e4, 1e8, 1e-3);
  for (CardUnits units : {CardUnits::si, CardUnits::mm}) {
    std::ostringstream out;
    write_pressure_overclosure(out, law, CardFormat::calculix, units, "");
    for (const Row& row : rows_of(out.str())) {
      for (const std::string& field : {row.text.substr(0, row.text.find(',')), row.text.substr(row.text.find(',') + 1)}) {
        const std::string mantissa = field.substr(0, field.find('e'));
        if (mantissa.find('.') != std::string::npos) {
          EXPECT_NE(mantissa.back(), '0') << row.text;
        }
        std::size_t digits = 0;
        for (char c : mantissa) digits += c >= '0' && c <= '9';
        EXPECT_LE(digits, 13u + 5u) << row.text;  // 13 significant digits and at most 5 leading zeros
      }
    }
  }
}

// --face-size is in the card's units; the cut-off's warning names the lengths and pressures in them,
// in the card's header too.
TEST(CardOptions, FaceSizeCutOffInTheCardsUnits) {
  EXPECT_EQ(card_length_unit(CardUnits::si), 1.0);
  EXPECT_EQ(card_length_unit(CardUnits::mm), 1e-3);
  // a card starting 3 um before contact, its pressure rising linearly to 1e8 Pa at contact
  const std::vector<PressureOverclosurePoint> rows{{0, -3e-6}, {1e8, 0}};
  EXPECT_EQ(calculix_cutoff_warning(rows, NAN, CardUnits::mm), "");
  EXPECT_EQ(calculix_cutoff_warning(rows, 3.1e-3, CardUnits::mm), "");  // 3.1 mm faces: cut-off 3.1 um covers it
  const std::string mm = calculix_cutoff_warning(rows, 1e-3, CardUnits::mm);  // 1 mm faces: cut-off 1 um
  EXPECT_NE(mm.find("clearance of 0.003 mm"), std::string::npos) << mm;
  EXPECT_NE(mm.find("= 0.001 mm for faces of 1 mm"), std::string::npos) << mm;
  EXPECT_NE(mm.find("below 66.6667 MPa the card never acts"), std::string::npos) << mm;  // 2/3 of the way to 1e8 Pa
  const std::string si = calculix_cutoff_warning(rows, 1e-3, CardUnits::si);
  EXPECT_NE(si.find("= 1e-06 m for faces of 0.001 m"), std::string::npos) << si;
  EXPECT_NE(si.find("below 6.66667e+07 Pa"), std::string::npos) << si;
  // in the header, and a card without clearance never warns
  std::ostringstream card;
  write_tabulated_pressure_overclosure(card, tabulate_points(rows, 200, OverclosureDatum::mean_summit, 0),
                                       CardFormat::calculix, CardUnits::mm, "", "", 1e-3);
  EXPECT_NE(card.str().find("**   WARNING: the card reaches a clearance of 0.003 mm"), std::string::npos) << card.str();
  const std::vector<PressureOverclosurePoint> touching{{0, 0}, {1e8, 3e-6}};
  EXPECT_EQ(calculix_cutoff_warning(touching, 1e-9, CardUnits::si), "");
}

// The C API's card with the command line's options: datum zero-pressure and 200 rows for calculix
// by default, the cap and the face size (in the card's units) as asked; the old function unchanged.
TEST(CardOptions, CApiCardOptionsAsTheCommandLine) {
  char err[512] = "";
  asperity_table* c_table = nullptr;
  ASSERT_EQ(asperity_table_load(ASPERITY_TEST_TABLE, &c_table, err, sizeof err), ASPERITY_OK) << err;
  asperity_model* model =
      asperity_model_open(c_table, "weibull", "tail", 2, 1e-6, 1e-4, 1e10, 1e-4, 1.15e11, err, sizeof err);
  ASSERT_NE(model, nullptr) << err;
  const auto card = [&](const char* units, const char* datum, size_t max_points, double face_size) {
    size_t length = 0;
    asperity_model_pressure_overclosure_card_options(model, 1e3, 1e8, 1e-3, "calculix", units, datum, max_points,
                                                     face_size, nullptr, nullptr, 0, &length, err, sizeof err);
    std::string text(length + 1, '\0');
    EXPECT_EQ(asperity_model_pressure_overclosure_card_options(model, 1e3, 1e8, 1e-3, "calculix", units, datum,
                                                               max_points, face_size, nullptr, text.data(),
                                                               text.size(), &length, err, sizeof err),
              ASPERITY_OK)
        << err;
    text.resize(length);
    return text;
  };
  const std::string standard = card("mm", nullptr, 0, NAN);
  EXPECT_LE(rows_of(standard).size(), calculix_points_max);
  EXPECT_NE(standard.find("TABULAR\n0,0\n"), std::string::npos) << standard;  // zero-pressure: the default
  const std::string capped = card("mm", "mean-summit", 41, NAN);
  EXPECT_EQ(rows_of(capped).size(), 41u);
  EXPECT_NE(capped.find("(--overclosure-datum mean-summit)"), std::string::npos);
  // faces of 1 mm with a card in mm: the cut-off is 1e-3 mm, and the card reaches 3 um
  EXPECT_NE(card("mm", "mean-summit", 0, 1).find("WARNING: the card reaches a clearance"), std::string::npos);
  EXPECT_EQ(card("mm", "mean-summit", 0, 100).find("WARNING"), std::string::npos);  // 100 mm faces: 0.1 mm
  EXPECT_EQ(card("mm", nullptr, 0, 1).find("WARNING"), std::string::npos);  // zero-pressure: no clearance
  EXPECT_EQ(asperity_model_pressure_overclosure_card_options(model, 1e3, 1e8, 1e-3, "calculix", "si", "mean", 0, NAN,
                                                             nullptr, nullptr, 0, nullptr, err, sizeof err),
            ASPERITY_BAD_NAME);
  // the old function: mean-summit, no cap
  size_t length = 0;
  asperity_model_pressure_overclosure_card(model, 1e3, 1e8, 1e-3, "calculix", "si", nullptr, nullptr, 0, &length, err,
                                           sizeof err);
  std::string old(length + 1, '\0');
  ASSERT_EQ(asperity_model_pressure_overclosure_card(model, 1e3, 1e8, 1e-3, "calculix", "si", nullptr, old.data(),
                                                     old.size(), &length, err, sizeof err),
            ASPERITY_OK);
  EXPECT_NE(old.find("(--overclosure-datum mean-summit)"), std::string::npos);
  asperity_model_close(model);
  asperity_table_close(c_table);
}

}  // namespace
