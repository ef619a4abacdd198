// The exact elastic contact of a height map (docs/exact-contact.md): the frictionless normal
// contact of a linear-elastic half-space (contact modulus E*) with a rigid flat, the map being
// the gap between them before loading, by the boundary-element method on FFTs (Stanley and Kato
// 1997) solved by the constrained conjugate gradient of Polonsky and Keer (1999), preconditioned
// and started from the solution on a coarsened map unless asked otherwise (ContactSolver). It
// neglects nothing a Greenwood-Williamson model neglects (coalescence, interaction, the bulk): it
// is the reference the asperity models of the same map are judged against.
//
// Elastic-perfectly-plastic (ExactContactOptions::hardness > 0): the same half-space with the
// contact pressure capped at the hardness H on every pixel, 0 <= p <= H (the saturation model of
// Almqvist et al. 2007, tamaas' "saturated" solvers): a point at p = H is plastic, its gap may be
// negative (the plastic interference, flattened to the flat: its gap counts 0 in the mean gap)
// and it carries no incremental load. It neglects hardening, the plastic zone below the surface
// and its interaction with the elastic field, and unloading (the flattening is not kept).
//
// Adhesive (ExactContactOptions::work_of_adhesion > 0): the Maugis-Dugdale cohesive zone on every
// pixel: a tension sigma0 (adhesive_stress) wherever the gap is at most the range
// h0 = work_of_adhesion / sigma0, in contact or not, besides the contact pressure p >= 0 where the
// gap is 0. Solved at given positions of the flat (at_approach; at_mean_gap on a periodic map
// without missing points), each step from the last step's contact and cohesive zone, so that
// loading and unloading follow their own branches (jump-in, pull-off). Not with a hardness.
//
// Assumptions: small slopes (half-space theory), frictionless, linear elastic; the
// map is sampled on its grid, the pressure constant over each pixel (love) or band-limited
// (fourier); missing points (NaN) never touch and are left out of the mean gap.
//
// Boundary: `periodic` repeats the map (a measured map's opposite edges differ: the periodic
// solve sees a step there); `padded` places the map in a grid twice as long each way whose other
// three quarters carry no pressure (non-periodic by zero padding). Kernel: `fourier` is the
// point-force Fourier kernel 2/(E* |q|) on the solve grid; `love` is the pixel-constant
// influence coefficients (Love 1929: uniform pressure over each pixel, displacement at the pixel
// centres): periodic by its exact alias sum in Fourier space, padded by the real-space
// coefficients on the doubled grid, which makes the padded Love solve exactly non-periodic (no
// images). The padded Fourier solve keeps images two map lengths apart.
//
// Datum: the separation of the flat is the mean gap u = <gap> over the map's valid points, the
// gap measured between the flat and the deformed surface; for a periodic map without missing
// points it is the distance of the flat from the mean plane of the map (the displacements have
// zero mean). `separation_from_mean_summit` is the same separation less the mean summit height
// (summits.hpp, 8 neighbours) above the mean plane: the datum of the GW curves
// (contact_model.hpp's mean_separation). Heights are taken about their mean (the mean plane).
//
// Convergence: a solve stops when the pressure-weighted mean |gap| over the contact points is
// at most `tolerance` times the rms height and no point outside the contact penetrates the flat
// by more than that; it never returns an unconverged answer: after max_iterations it throws
// asperity::Error naming the iterations and the residual reached. Memory: a few arrays the size
// of the solve grid (O(N); exact_contact_memory), and a seventh more for the coarsened maps of the
// coarse start (their solutions; their work arrays only while they solve); each
// iteration costs two convolutions (O(N log N)) and a few passes over the points (O(N)).
#pragma once
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "asperity/record_fields.hpp"
#include "asperity/topography/height_map.hpp"

