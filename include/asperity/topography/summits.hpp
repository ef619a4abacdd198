// Summits of a height map (Greenwood and Williamson's asperities on a sampled surface).
//
// A summit is a point higher than its 8 neighbours (window = 1), or than every point within
// `window` points in x and y (window > 1: a size threshold against small noise peaks). Ties are
// broken in raster order (a point must exceed the neighbours before it and equal or exceed
// those after it), so a flat top of equal heights counts once. Points whose window touches a
// missing point or the edge are not candidates. An optional height threshold `min_drop` keeps
// only summits standing at least that much above the mean of their 8 neighbours (against
// instrument noise).
//
// Curvatures from the 3 x 3 stencil at the summit: h_xx = (h[i+1] - 2h + h[i-1]) / dx^2,
// h_yy likewise, h_xy = (h[i+1,j+1] - h[i+1,j-1] - h[i-1,j+1] + h[i-1,j-1]) / (4 dx dy).
// Principal curvatures kappa1 >= kappa2 are the eigenvalues of -Hessian; the mean curvature is
// kappa_m = -(h_xx + h_yy)/2 (half the discrete Laplacian). The GW summit radius is
// R = 1 / <kappa_m> over the summits (mean curvature averaged, then inverted).
//
// Sampling-interval dependence: on a rough (self-affine) surface a finer sampling finds more
// and sharper summits: the density grows and R falls as dx shrinks. `decimated` resamples
// the map at k dx so the dependence can be measured and stated.
#pragma once
#include <cstddef>
#include <vector>

#include "asperity/record_fields.hpp"
#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

struct SummitOptions {
  int window = 1;        // half-width of the neighbourhood in points (1: the 8 neighbours)
  double min_drop = 0;   // [m] summit height minus the mean of its 8 neighbours, at least
};

struct Summit {
  std::size_t i = 0, j = 0;
  double height = 0;            // [m]
  double mean_curvature = 0;    // kappa_m [1/m]
  double kappa1 = 0, kappa2 = 0;  // principal curvatures [1/m], kappa1 >= kappa2
};

// Over the summits found (report.json's summits, after its count and how they were found); the
// fields defined once (record_fields.hpp)
#define ASPERITY_SUMMITS_FIELDS(X)                                                             \
  X(std::size_t, rejected_by_drop, "rejected_by_drop", "maxima less than min_drop above their neighbours") \
  X(std::size_t, candidates, "candidates", "points whose whole window is valid")             \
  X(double, area_searched, "area_searched_m2", "candidates dx dy [m^2]")                     \
  X(double, density, "density_per_m2", "summits per unit area [1/m^2]")                      \
  X(double, mean_curvature, "mean_curvature_per_m", "<kappa_m> over the summits [1/m]")      \
  X(double, radius, "radius_m", "R = 1 / <kappa_m> [m]")                                     \
  X(SummitOptions, options, nullptr, "how the summits were found")                          \
  X(double, dx, nullptr, "the map's sampling interval along x [m]")                         \
  X(double, dy, nullptr, "the map's sampling interval along y [m]")

struct Summits {
  std::vector<Summit> list;  // every summit (Python: arrays of each field)
  ASPERITY_SUMMITS_FIELDS(ASPERITY_RECORD_MEMBER_INIT)
};

// Throws asperity::Error for a window < 1 or a negative/NaN min_drop.
Summits find_summits(const HeightMap& map, const SummitOptions& options = {});

// Every factor-th point in x and y (sampling interval factor dx, factor dy).
HeightMap decimated(const HeightMap& map, std::size_t factor);

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::Summits, ASPERITY_SUMMITS_FIELDS)
}  // namespace asperity
