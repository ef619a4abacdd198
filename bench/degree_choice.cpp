// The interpolation degree against table size: for the curves of docs/scenes.md's scene, how many
// intervals (inside each curve's range) quintic and cubic Hermite need to reproduce a fine
// layout's knots to half the tolerance, the same test tablegen --scene thins by, and the
// power-basis coefficients that costs in memory (6 per interval for the quintic, 4 for the cubic).
//   build/bench/degree_choice
#include "asperity/generator/chain_ode.hpp"
#include "asperity/layout.hpp"
#include "asperity/detail/segment_map.hpp"
#include "asperity/detail/quintic_hermite.hpp"
#include <cstdio>
#include <cmath>
#include <vector>
#include <algorithm>
using namespace asperity;
// The cubic Hermite interpolant on [0, 1] from {f, h f'} at both ends.
double cubic(const double* l, const double* r, double x) {
  double f0=l[0], g0=l[1], f1=r[0], g1=r[1];
  double c2 = 3*(f1-f0) - 2*g0 - g1, c3 = 2*(f0-f1) + g0 + g1;
  return f0 + x*(g0 + x*(c2 + x*c3));
}
int main() {
  struct C { Distribution d; Side side; double a; std::vector<int> orders; double lo, hi; const char* name; };
  std::vector<C> cs = {{Distribution::weibull, Side::bounded, 1.73, {1,3}, -0.5, -1e-4, "worn"},
                       {Distribution::gaussian, Side::tail, 2.0, {4,5}, -3, 4, "lubrication"},
                       {Distribution::weibull, Side::tail, 2.7, {0,2,3}, 0.9, 2.6, "ground"}};
  for (auto& c : cs) {
    auto layout = scale_knot_density(default_layout(c.d, c.side), 2);
    auto data = generator::integrate_curve({c.d, c.side, c.a}, layout, {});
    auto maps = detail::SegmentMap::resolve(layout, c.d, c.side, c.a);
    int total = 0; for (auto& l : layout) total += l.knots;
    for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
      int iq = 0, ic = 0; int first = 0;
      for (size_t sgi = 0; sgi < layout.size(); ++sgi) {
        int knots = layout[sgi].knots, intervals = knots - 1;
        double fine = (maps[sgi].u_hi - maps[sgi].u_lo) / intervals;
        auto s_at = [&](int j){ double s, a, b; maps[sgi].s_of_u(maps[sgi].u_lo + fine*j, s, a, b); return s; };
        for (int degree : {5, 3}) {
          int best = 1; 
          for (int f = 1; intervals % f == 0 && intervals / f >= 2; f *= 2) {
            double worst = 0;
            for (int o : c.orders) { const double* d = &data[((size_t)o*total + first)*3];
              for (int st = 0; st + f <= intervals; st += f) {
                double sa = s_at(st), sb = s_at(st+f); if (std::max(sa,sb) < c.lo || std::min(sa,sb) > c.hi) continue;
                double h = fine*f; double L[3] = {d[st*3], d[st*3+1]*h, d[st*3+2]*h*h}, R[3] = {d[(st+f)*3], d[(st+f)*3+1]*h, d[(st+f)*3+2]*h*h};
                for (int m = 1; m < f; ++m) { double s = s_at(st+m); if (s < c.lo || s > c.hi) continue;
                  double v = degree == 5 ? detail::quintic_hermite(L, R, double(m)/f) : cubic(L, R, double(m)/f);
                  worst = std::max(worst, std::fabs(v - d[(st+m)*3])); } } }
            if (worst <= 0.5*tol) best = f; else break;
          }
          // count intervals inside the range only
          int in = 0; for (int st = 0; st + best <= intervals; st += best) { double sa = s_at(st), sb = s_at(st+best); if (!(std::max(sa,sb) < c.lo || std::min(sa,sb) > c.hi)) ++in; }
          (degree == 5 ? iq : ic) += in;
        }
        first += knots;
      }
      std::printf("%-12s tol %.0e: intervals in range quintic %4d (x6 coef = %5d)  cubic %4d (x4 coef = %5d)\n", c.name, tol, iq, iq*6, ic, ic*4);
    }
  }
}
