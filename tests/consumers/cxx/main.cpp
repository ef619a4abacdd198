// An installed asperity from C++ (find_package): the default table it finds, a value against
// the closed form J_1(s) = (sqrt(pi)/2) erfc(s) for a = 2, an error caught across the library's
// boundary, and a measured surface (the X3P given as argv[1]) read, leveled and its summits
// found through asperity::topography. Prints the table's path for tests/consumers/run.sh to check.
#include <cmath>
#include <cstdio>

#include "asperity/contact.hpp"
#include "asperity/error.hpp"
#include "asperity/table.hpp"
#include "asperity/topography/height_map_io.hpp"
#include "asperity/topography/leveling.hpp"
#include "asperity/topography/summits.hpp"

int main(int argc, char** argv) {
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

  if (argc < 2) return 1;
  namespace topo = asperity::topography;
  topo::HeightMap map = topo::read_height_map(argv[1]);  // X3P: libzip, pugixml, MD5 checked
  topo::subtract_plane(map, topo::fit_plane(map));
  const topo::Summits summits = topo::find_summits(map);
  std::printf("%s: %zu x %zu points, dx %.4g m, %zu summits, radius %.4g m\n", argv[1], map.nx, map.ny, map.dx,
              summits.list.size(), summits.radius);
  // as `asperity surface` finds on the same file (tests/test_topography_cli.cpp)
  if (map.nx != 650 || map.ny != 650 || summits.list.size() != 2482) return 1;
  try {
    topo::read_height_map(std::string(argv[1]) + ".missing");
    return 1;
  } catch (const asperity::Error& error) {
    std::printf("expected error: %s\n", error.what());
  }
  return 0;
}