namespace asperity::topography {

enum class ContactBoundary { periodic, padded };
enum class ContactKernel { fourier, love };
// `preconditioned`: the conjugate gradient on the contact set preconditioned by the 3 x 3 stencil
// of the inverse Green's function (the elastic stiffness of a pixel and its neighbours), its
// conjugation kept while the contact set grows by at most 1% an iteration; a solve that stops
// improving continues as `polonsky_keer`. `polonsky_keer`: the algorithm as published, no
// preconditioner, steepest descent again whenever the contact set grows.
enum class ContactSolver { preconditioned, polonsky_keer };

bool parse_contact_boundary(const std::string& name, ContactBoundary& boundary);
bool parse_contact_kernel(const std::string& name, ContactKernel& kernel);
bool parse_contact_solver(const std::string& name, ContactSolver& solver);
const char* contact_boundary_name(ContactBoundary boundary);
const char* contact_kernel_name(ContactKernel kernel);
const char* contact_solver_name(ContactSolver solver);

// What a long solve reports now and then (every iteration; the caller throttles).
struct ContactProgress {
  const char* stage = "";       // "pressure", "gap", "stiffness"; "coarse pressure", "coarse gap"
  int iteration = 0;
  double residual = 0;          // the stopping residual (relative; see above)
  std::size_t contact_points = 0;
};

// Limits, checked before anything is allocated: the solve grid (the map's, or four times it
// padded) of at most max_contact_points points.
inline constexpr std::size_t max_contact_points = std::size_t{1} << 26;
inline constexpr double min_contact_tolerance = 1e-14, max_contact_tolerance = 1e-2;
// The coarse start: the smallest coarsened map (points each way), and the coarser solves' tolerance.
inline constexpr std::size_t coarse_start_points = 64;
inline constexpr double coarse_start_tolerance = 1e-4;

struct ExactContactOptions {
  double contact_modulus = 0;  // E* [Pa]; required
  ContactBoundary boundary = ContactBoundary::periodic;
  ContactKernel kernel = ContactKernel::fourier;
  double tolerance = 1e-8;     // relative residual (see above)
  int max_iterations = 20000;  // per solve (each constrained CG and each stiffness CG)
  int love_aliases = 16;       // periodic Love kernel: aliases summed each way (|m|, |n| <= this)
  ContactSolver solver = ContactSolver::preconditioned;
  // Start each step from the solution on the map coarsened 2 x 2 (itself started so, down to
  // coarse_start_points points each way), the coarser solves to coarse_start_tolerance (or the
  // tolerance, if larger); otherwise (or when a map is too small) from the last step's solution.
  bool coarse_start = true;
  bool stiffness = true;       // solve the incremental problem at every step
  int threads = 0;             // that share each FFT (0: every core; 1 to 1024)
  std::function<void(const ContactProgress&)> progress;  // may be empty
  // Bytes the solver may allocate (exact_contact_memory below); 0: no limit. A map whose
  // estimate exceeds it is refused before anything is allocated.
  std::size_t max_memory = 0;
  // The hardness H [Pa]: the pressure no pixel exceeds (elastic-perfectly-plastic, above);
  // 0 or +inf: elastic (the default; its answers unchanged).
  double hardness = 0;
  // Adhesion (Maugis-Dugdale, above): the work of adhesion [J/m^2] and the Dugdale stress sigma0
  // [Pa], both positive or both 0 (no adhesion, the default; its answers unchanged). The range
  // h0 = work_of_adhesion / adhesive_stress must be resolved by the grid: the cohesive zone's width
  // (on a sphere about 0.75 a_s / lambda^2 at large Maugis parameter lambda) a few pixels at least
  // (docs/exact-contact.md, "Adhesive contact").
  double work_of_adhesion = 0;
  double adhesive_stress = 0;
};

// True when the options ask for the capped pressure (a finite hardness > 0).
inline bool is_plastic(const ExactContactOptions& options) {
  return options.hardness > 0 && options.hardness < HUGE_VAL;
}

// True when the options ask for adhesion (a work of adhesion > 0).
inline bool is_adhesive(const ExactContactOptions& options) { return options.work_of_adhesion > 0; }

// What one solver of an nx x ny map needs at most [bytes], counted from its arrays: on the solve
// grid (the map's, or four times it padded) the heights, the pressure, the displacement and a mask
// (25 bytes a point), the kernel's even half (4), and while a step solves its work arrays (the
// direction, the gap, the direction's convolution, the stiffness increment: 32) and the complex
// spectrum of half the grid (8): about 69 bytes a point; each coarse start level keeps its 29
// bytes a point (about 10 over all levels, a third of the map's points), its work arrays released
// between its solves (and the finer level's while it solves); on the map's grid a step's contact
// mask and clusters' labels (5 bytes a point). The largest of that, the constructor's (the padded
// Love kernel's coefficients, 8 bytes a point more while they are made) and the summit search's.
// Throws nothing; saturates at SIZE_MAX.
std::size_t exact_contact_memory(std::size_t nx, std::size_t ny, const ExactContactOptions& options);

// Memory as text for messages: "1.2 GB", "340 MB", "12 kB", "512 bytes" (SI prefixes).
std::string memory_text(std::size_t bytes);

// The memory this process may still take [bytes]: the smallest of MemAvailable in
// /proc/meminfo (else sysconf's available pages), the address-space and data limits
// (RLIMIT_AS, RLIMIT_DATA) less what is mapped, and a cgroup v2 memory.max less memory.current.
// 0 when none of them can be read.
std::size_t available_memory();

// A memory size as the commands take it: a whole or decimal number with an optional unit, k K M
// G T (powers of 1000) or KiB MiB GiB TiB (powers of 1024), B or nothing for bytes: "1M",
// "512MiB", "2.5G", "1000000". False for anything else (or a size beyond SIZE_MAX, or 0).
bool parse_memory_size(const std::string& text, std::size_t& bytes);

// A command's --max-memory: the size `text` gives (parse_memory_size), or when it is empty the
// memory available now (available_memory(); 0, no limit, when nothing can be read). Throws
// asperity::Error naming `option` for a text that is not a size.
std::size_t memory_limit_option(const std::string& text, const std::string& option);

// The --max-memory option's help: one text for asperity exact-contact and asperity surface.
inline constexpr const char* max_memory_help =
    "refuse a map whose analysis is estimated to need more memory than this, before allocating it: a size with "
    "its unit, 1M 500MB 2G (powers of 1000) or 512MiB 4GiB (powers of 1024) (default: the memory available now, "
    "MemAvailable in /proc/meminfo, less under a ulimit -v or -d or a cgroup memory.max)";

// One load step. Pressures are nominal: load over the map's area nx dx ny dy. Its fields, defined
// once (a record's list, record_fields.hpp), in the order of exact-contact's CSV columns and JSON
// (exact_contact_report.hpp writes both from it); coarse_iterations is not written.
#define ASPERITY_CONTACT_STEP_FIELDS(X)                                                                        \
  X(double, pressure, "pressure_Pa", "mean nominal pressure [Pa]")                                             \
  X(double, load, "load_N", "[N] on the map's area")                                                           \
  X(double, mean_gap, "mean_gap_m", "separation of the flat from the mean plane [m]")                          \
  X(double, separation_from_mean_summit, "separation_from_mean_summit_m", "mean_gap less the mean summit height [m]") \
  X(double, approach, "approach_m", "the flat's position above the mean plane, rigid-body [m]")                \
  X(double, area_fraction, "area_fraction", "contact points / map points")                                     \
  X(double, real_area, "real_area_m2", "[m^2]")                                                                \
  X(std::size_t, contact_points, "contact_points", "map points in contact")                                    \
  X(std::size_t, clusters, "clusters", "connected contact patches (4-neighbour; wrapped when periodic)")       \
  X(double, plastic_area_fraction, "plastic_area_fraction", "plastic points (p = hardness) / map points; 0 elastic") \
  X(std::size_t, plastic_points, "plastic_points", "map points at the hardness")                              \
  X(double, adhesive_pressure, "adhesive_pressure_Pa",                                                         \
    "the cohesive zone's tension over the map's area [Pa] (pressure includes it, less); 0 without adhesion")    \
  X(std::size_t, adhesive_points, "adhesive_points",                                                           \
    "map points under the adhesive stress: gap at most its range, in contact or not; 0 without adhesion")       \
  X(double, stiffness, "stiffness_N_per_m", "-dP/d(mean gap) [N/m], 0 without contact")                        \
  X(double, stiffness_per_area, "stiffness_per_area_N_per_m3", "-dp/d(mean gap) [N/m^3]")                      \
  X(double, approach_stiffness, "approach_stiffness_N_per_m",                                                  \
    "-dP/d(approach) [N/m] (equal to stiffness when periodic, without missing points); +inf for both in full contact") \
  X(double, max_pressure, "max_pressure_Pa", "[Pa]")                                                           \
  X(int, iterations, "iterations", "constrained CG iterations (all solves of a gap-driven step)")              \
  X(int, coarse_iterations, nullptr, "those of the coarse start, all coarser levels summed")                   \
  X(int, solves, "solves", "constrained solves (1 when driven by pressure)")                                   \
  X(double, residual, "residual", "reached (<= tolerance)")                                                    \
  X(int, stiffness_iterations, "stiffness_iterations", "CG iterations of the incremental problem")             \
  X(double, stiffness_residual, "stiffness_residual", "its relative residual")

struct ContactStep {
  ASPERITY_CONTACT_STEP_FIELDS(ASPERITY_RECORD_MEMBER_ZERO)
};

// The pressures a solver answers (ExactContact::pressure_range), found before any iteration.
struct ContactPressureRange {
  // Below it the whole load on the highest point deflects that point by less than the solve
  // resolves (tolerance times the rms height): the contact is less than one node, the answer
  // the undeformed map resting on its highest point. Refused below it.
  double one_node = 0;
  // Periodic maps without missing points: the nominal pressure of full contact, from one FFT:
  // flattened, the map carries p(x) = p0 + K[h](x), K the solver's own inverse kernel (1/G, the
  // mean left out), so the whole map touches when p0 > max(-K[h]). Above it the step is
  // answered in closed form (no iteration). +inf otherwise (padded, or missing points: no
  // closed form; such a map's full contact is iterated).
  double full_contact = 0;
  // Above it the displacements' rounding (2^-52 of the largest compliance times the pressure,
  // times 8 for the transforms' and iterations' accumulation) reaches the tolerance: the solve
  // cannot converge. Refused above it (unless answered in closed form as full contact). A
  // lower bound of the hopeless: solves within about 30 times below it may still not converge
  // (docs/exact-contact.md), none above it does.
  double numerical_limit = 0;
  // With a hardness H: the mean pressure of the whole map plastic, H times the valid points'
  // share of the map; refused at or above it (no load beyond it can be carried). +inf elastic.
  double plastic_limit = 0;
};

class ExactContact {
 public:
  // Throws asperity::Error for a bad map (HeightMap::validate), a modulus not finite and > 0, a
  // tolerance outside [min_contact_tolerance, max_contact_tolerance], max_iterations < 1,
  // love_aliases outside [1, 1000], a hardness negative or NaN, a solve grid beyond max_contact_points, a map whose valid
  // heights are all equal, or a memory estimate beyond options.max_memory (the figure named);
  // running out of memory (std::bad_alloc) is an asperity::Error naming the map and the estimate.
  ExactContact(const HeightMap& map, const ExactContactOptions& options);

