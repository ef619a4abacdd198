// The runtime alone, from an installed tree: the default table found beside the library, a
// value against its closed form (Weibull a = 1, tail: X_0(s) = exp(-s) for s >= 0), the
// contact model in SI units and its FE card. Prints the table it used (checked by the script).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "asperity/contact_model.hpp"
#include "asperity/pressure_overclosure.hpp"
#include "asperity/table.hpp"

int main() {
  const std::string path = asperity::Table::default_search_paths().front();
  const asperity::Table table = asperity::Table::open_default();
  const asperity::Curve curve = table.curve(asperity::Distribution::weibull, asperity::Side::tail, 1.0);
  const double value = curve.value(asperity::orders::count, 0.75), exact = std::exp(-0.75);
  if (!(std::fabs(value - exact) <= 1e-12 * exact)) {
    std::printf("X_0(0.75) = %.17g, expected %.17g\n", value, exact);
    return 1;
  }
  asperity::RoughSurface surface;  // the README's quick start: a Weibull tail of shape 2
  surface.shape = 2;
  surface.height_scale = 1e-6;
  surface.summit_radius = 1e-4;
  surface.summit_density = 1e10;
  surface.nominal_area = 1e-4;
  surface.contact_modulus = asperity::contact_modulus_from(2.1e11, 0.3, 2.1e11, 0.3);
  const asperity::ContactModel model(table, surface);
  const asperity::PhysicalState state = model.at_load(1.0);
  std::ostringstream card;
  asperity::write_pressure_overclosure(card, asperity::tabulate_pressure_overclosure(model, 1e3, 1e8, 1e-3),
                                       asperity::CardFormat::calculix, asperity::CardUnits::si, "runtime only");
  if (!(state.load == 1.0 || std::fabs(state.load - 1.0) < 1e-9) || card.str().find("PRESSURE-OVERCLOSURE") == std::string::npos) {
    std::printf("the model or its card is wrong\n");
    return 1;
  }
  std::printf("X_0(0.75) = %.17g (closed form %.17g); at 1 N: separation %.6g m, card %zu bytes\ntable %s\n", value,
              exact, state.separation, card.str().size(), path.c_str());
  return 0;
}
