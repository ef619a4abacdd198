// `asperity surface`: the command end to end, run as the `asperity` program (summary, JSON,
// report directory). Its usage errors and messages are checked with cli_check in CMakeLists.txt,
// like the other commands'.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "asperity/contact_law.hpp"
#include "contact_law_reference.hpp"

namespace {
const std::string surfaces = ASPERITY_TEST_SURFACES;
const std::string work = std::string(ASPERITY_TEST_BINARY_DIR) + "/topography_cli";

struct CommandRun {
  int status;
  std::string out, err;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::string quoted(const std::string& argument) {
  std::string text = "'";
  for (char c : argument) text += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return text + "'";
}

// Runs `asperity surface ARGUMENTS...`, standard output and error into files.
CommandRun run(const std::vector<std::string>& arguments) {
  std::filesystem::create_directories(work);
  std::string command = quoted(ASPERITY_COMMAND) + " surface";
  for (const std::string& argument : arguments) command += " " + quoted(argument);
  const std::string out = work + "/stdout.txt", err = work + "/stderr.txt";
  const int status = std::system((command + " >" + quoted(out) + " 2>" + quoted(err)).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
}
}  // namespace

TEST(TopographyCli, SummaryOfTheRealX3P) {
  const CommandRun r = run({surfaces + "/digitalsurf-650x650.x3p", "--ensemble", "40", "--no-height-fit",
                            "--modulus", "1e11", "--pressure", "1e6"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("650 x 650 points"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("summits 2482"), std::string::npos) << r.out;
  // how many measured summits carry the answer (issue 40): 27, enough to name the closest model
  EXPECT_NE(r.out.find("at 1e+06 Pa (27 measured summits in contact): stiffness per area"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Closest to GW on the measured summits (no law fitted): "), std::string::npos) << r.out;
}

TEST(TopographyCli, JsonAndReport) {
  const std::string dir = work + "/report";
  std::filesystem::remove_all(dir);
  const CommandRun r = run({surfaces + "/afm-zsensor-10um.txt", "--ensemble", "40", "--json", "--report", dir,
                            "--modulus=2e9", "--load", "1e-5", "--summit-window", "2"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{", 0), 0u);
  EXPECT_NE(r.out.find("\"schema\": \"asperity-surface/3\""), std::string::npos);
  EXPECT_NE(r.out.find("\"window_points\": 2"), std::string::npos);
  // standard error holds at most the progress of the ensemble and of the exact contact (solved by
  // default on this 256 x 256 map: a run over a second)
  std::istringstream lines(r.err);
  for (std::string line; std::getline(lines, line);)
    EXPECT_TRUE(line.rfind("asperity surface: ensemble ", 0) == 0 || line.find("asperity surface: exact contact, load step") != std::string::npos)
        << line;
  for (const char* name : {"report.md", "report.json", "curves.csv", "summits.csv", "fits.svg", "contact.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << name;
  const std::string text = read_text(dir + "/report.md");
  EXPECT_NE(text.find("![fits](fits.svg)"), std::string::npos);
  // --load 1e-5 N over the measured 1e-10 m^2: 1e5 Pa
  EXPECT_NE(text.find("At a nominal pressure of 1e+05 Pa"), std::string::npos);
}

// ---- hostile inputs (issue 26): a clear message, exit 2, nothing run or lost ----

namespace {
void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}
}  // namespace

// A map at its noise floor gets its statistics and the statement, and exit 2 (what was asked
// beyond the statistics does not exist); a too small bootstrap is refused.
TEST(TopographyCli, NoiseFloorAndTooSmallBootstrap) {
  std::string matrix = "# Width: 1 um\n# Height: 1 um\n# Value units: nm\n";
  for (int j = 0; j < 40; ++j) {
    for (int i = 0; i < 40; ++i) matrix += std::to_string(i + 2 * j) + (i + 1 < 40 ? " " : "\n");  // a plane in whole nm
  }
  const std::string plane = work + "/plane.txt";
  std::filesystem::create_directories(work);
  write_text(plane, matrix);
  const CommandRun r = run({plane, "--ensemble", "40", "--modulus", "1e11"});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.out.find("noise floor"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("at the level of the heights' quantization"), std::string::npos) << r.err;
  const CommandRun small = run({surfaces + "/afm-zsensor-10um.txt", "--bootstrap", "10"});
  EXPECT_EQ(small.status, 2);
  EXPECT_NE(small.err.find("an ensemble of 10 surrogate surfaces can never give p below 0.025"), std::string::npos)
      << small.err;
}

// Bytes of a bad file never reach the terminal as an escape sequence.
TEST(TopographyCli, FileBytesInMessagesArePrintable) {
  const std::string path = work + "/escape.txt";
  std::filesystem::create_directories(work);
  write_text(path, "# Width: 1 um\n# Height: 1 um\n# Value units: m\n1 2 3\n4 \x1b]0;owned\x07 6\n");
  const CommandRun r = run({path});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\x07'), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\\x1B]0;owned\\x07"), std::string::npos) << r.err;
}

// The map's name and the report's folder on standard output as on the other streams: control
// bytes (an escape sequence, a newline that would fake a line) shown as \xNN (issue 37)
TEST(TopographyCli, FileNamesArePrintableOnStandardOutput) {
  const std::string folder = work + "/names";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::string map = folder + "/m\x1b]0;owned\x07\nfake.txt", report = folder + "/r\x1b[2J";
  std::filesystem::copy_file(surfaces + "/afm-zsensor-10um.txt", map);
  const CommandRun r = run({map, "--ensemble", "0", "--no-height-fit", "--report", report});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\x07'), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("/m\\x1B]0;owned\\x07\\x0Afake.txt (ascii-matrix): 256 x 256 points"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  report: " + folder + "/r\\x1B[2J/report.md"), std::string::npos) << r.out;
}

// More threads than the system gives (an address-space limit: 1024 stacks do not fit) is not
// std::terminate (exit 134): the threads that start do the work.
TEST(TopographyCli, ThreadsTheSystemRefuses) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "an address-space limit is incompatible with the sanitizers' shadow memory";
#else
  const std::string out = work + "/threads.txt";
  const std::string command = "ulimit -v 1500000; " + quoted(ASPERITY_COMMAND) + " surface " +
                              quoted(surfaces + "/afm-zsensor-10um.txt") +
                              " --bootstrap 40 --no-height-fit --threads 1024 >" + quoted(out) + " 2>&1";
  const int status = std::system(("sh -c " + quoted(command)).c_str());
  ASSERT_TRUE(WIFEXITED(status)) << read_text(out);
  EXPECT_EQ(WEXITSTATUS(status), 0) << read_text(out);
  EXPECT_NE(read_text(out).find("summits"), std::string::npos);
#endif
}

// ---- a contact law beside the elastic curves (issue 30 item 6) ----

namespace {
using nlohmann::json;

const std::string afm = surfaces + "/afm-zsensor-10um.txt";
// the AFM map's contact at two pressures, without the ensemble (the verdict is not needed here)
const std::vector<std::string> afm_contact = {afm, "--ensemble", "0", "--no-height-fit", "--no-persson",
                                              "--modulus", "1e11", "--pressure", "1e6,1e7"};

std::vector<std::string> with(std::vector<std::string> arguments, const std::vector<std::string>& more) {
  arguments.insert(arguments.end(), more.begin(), more.end());
  return arguments;
}

double relative(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

const json& model_of(const json& contact, const std::string& label) {
  for (const json& m : contact["models"])
    if (m["model"] == label) return m;
  throw std::runtime_error("no model " + label);
}
}  // namespace

// Kogut-Etsion on the AFM map: the plasticity index against a hand computation from the reported
// sigma_s (itself against the summits written to summits.csv), R, E* and H; the law's pressure,
// stiffness and area at the separations reported against the independent reference quadrature
// (tests/contact_law_reference.hpp), and the elastic numbers those of the fit's own curves.
TEST(TopographyCli, LawPlasticityIndexAndCurves) {
  const std::string dir = work + "/law-report";
  std::filesystem::remove_all(dir);
  const CommandRun r = run(with(afm_contact, {"--law", "kogut-etsion", "--yield-strength", "1e9", "--law-poisson", "0.3",
                                              "--json", "--report", dir}));
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  const json& contact = j["contact"];
  const json& law = contact["law"];
  ASSERT_EQ(law["law"], "kogut-etsion");
  ASSERT_TRUE(law["served"].get<bool>()) << law["note"];
  const json& plasticity = law["plasticity"];
  const double sd = plasticity["summit_height_standard_deviation_m"], radius = plasticity["summit_radius_m"];
  const double e = 1e11, y = 1e9, nu = 0.3, h = 2.8 * y, k = 0.454 + 0.41 * nu, pi = 3.14159265358979323846;
  EXPECT_EQ(radius, j["summits"]["radius_m"].get<double>());
  // sigma_s: the sample standard deviation of the summit heights written to summits.csv
  {
    std::istringstream csv(read_text(dir + "/summits.csv"));
    std::string line;
    std::getline(csv, line);
    std::vector<double> heights;
    while (std::getline(csv, line)) {
      std::istringstream fields(line);
      std::string field;
      for (int column = 0; column < 5; ++column) std::getline(fields, field, ',');
      heights.push_back(std::stod(field));
    }
    ASSERT_EQ(heights.size(), j["summits"]["count"].get<std::size_t>());
    double mean = 0, squares = 0;
    for (double z : heights) mean += z;
    mean /= static_cast<double>(heights.size());
    for (double z : heights) squares += (z - mean) * (z - mean);
    EXPECT_LT(relative(sd, std::sqrt(squares / static_cast<double>(heights.size() - 1))), 1e-8);
  }
  const double wc = std::pow(pi * k * h / (2 * e), 2) * radius;
  EXPECT_LT(relative(plasticity["critical_interference_m"], wc), 1e-13);
  EXPECT_LT(relative(plasticity["hardness_Pa"], h), 1e-15);
  EXPECT_LT(relative(plasticity["psi"], std::sqrt(sd / wc)), 1e-13);
  EXPECT_LT(relative(plasticity["psi_gw"], e / h * std::sqrt(sd / radius)), 1e-13);
  EXPECT_NE(plasticity["regime"].get<std::string>().find("GW's psi = "), std::string::npos);

  // the law's curves on the verdict's fit, against the reference at the reported separations
  const json& fit = model_of(contact, law["model"]);
  const json& surface = fit["surface"];
  asperity::test::SummitHeights heights;
  heights.distribution = surface["distribution"] == "weibull" ? asperity::Distribution::weibull : asperity::Distribution::gaussian;
  heights.side = surface["side"] == "bounded" ? asperity::Side::bounded : asperity::Side::tail;
  if (heights.distribution == asperity::Distribution::weibull) heights.shape = surface["shape"];
  heights.scale = surface["height_scale_m"];
  const double density = surface["summit_density_per_m2"];
  const asperity::ContactLaw ke = asperity::kogut_etsion_law(radius, e, y, nu);
  ASSERT_EQ(law["at_pressures"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const json& at = law["at_pressures"][i];
    const double p = at["pressure_Pa"];
    const double s = at["law"]["separation_m"].get<double>() / heights.scale;
    const asperity::test::RoughSurfaceValues exact = asperity::test::law_integrals(ke, heights, s);
    EXPECT_LT(relative(density * exact.load, p), 1e-6) << p;
    EXPECT_LT(relative(density * exact.stiffness, at["law"]["stiffness_per_area_N_per_m3"]), 1e-5) << p;
    EXPECT_LT(relative(density * exact.area, at["law"]["area_fraction"]), 1e-5) << p;
    // the elastic numbers: the fit's own, and the ratios between them
    EXPECT_EQ(at["elastic"]["mean_separation_m"], fit["at_pressures"][i]["mean_separation_m"]);
    EXPECT_EQ(at["elastic"]["stiffness_N_per_m"], fit["at_pressures"][i]["stiffness_N_per_m"]);
    EXPECT_LT(relative(at["stiffness_over_elastic"],
                       at["law"]["stiffness_N_per_m"].get<double>() / at["elastic"]["stiffness_N_per_m"].get<double>()),
              1e-15);
    EXPECT_LT(relative(at["area_over_elastic"],
                       at["law"]["real_area_m2"].get<double>() / at["elastic"]["real_area_m2"].get<double>()),
              1e-15);
    // a plastic surface (psi ~ 15) carries the same load on more area, less stiffly, closer
    EXPECT_GT(at["area_over_elastic"].get<double>(), 2.0);
    EXPECT_LT(at["stiffness_over_elastic"].get<double>(), 1.0);
    EXPECT_LT(at["mean_separation_minus_elastic_m"].get<double>(), 0.0);
  }
  for (const char* name : {"report.md", "law.svg", "curves.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << name;
  EXPECT_NE(read_text(dir + "/curves.csv").find("\nlaw:kogut-etsion,"), std::string::npos);
}

// Hertz as the law is the elastic curve itself (the generator's table against the default
// table's, two independent tabulations): ratios 1; and the outputs without --law are the outputs
// with it less the law's object.
TEST(TopographyCli, HertzLawIsTheElasticCurveAndNoLawChangesNothing) {
  const CommandRun plain = run(with(afm_contact, {"--json"}));
  const CommandRun hertz = run(with(afm_contact, {"--json", "--law", "hertz"}));
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(hertz.status, 0) << hertz.err;
  json a = json::parse(plain.out), b = json::parse(hertz.out);
  const json law = b["contact"]["law"];
  ASSERT_TRUE(law["served"].get<bool>()) << law["note"];
  EXPECT_TRUE(law["plasticity"]["psi"].is_null());  // Hertz has no critical interference
  const double scale = model_of(b["contact"], law["model"])["surface"]["height_scale_m"];
  for (const json& at : law["at_pressures"]) {
    EXPECT_LT(std::fabs(at["stiffness_over_elastic"].get<double>() - 1), 1e-6);
    EXPECT_LT(std::fabs(at["area_over_elastic"].get<double>() - 1), 1e-6);
    EXPECT_LT(std::fabs(at["mean_separation_minus_elastic_m"].get<double>()), 1e-7 * scale);
  }
  b["contact"].erase("law");
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.dump().find("\"law\""), std::string::npos);
  const CommandRun summary = run(afm_contact);
  ASSERT_EQ(summary.status, 0) << summary.err;
  EXPECT_EQ(summary.out.find("\n  law "), std::string::npos) << summary.out;
}

// A law's limits are stated, not silently wrong: Jackson-Green's fits end where a = R (a Gaussian's
// highest summits reach it); a soft material's real area passes GW's sparse-contact limit (warned)
// or 1 (no curves).
TEST(TopographyCli, LawLimitsAreStated) {
  const CommandRun jg = run(with(afm_contact, {"--law", "jackson-green", "--yield-strength", "1e9", "--law-poisson", "0.3"}));
  ASSERT_EQ(jg.status, 0) << jg.err;
  EXPECT_NE(jg.out.find("jackson-green: no curves over the pressures 1e+05 to 3e+07 Pa"), std::string::npos) << jg.out;
  EXPECT_NE(jg.out.find("beyond the interference its source supports"), std::string::npos) << jg.out;
  EXPECT_NE(jg.out.find("no hardness for GW's psi (jackson-green takes the yield strength); the law's psi = "),
            std::string::npos) << jg.out;
  const CommandRun soft = run(with(afm_contact, {"--law", "kogut-etsion", "--yield-strength", "3e7", "--law-poisson", "0.3"}));
  ASSERT_EQ(soft.status, 0) << soft.err;
  EXPECT_NE(soft.out.find("kogut-etsion: at 1e+07 Pa the real area fraction under the law is "), std::string::npos)
      << soft.out;
  const CommandRun softer = run(with(afm_contact, {"--law", "kogut-etsion", "--yield-strength", "1e6", "--law-poisson", "0.3"}));
  ASSERT_EQ(softer.status, 0) << softer.err;
  EXPECT_NE(softer.out.find("kogut-etsion: no curves over the pressures"), std::string::npos) << softer.out;
  EXPECT_NE(softer.out.find("GW's psi = "), std::string::npos) << softer.out;
}

namespace {
// Runs a command the report printed ("asperity ..."), in `directory`, through the shell: the
// commands are meant to be pasted as they are.
CommandRun run_printed(const std::string& printed, const std::string& directory) {
  std::filesystem::create_directories(directory);
  const std::string command = "(cd " + quoted(directory) + " && " + quoted(ASPERITY_COMMAND) + printed.substr(8) + ")";
  const std::string out = directory + "/printed-stdout.txt", err = directory + "/printed-stderr.txt";
  const int status = std::system((command + " >" + quoted(out) + " 2>" + quoted(err)).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
}

std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}
}  // namespace

// The report ends with what to do next (issue 39): for the model it names, the `asperity contact`
// command reproduces the report's curve of that model (the default table's shape interpolation
// against the report's exact-shape scene table: within 1e-4), and its card command writes a card;
// where no model is named, the exact-contact command runs as printed (fewer steps) and writes its
// table and card.
TEST(TopographyCli, NextStepsRunAsPrinted) {
  const CommandRun r = run({surfaces + "/digitalsurf-650x650.x3p", "--ensemble", "40", "--modulus", "1e11",
                            "--pressure", "1e6,1e7", "--no-persson", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  const json& next = j["next_steps"];
  ASSERT_TRUE(next["model_named"].get<bool>()) << next.dump(1);
  const std::string model = next["model"];
  const std::string directory = work + "/next-steps";
  const CommandRun contact = run_printed(next["contact_command"], directory);
  ASSERT_EQ(contact.status, 0) << contact.err;
  const auto rows = csv_rows(contact.out);
  ASSERT_EQ(rows.size(), 9u);
  const json& curve = model_of(j["contact"], model)["curve"];
  for (const auto& [row, state] : {std::pair{rows.front(), curve.front()}, std::pair{rows.back(), curve.back()}}) {
    EXPECT_LT(relative(row[6], state["nominal_pressure_Pa"]), 1e-9);
    EXPECT_LT(relative(row[1], state["mean_separation_m"]), 1e-4) << contact.out;
    EXPECT_LT(relative(row[7], state["stiffness_N_per_m"]), 1e-4) << contact.out;
  }
  std::filesystem::remove(directory + "/" + model + ".inp");
  const CommandRun card = run_printed(next["card_command"], directory);
  ASSERT_EQ(card.status, 0) << card.err;
  EXPECT_EQ(read_text(directory + "/" + model + ".inp").rfind("** asperity", 0), 0u);
  EXPECT_NE(r.out.find("Its pressure-overclosure card"), std::string::npos);
  // surface --card writes that card: the same rows
  const std::string card_path = directory + "/surface-card.inp";
  std::filesystem::remove(card_path);
  const CommandRun with_card = run({surfaces + "/digitalsurf-650x650.x3p", "--ensemble", "40", "--modulus", "1e11",
                                    "--pressure", "1e6,1e7", "--no-persson", "--quiet", "--card", card_path});
  ASSERT_EQ(with_card.status, 0) << with_card.err;
  const auto rows_of = [](const std::string& card) { return card.substr(card.find("*SURFACE BEHAVIOR")); };
  EXPECT_EQ(rows_of(read_text(card_path)), rows_of(read_text(directory + "/" + model + ".inp")));

  const CommandRun afm_run = run(with(afm_contact, {"--json"}));
  ASSERT_EQ(afm_run.status, 0) << afm_run.err;
  const json afm_next = json::parse(afm_run.out)["next_steps"];
  std::string exact = afm_next["exact_command"];
  ASSERT_FALSE(exact.empty());
  const std::size_t steps = exact.find(":17 ");
  ASSERT_NE(steps, std::string::npos) << exact;
  exact.replace(steps, 4, ":3 ");
  const CommandRun solved = run_printed(exact, directory);
  ASSERT_EQ(solved.status, 0) << solved.err;
  EXPECT_TRUE(std::filesystem::exists(directory + "/afm-zsensor-10um-exact.h5"));
  EXPECT_EQ(read_text(directory + "/afm-zsensor-10um-exact.inp").rfind("** asperity", 0), 0u);
}