  // The contact at a mean nominal pressure [Pa] > 0 (0: no contact), from the last solution
  // (a warm start). Above pressure_range().full_contact the closed form (every point in contact,
  // infinite stiffness, no iteration). Throws asperity::Error for a pressure not finite and >= 0,
  // one below pressure_range().one_node, above its numerical_limit or at or above its
  // plastic_limit (the bound and what to do named, before any iteration), no convergence, or no
  // memory. With a hardness the closed form of full contact is used only where it stays below it.
  ContactStep at_pressure(double pressure);
  // The checks at_pressure makes before iterating: throws its asperity::Error for a pressure it
  // would refuse (so that a sweep is checked before its first solve); nothing else.
  void check_pressure(double pressure) const;
  const ContactPressureRange& pressure_range() const noexcept { return range_; }
  // exact_contact_memory of this solver's map and options [bytes].
  std::size_t memory_estimate() const noexcept { return memory_; }
  // The contact at a mean gap [m] > 0 (the separation from the mean plane; at or above the
  // highest point: no contact), from the last solution. Throws asperity::Error for a gap not
  // finite and > 0, or no convergence.
  ContactStep at_mean_gap(double mean_gap);
  // The contact with the flat at `approach` [m] above the mean plane (the rigid-body position:
  // ContactStep::approach; for a padded Love solve from the far field), from the last solution.
  // With adhesion, the cohesive zone and the contact are continued from the last step's (loading
  // and unloading follow their branches). Throws asperity::Error for a position not finite, or no
  // convergence.
  ContactStep at_approach(double approach);

