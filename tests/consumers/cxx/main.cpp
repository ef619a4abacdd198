// An installed asperity from C++ (find_package): the default table it finds, a value against
// the closed form J_1(s) = (sqrt(pi)/2) erfc(s) for a = 2, and an error caught across the
// library's boundary. Prints the table's path for tests/consumers/run.sh to check.
#include <cmath>
#include <cstdio>

#include "asperity/contact.hpp"
#include "asperity/error.hpp"
#include "asperity/table.hpp"

int main() {
  const std::string path = asperity::Table::default_path();
  const asperity::Table table = asperity::Table::open_default();
  const asperity::Curve curve = table.curve(asperity::Distribution::weibull, asperity::Side::tail, 2.0);
  const double s = 0.7, value = curve.value(2, s), expected = 0.5 * std::sqrt(std::acos(-1.0)) * std::erfc(s);
  std::printf("table %s\nJ_1(0.7) = %.17g, closed form %.17g\n", path.c_str(), value, expected);
  if (!(std::fabs(value - expected) <= 1e-12 * expected)) return 1;
  try {
    table.curve(asperity::Distribution::weibull, asperity::Side::tail, 1000.0);
    return 1;
  } catch (const asperity::Error& error) {
    std::printf("expected error: %s\n", error.what());
  }
  return 0;
}