  std::size_t nx() const noexcept { return nx_; }
  std::size_t ny() const noexcept { return ny_; }
  double rms_height() const noexcept { return rms_; }
  double max_height() const noexcept { return max_height_; }   // above the mean plane [m]
  double mean_summit_height() const noexcept { return mean_summit_; }  // above the mean plane [m]
  std::size_t summits() const noexcept { return summits_; }
  double nominal_area() const noexcept { return nominal_area_; }
  const ExactContactOptions& options() const noexcept { return options_; }

  // The last solution on the map's grid (row j at j * nx, x fastest): pressure [Pa] (0 off
  // contact and at missing points) and gap [m] (0 in contact, NaN at missing points).
  std::vector<double> pressure_field() const;
  std::vector<double> gap_field() const;

 private:
  // out = G in on the solve grid; `in` is zero outside the map (a padded grid's other three
  // quarters), and `out` is written on the map's rows only.
  void apply(const std::vector<double>& in, std::vector<double>& out);
  // M in on the contact set, M the preconditioner's stencil; `in` is zero off the contact set.
  // Returns the sums over the contact set of M in, M in * other and other. (M in is not stored:
  // over_stencil gives it to each pass that needs it.)
  struct Sums3 {
    double out = 0, out_other = 0, other = 0;
  };
  Sums3 precondition(const std::vector<double>& in, const std::vector<double>& other);
  template <class Visit, class Skip>
  void over_stencil(const std::vector<double>& in, std::size_t first, std::size_t end, Visit&& visit, Skip&& skip) const;
  struct Solve {
    int iterations = 0;
    double residual = 0, approach = 0;
    bool stalled = false;  // capped, by pressure: stopped improving (plastic_pressure_search takes over)
  };
  Solve constrained(bool by_pressure, double target);
  // constrained's parts (exact_contact.cpp): its start, and its passes over the map's points,
  // each returning its sums (PassSums: [0..4] added, [5] the largest)
  using PassSums = std::array<double, 6>;
  void seed_pressure(bool by_pressure, double target, double total);
  void pressure_from_overlap(double target);
  PassSums scale_and_sum_contact_gaps(double scale);
  PassSums gaps_and_residual_sums(double approach, bool preconditioned);
  void set_direction(bool preconditioned, double source_mean, bool conjugate, double beta);
  // With a hardness: the pressures scaled to the load `total`, each capped at it (the scale
  // solved for, the plastic points held while the free ones can carry the rest); the flat's
  // position when no point is free (the highest that keeps every plastic point's gap <= 0).
  void rescale_capped(double total);
  double plastic_approach() const;
  PassSums step_products();
  PassSums move_pressure(double step, double overlap_step);
  void stiffness_of(ContactStep& step);
  ContactStep describe(const Solve& solve);
  void report(const char* stage, int iteration, double residual, std::size_t contact) const;
  void start_from_coarse();  // the pressure prolonged from coarse_'s last solution
  void find_pressure_range();  // range_, from the kernel and the heights
  void stiffness_times_heights(std::vector<double>& out);  // K[h] on the solve grid (periodic)
  ContactStep full_contact(double pressure);  // the closed form above range_.full_contact
  // Whether `pressure` is answered by full_contact: above range_.full_contact, and with a
  // hardness, the flattened map's peak pressure at most the hardness.
  bool closed_form_full_contact(double pressure) const noexcept {
    return pressure > range_.full_contact && pressure + flattening_peak_ <= hardness_;
  }
  ContactStep solve_pressure(double pressure);
  // With a hardness, by pressure when the load's rescaling stalls: the flat's position whose
  // capped solve carries the load, by Newton's steps on the incremental stiffness (the tangent of
  // load against position) kept within the bracket found; from `approach`.
  ContactStep plastic_pressure_search(double pressure, double approach, int iterations);
  ContactStep solve_mean_gap(double mean_gap);
  // With adhesion (exact_contact_adhesion.cpp): the flat at `approach`, the cohesive zone found by
  // fixed-point passes (each a contact solve of the heights less the zone's displacement).
  ContactStep solve_adhesive(double approach);
  void set_adhesive_heights();  // heights_ = base_heights_ + G[sigma0 on the cohesive zone]
  [[noreturn]] void refuse_pressure_with_adhesion(double pressure) const;
  [[noreturn]] void out_of_memory(const std::string& doing) const;
  // the constructor's parts (exact_contact.cpp)
  void allocate_solve_grid(const HeightMap& map, double mean);
  void make_padded_love_kernel(double modulus);
  void make_spectral_kernel(double modulus);  // Fourier, or periodic Love
  void make_preconditioner_stencil();
  void ensure_scratch();   // the work arrays, made again if released
  void release_scratch();  // the work arrays returned to the system (a coarse level between solves)
  std::size_t kernel_row(std::size_t ky) const noexcept { return ky <= sy_ / 2 ? ky : sy_ - ky; }  // kernel_ is even in q_y

  ExactContactOptions options_;
  std::size_t nx_ = 0, ny_ = 0, sx_ = 0, sy_ = 0;  // map grid; solve grid
  double dx_ = 0, dy_ = 0, rms_ = 0, max_height_ = 0, mean_summit_ = 0, nominal_area_ = 0, self_compliance_ = 0;
  std::size_t summits_ = 0, valid_points_ = 0;
  int threads_ = 1, loop_threads_ = 1;  // the FFTs'; the passes over the points'
  std::vector<double> kernel_;       // the real spectrum of G, rows 0 to sy/2 ((sy/2 + 1) x (sx/2 + 1)): even in q_y
  std::vector<unsigned char> active_;  // on the solve grid: may carry pressure (a valid map point)
  std::vector<double> heights_;      // on the solve grid, about the mean plane (0 where inactive)
  std::vector<double> pressure_, displacement_;  // solve grid: the solution
  // solve grid: the solves' work arrays (scratch: a coarse level's are released between its
  // solves, and this map's while its coarse level solves; ensure_scratch makes them again)
  std::vector<double> direction_, work_, increment_, stiffness_x_;
  std::vector<std::complex<double>> spectrum_;  // sy x (sx/2 + 1)
  std::vector<double> partial_sums_;  // per block of rows, for the passes' sums
  std::vector<double> zero_row_;      // sx zeros: the padding's rows, for the preconditioner
  // The preconditioner: the inverse Green's function's real-space coefficients at offsets
  // (0, 0), (1, 0), (0, 1), (1, 1) pixels; none (the identity) when they are not positive definite.
  double stencil_centre_ = 0, stencil_x_ = 0, stencil_y_ = 0, stencil_diagonal_ = 0;
  bool stencil_ = false;
  double approach_ = 0;              // the last solution's rigid-body position
  ContactPressureRange range_;
  double hardness_ = HUGE_VAL;       // the cap on the pressure (+inf elastic)
  bool plastic_ = false;             // a finite hardness
  bool adhesive_ = false;            // a work of adhesion (Maugis-Dugdale)
  double adhesive_stress_ = 0, adhesive_range_ = 0;  // sigma0 [Pa], h0 [m]
  std::vector<double> base_heights_;   // adhesive: the map's heights on the solve grid (heights_ less the zone's pull)
  std::vector<unsigned char> cohesive_;  // adhesive: the points under sigma0 (gap <= h0)
  double flattening_peak_ = 0;       // max K[h] (periodic, no missing points): full contact's peak less its mean
  double largest_compliance_ = 0;    // of the kernel [m/Pa]: the displacements' scale
  std::size_t memory_ = 0;           // exact_contact_memory of the map and options
  std::unique_ptr<ExactContact> coarse_;  // the map coarsened 2 x 2, for the coarse start
  bool coarse_level_ = false;        // this solver is another's coarse start (no stiffness solves)
};

// Connected contact patches of a contact mask (nx x ny, x fastest; nonzero: in contact), by
// 4-neighbour connectivity, wrapped across opposite edges when `periodic`.
std::size_t count_clusters(const std::vector<unsigned char>& contact, std::size_t nx, std::size_t ny, bool periodic);

}  // namespace asperity::topography

namespace asperity {
ASPERITY_DEFINE_RECORD(topography::ContactStep, ASPERITY_CONTACT_STEP_FIELDS)
}  // namespace asperity
