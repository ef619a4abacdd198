#include "asperity/topography/exact_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <new>
#include <numeric>
#include <sstream>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

#include "asperity/detail/parallel_for.hpp"
#include "asperity/error.hpp"
#include "asperity/number_text.hpp"
#include "asperity/topography/summits.hpp"
#include "statistics/fft.hpp"

namespace asperity::topography {
namespace {

constexpr double pi = 3.14159265358979323846;

std::string number(double value) {
  std::ostringstream text;
  text.precision(6);
  text << value;
  return text.str();
}

// The signed wavenumber [rad/m] of DFT index k on n points of spacing h.
double wavenumber(std::size_t k, std::size_t n, double h) {
  const double signed_k = k <= n / 2 ? static_cast<double>(k) : static_cast<double>(k) - static_cast<double>(n);
  return 2 * pi * signed_k / (static_cast<double>(n) * h);
}

// f(first, count) over [0, total) in `threads` contiguous blocks, on the project's threads
// (detail::parallel_for: a thread the system refuses is no error).
template <class Function>
void in_parallel(int threads, std::size_t total, Function&& f) {
  const std::size_t parts = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), total);
  if (parts <= 1) {
    f(std::size_t{0}, total);
    return;
  }
  asperity::detail::parallel_for(parts, static_cast<int>(parts), [&](std::size_t part) {
    const std::size_t first = part * total / parts;
    f(first, (part + 1) * total / parts - first);
  });
}

// The passes over the map's points run over fixed blocks of rows, on `threads` threads; each
// block's sums are kept apart (`partial`: sums_per_block a block) and added in the blocks' order,
// so that the sums, and the solution, do not depend on the number of threads. pass(first, end,
// sums) covers rows [first, end) and writes sums[0..4] (added) and sums[5] (the largest).
constexpr std::size_t rows_per_block = 8, sums_per_block = 6;

std::size_t row_blocks(std::size_t rows) { return (rows + rows_per_block - 1) / rows_per_block; }

template <class Pass>
std::array<double, sums_per_block> over_rows(std::size_t rows, int threads, std::vector<double>& partial, Pass&& pass) {
  const std::size_t blocks = row_blocks(rows);
  auto run = [&](std::size_t block) {
    double* sums = &partial[block * sums_per_block];
    std::fill(sums, sums + sums_per_block, 0.0);
    pass(block * rows_per_block, std::min(rows, (block + 1) * rows_per_block), sums);
  };
  if (threads <= 1 || blocks == 1) {
    for (std::size_t block = 0; block < blocks; ++block) run(block);
  } else {
    asperity::detail::parallel_for(blocks, threads, run);
  }
  std::array<double, sums_per_block> total{};
  for (std::size_t block = 0; block < blocks; ++block) {
    const double* sums = &partial[block * sums_per_block];
    for (std::size_t k = 0; k + 1 < sums_per_block; ++k) total[k] += sums[k];
    total[sums_per_block - 1] = std::max(total[sums_per_block - 1], sums[sums_per_block - 1]);
  }
  return total;
}

double sinc(double x) { return x == 0 ? 1.0 : std::sin(x) / x; }

// X asinh(Y / |X|) + Y asinh(X / |Y|) = X ln(Y + r) + Y ln(X + r) - X ln|X| - Y ln|Y|: an
// antiderivative of 1/r = 1 / sqrt(X^2 + Y^2) in X and Y (the last two terms are functions of X
// alone and of Y alone, which cancel in the rectangle's double difference), finite at X, Y = 0.
double love_antiderivative(double x, double y) {
  const double a = x == 0 ? 0.0 : x * std::asinh(y / std::fabs(x));
  const double b = y == 0 ? 0.0 : y * std::asinh(x / std::fabs(y));
  return a + b;
}

// The displacement at (x, y) under unit pressure over [-a, a] x [-b, b], times pi E*:
// the integral of 1/r over the rectangle (Love 1929; Johnson 1985, eq. 3.25).
double love_coefficient(double x, double y, double a, double b) {
  return love_antiderivative(x + a, y + b) - love_antiderivative(x - a, y + b) - love_antiderivative(x + a, y - b) +
         love_antiderivative(x - a, y - b);
}

}  // namespace

bool parse_contact_boundary(const std::string& name, ContactBoundary& boundary) {
  if (name == "periodic") boundary = ContactBoundary::periodic;
  else if (name == "padded") boundary = ContactBoundary::padded;
  else return false;
  return true;
}

bool parse_contact_kernel(const std::string& name, ContactKernel& kernel) {
  if (name == "fourier") kernel = ContactKernel::fourier;
  else if (name == "love") kernel = ContactKernel::love;
  else return false;
  return true;
}

const char* contact_boundary_name(ContactBoundary boundary) {
  return boundary == ContactBoundary::periodic ? "periodic" : "padded";
}

const char* contact_kernel_name(ContactKernel kernel) { return kernel == ContactKernel::fourier ? "fourier" : "love"; }

bool parse_contact_solver(const std::string& name, ContactSolver& solver) {
  if (name == "preconditioned") solver = ContactSolver::preconditioned;
  else if (name == "polonsky-keer") solver = ContactSolver::polonsky_keer;
  else return false;
  return true;
}

const char* contact_solver_name(ContactSolver solver) {
  return solver == ContactSolver::preconditioned ? "preconditioned" : "polonsky-keer";
}

namespace {

// One level's arrays [bytes] (in doubles: a size past SIZE_MAX saturates instead of wrapping):
// `kept` from one step to the next (the heights, the pressure, the displacement, the mask, the
// kernel's half), `work` the work arrays (made at each solve; a coarse level's released between its
// solves, a finer level's while the coarser one solves), `setup` what only the constructor adds.
struct LevelMemory {
  double kept = 0, work = 0, setup = 0;
};

LevelMemory level_memory(std::size_t nx, std::size_t ny, const ExactContactOptions& options, bool coarse_level) {
  const double factor = options.boundary == ContactBoundary::padded ? 2 : 1;
  const double sx = factor * static_cast<double>(nx), sy = factor * static_cast<double>(ny);
  const double solve_points = sx * sy, half_points = sy * (std::floor(sx / 2) + 1);
  const double kernel_points = (std::floor(sy / 2) + 1) * (std::floor(sx / 2) + 1);
  LevelMemory level;
  level.kept = solve_points * (3 * sizeof(double) + 1) + kernel_points * sizeof(double);
  // the direction, the gap, the convolution of the direction (and the stiffness increment, but on
  // a coarse level), the complex spectrum on half the grid
  const double work_arrays = !coarse_level || is_plastic(options) ? 4 : 3;
  level.work = solve_points * work_arrays * sizeof(double) + half_points * sizeof(std::complex<double>);
  if (options.kernel == ContactKernel::love && options.boundary == ContactBoundary::padded)
    level.setup = solve_points * sizeof(double);  // the real-space coefficients, while the kernel is made
  return level;
}

}  // namespace

std::size_t exact_contact_memory(std::size_t nx, std::size_t ny, const ExactContactOptions& options) {
  const double map_points = static_cast<double>(nx) * static_cast<double>(ny);
  const double factor = options.boundary == ContactBoundary::padded ? 2 : 1;
  const double sx = factor * static_cast<double>(nx), sy = factor * static_cast<double>(ny);
  const double solve_points = sx * sy;
  LevelMemory fine = level_memory(nx, ny, options, false);
  double bytes = fine.kept;
  if (is_adhesive(options)) bytes += solve_points * (sizeof(double) + 1);  // the map's own heights, the cohesive zone
  // the coarse start's levels: their kept arrays (their work arrays are released while this map solves)
  if (options.coarse_start && !is_adhesive(options) && nx >= 2 * coarse_start_points && ny >= 2 * coarse_start_points) {
    for (std::size_t cx = (nx + 1) / 2, cy = (ny + 1) / 2;; cx = (cx + 1) / 2, cy = (cy + 1) / 2) {
      bytes += level_memory(cx, cy, options, true).kept;
      if (!(cx >= 2 * coarse_start_points && cy >= 2 * coarse_start_points)) break;
    }
  }
  // the transforms' per-thread rows and columns
  const double threads = options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  const double rows = threads * (sx + sy) * sizeof(std::complex<double>);
  // the largest of: a step (the work arrays, and on the map's grid the contact mask and the
  // clusters' 32-bit labels), the constructor's kernel, the summit search before the solve grid
  // (the centred copy, the marks and missing-point counts, at most a summit in four points)
  const double step = bytes + fine.work + rows + map_points * (1 + sizeof(std::uint32_t));
  const double setup = bytes + fine.work + rows + fine.setup;
  const double summits = map_points * (sizeof(double) + 1 + sizeof(std::size_t) + sizeof(Summit) / 4.0);
  const double total = std::max({step, setup, summits});
  const double most = static_cast<double>(std::numeric_limits<std::size_t>::max());
  return total >= most ? std::numeric_limits<std::size_t>::max() : static_cast<std::size_t>(total);
}

std::string memory_text(std::size_t bytes) {
  if (bytes < 1000) return std::to_string(bytes) + " bytes";
  const char* units[] = {"kB", "MB", "GB", "TB", "PB", "EB"};
  double value = static_cast<double>(bytes) / 1000;
  int unit = 0;
  while (value >= 999.5 && unit < 5) {
    value /= 1000;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %s", value, units[unit]);
  return text;
}

namespace {

// The first number after `key` in a text file of "key value" lines (/proc's), or -1.
double number_after(const char* path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, key.size(), key) == 0) {
      double value = 0;
      std::istringstream rest(line.substr(key.size()));
      if (rest >> value) return value;
    }
  return -1;
}

// A cgroup v2 file of this process's group: its number, or -1 ("max", absent, unreadable).
double cgroup_number(const std::string& name) {
  std::ifstream groups("/proc/self/cgroup");
  std::string line;
  while (std::getline(groups, line))
    if (line.compare(0, 3, "0::") == 0) {
      std::ifstream in("/sys/fs/cgroup" + line.substr(3) + "/" + name);
      double value = 0;
      if (in >> value) return value;
    }
  return -1;
}

}  // namespace

std::size_t available_memory() {
  double least = INFINITY;
  const auto take = [&least](double bytes) {
    if (bytes >= 0) least = std::min(least, bytes);
  };
  const double available_kb = number_after("/proc/meminfo", "MemAvailable:");
  if (available_kb >= 0) {
    take(available_kb * 1024);
  } else {
    const long pages = ::sysconf(_SC_AVPHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0) take(static_cast<double>(pages) * static_cast<double>(page));
  }
  // an address-space or data limit (ulimit -v, -d) less what this process has mapped already
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    take(static_cast<double>(limit.rlim_cur) - 1024 * std::max(0.0, number_after("/proc/self/status", "VmSize:")));
  if (::getrlimit(RLIMIT_DATA, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    take(static_cast<double>(limit.rlim_cur) - 1024 * std::max(0.0, number_after("/proc/self/status", "VmData:")));
  const double group_limit = cgroup_number("memory.max");
  if (group_limit >= 0) take(group_limit - std::max(0.0, cgroup_number("memory.current")));
  if (!std::isfinite(least)) return 0;
  return static_cast<std::size_t>(std::max(least, 0.0));
}

std::size_t memory_limit_option(const std::string& text, const std::string& option) {
  if (text.empty()) return available_memory();
  std::size_t bytes = 0;
  if (!parse_memory_size(text, bytes))
    throw Error(option + ": '" + quote_text(text) + "' is not a memory size (a positive number with an optional unit: "
                "1000000, 500k, 1M, 2.5G, 512MiB, 4GiB)");
  return bytes;
}

bool parse_memory_size(const std::string& text, std::size_t& bytes) {
  double value = 0;
  const std::size_t used = read_double_prefix(text, value);
  if (used == 0 || !(value > 0) || !std::isfinite(value)) return false;
  const std::string unit = text.substr(used);
  static const struct {
    const char* name;
    double factor;
  } units[] = {{"", 1},      {"B", 1},       {"k", 1e3},     {"K", 1e3},     {"kB", 1e3},           {"KB", 1e3},
               {"M", 1e6},   {"MB", 1e6},    {"G", 1e9},     {"GB", 1e9},    {"T", 1e12},           {"TB", 1e12},
               {"KiB", 1024.0}, {"MiB", 1048576.0}, {"GiB", 1073741824.0}, {"TiB", 1099511627776.0}};
  for (const auto& u : units)
    if (unit == u.name) {
      const double total = std::round(value * u.factor);
      if (!(total >= 1 && total < static_cast<double>(std::numeric_limits<std::size_t>::max()))) return false;
      bytes = static_cast<std::size_t>(total);
      return true;
    }
  return false;
}

namespace {

// "FILE (NX x NY points, padded to a 2NX x 2NY solve grid)": the map in messages.
std::string map_in_words(const std::string& source, std::size_t nx, std::size_t ny, ContactBoundary boundary) {
  std::string text = "'" + quote_text(source, 4096) + "' (" + std::to_string(nx) + " x " + std::to_string(ny) + " points";
  if (boundary == ContactBoundary::padded)
    text += ", padded to a " + std::to_string(2 * nx) + " x " + std::to_string(2 * ny) + " solve grid";
  return text + ")";
}

std::string smaller_map_advice(ContactBoundary boundary) {
  return std::string("crop or decimate the map (half the points each way needs a quarter of the memory)") +
         (boundary == ContactBoundary::padded ? ", or solve it with the periodic boundary (a quarter of the padded grid)"
                                              : "");
}

// The constructor's checks of its options, in their order: the first that fails is thrown.
void check_contact_options(const ExactContactOptions& options) {
  const double modulus = options.contact_modulus;
  if (!(std::isfinite(modulus) && modulus > 0)) throw Error("the contact modulus must be finite and positive");
  if (!(options.tolerance >= min_contact_tolerance && options.tolerance <= max_contact_tolerance))
    throw Error("the tolerance must be between " + number(min_contact_tolerance) + " and " +
                number(max_contact_tolerance) + ", got " + number(options.tolerance));
  if (options.max_iterations < 1) throw Error("max_iterations must be at least 1");
  if (options.love_aliases < 1 || options.love_aliases > 1000) throw Error("love_aliases must be from 1 to 1000");
  if (options.threads < 0 || options.threads > 1024) throw Error("threads must be from 0 to 1024");
  if (std::isnan(options.hardness) || options.hardness < 0)
    throw Error("the hardness must be 0 (elastic), positive or infinite (elastic) [Pa], got " + number(options.hardness));
  const double work = options.work_of_adhesion, stress = options.adhesive_stress;
  if (!(std::isfinite(work) && work >= 0))
    throw Error("the work of adhesion must be 0 (no adhesion) or finite and positive [J/m^2], got " + number(work));
  if (!(std::isfinite(stress) && stress >= 0))
    throw Error("the adhesive stress must be 0 (no adhesion) or finite and positive [Pa], got " + number(stress));
  if ((work > 0) != (stress > 0))
    throw Error("adhesion needs both the work of adhesion [J/m^2] and the adhesive (Dugdale) stress [Pa], positive: got " +
                number(work) + " and " + number(stress));
  if (work > 0 && is_plastic(options))
    throw Error("adhesion with a hardness is not solved: give one of them");
}

// The map's valid heights: how many, their mean, their rms about it and the highest above it.
struct HeightFigures {
  std::size_t valid = 0;
  double mean = 0, rms = 0, max_height = 0;
};

// Throws for a map whose valid heights are all equal (no contact problem).
HeightFigures height_figures(const HeightMap& map) {
  HeightFigures figures;
  double sum = 0;
  for (double h : map.heights)
    if (!std::isnan(h)) {
      sum += h;
      ++figures.valid;
    }
  const double mean = sum / static_cast<double>(figures.valid);
  double squares = 0, highest = -std::numeric_limits<double>::infinity(), lowest = -highest;
  for (double h : map.heights)
    if (!std::isnan(h)) {
      squares += (h - mean) * (h - mean);
      highest = std::max(highest, h);
      lowest = std::min(lowest, h);
    }
  figures.mean = mean;
  figures.rms = std::sqrt(squares / static_cast<double>(figures.valid));
  figures.max_height = highest - mean;
  if (!(highest > lowest && figures.rms > 0)) throw Error(map.source + ": the heights are all equal: a flat has no contact problem to solve");
  return figures;
}

// The periodic Love kernel at one wavenumber, times E*/2: the sum over the aliases (m, n) of
// sinc * sinc / |q + Q| from the aliases' x factors and squared wavenumbers of its column (xf,
// x2) and those in y of its row, with Richardson's step on M and M/2 (see make_spectral_kernel).
double love_alias_sum(const double* xf, const double* x2, const std::vector<double>& y_factor,
                      const std::vector<double>& y_squared, int aliases) {
  const int inner = aliases / 2, width = 2 * aliases + 1;
  double outer_sum = 0, inner_sum = 0;
  for (int n = -aliases; n <= aliases; ++n) {
    const double yf = y_factor[n + aliases], y2 = y_squared[n + aliases];
    if (yf == 0) continue;
    double row = 0, inner_row = 0;
    for (int m = 0; m < width; ++m) {
      const double term = xf[m] / std::sqrt(x2[m] + y2);
      row += term;
      if (std::abs(m - aliases) <= inner) inner_row += term;
    }
    outer_sum += yf * row;
    if (std::abs(n) <= inner) inner_sum += yf * inner_row;
  }
  // error ~ c / M^2: S = S_M + (S_M - S_{M/2}) / 3 when M/2 is exactly half
  return inner * 2 == aliases && inner > 0 ? outer_sum + (outer_sum - inner_sum) / 3 : outer_sum;
}

// The map coarsened 2 x 2 for the coarse start: each coarse point the mean of the valid points of
// its block (NaN if none); an odd last row or column a block of its own.
HeightMap coarsened_2x2(const HeightMap& map) {
  const std::size_t nx = map.nx, ny = map.ny;
  HeightMap coarse;
  coarse.nx = (nx + 1) / 2;
  coarse.ny = (ny + 1) / 2;
  coarse.dx = 2 * map.dx;
  coarse.dy = 2 * map.dy;
  coarse.source = map.source;
  coarse.format = map.format;
  coarse.heights.assign(coarse.nx * coarse.ny, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t j = 0; j < coarse.ny; ++j)
    for (std::size_t i = 0; i < coarse.nx; ++i) {
      double block_sum = 0;
      int count = 0;
      for (std::size_t b = 2 * j; b < std::min(2 * j + 2, ny); ++b)
        for (std::size_t a = 2 * i; a < std::min(2 * i + 2, nx); ++a) {
          const double h = map.heights[b * nx + a];
          if (std::isnan(h)) continue;
          block_sum += h;
          ++count;
        }
      if (count > 0) coarse.heights[j * coarse.nx + i] = block_sum / count;
    }
  return coarse;
}

// The coarse start's options: the same less the stiffness, to a looser tolerance, its progress
// reported as the coarse start's.
ExactContactOptions coarse_start_options(const ExactContactOptions& options) {
  ExactContactOptions coarse_options = options;
  coarse_options.tolerance = std::max(options.tolerance, coarse_start_tolerance);
  coarse_options.stiffness = false;
  if (options.progress)
    coarse_options.progress = [progress = options.progress](const ContactProgress& reported) {
      ContactProgress relabelled = reported;
      if (std::strcmp(reported.stage, "pressure") == 0) relabelled.stage = "coarse pressure";
      else if (std::strcmp(reported.stage, "gap") == 0) relabelled.stage = "coarse gap";
      progress(relabelled);
    };
  coarse_options.max_memory = 0;  // counted in this map's estimate
  return coarse_options;
}

}  // namespace

ExactContact::ExactContact(const HeightMap& map, const ExactContactOptions& options) try : options_(options) {
  map.validate();
  check_contact_options(options);
  const double modulus = options.contact_modulus;
  plastic_ = is_plastic(options);
  hardness_ = plastic_ ? options.hardness : HUGE_VAL;
  adhesive_ = is_adhesive(options);
  if (adhesive_) {
    adhesive_stress_ = options.adhesive_stress;
    adhesive_range_ = options.work_of_adhesion / options.adhesive_stress;
  }
  threads_ = options.threads > 0 ? options.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  nx_ = map.nx;
  ny_ = map.ny;
  dx_ = map.dx;
  dy_ = map.dy;
  const std::size_t factor = options.boundary == ContactBoundary::padded ? 2 : 1;
  if (nx_ > max_contact_points / factor || ny_ > max_contact_points / factor ||
      nx_ * factor > max_contact_points / (ny_ * factor))
    throw Error("the solve grid of " + std::to_string(nx_) + " x " + std::to_string(ny_) + " points" +
                (factor == 2 ? " padded to twice each way" : "") + " exceeds " + std::to_string(max_contact_points) +
                " points");
  sx_ = nx_ * factor;
  sy_ = ny_ * factor;
  memory_ = exact_contact_memory(nx_, ny_, options);
  if (options.max_memory > 0 && memory_ > options.max_memory)
    throw Error("the exact contact of " + map_in_words(map.source, nx_, ny_, options.boundary) + " needs about " +
                memory_text(memory_) + ", more than the " + memory_text(options.max_memory) +
                " allowed (--max-memory, max_memory): " + smaller_map_advice(options.boundary) + ", or allow more");
  nominal_area_ = map.width() * map.length();

  const HeightFigures heights = height_figures(map);
  valid_points_ = heights.valid;
  rms_ = heights.rms;
  max_height_ = heights.max_height;

  {  // (centred and found are gone before the solve grid is made: the memory estimate counts the larger)
    HeightMap centred = map;
    for (double& h : centred.heights) h -= heights.mean;
    const Summits found = find_summits(centred);
    summits_ = found.list.size();
    double summit_sum = 0;
    for (const Summit& s : found.list) summit_sum += s.height;
    mean_summit_ = summits_ > 0 ? summit_sum / static_cast<double>(summits_) : std::numeric_limits<double>::quiet_NaN();
  }

  allocate_solve_grid(map, heights.mean);
  if (options.kernel == ContactKernel::love && options.boundary == ContactBoundary::padded)
    make_padded_love_kernel(modulus);
  else
    make_spectral_kernel(modulus);
  make_preconditioner_stencil();
  if (adhesive_) {
    base_heights_ = heights_;
    cohesive_.assign(heights_.size(), 0);
  }

  // The coarse start: the map coarsened 2 x 2 (each coarse point the mean of the valid points of
  // its block; an odd last row or column a block of its own), solved with the same options less
  // the stiffness and to a looser tolerance, itself started from a coarser map.
  // (not with adhesion: each step continues the last one's cohesive zone, its branch)
  if (options_.coarse_start && !adhesive_ && nx_ >= 2 * coarse_start_points && ny_ >= 2 * coarse_start_points) {
    release_scratch();  // while the coarse levels are made
    const HeightMap coarse = coarsened_2x2(map);
    const ExactContactOptions coarse_options = coarse_start_options(options);
    try {
      coarse_ = std::make_unique<ExactContact>(coarse, coarse_options);
      coarse_->coarse_level_ = true;
      coarse_->release_scratch();
    } catch (const Error&) {
      // a coarse map the solver refuses (its heights all equal, its pixels too large): no coarse start
    }
    ensure_scratch();
  }
  find_pressure_range();
} catch (const std::bad_alloc&) {
  // the members are gone here: the figures from the arguments
  throw Error("out of memory setting up the exact contact of " + map_in_words(map.source, map.nx, map.ny, options.boundary) +
              ": it needs about " + memory_text(exact_contact_memory(map.nx, map.ny, options)) +
              " and the system gave less: " + smaller_map_advice(options.boundary));
}

// The solve grid's arrays: the map's heights about their mean (`mean`) and where it may carry
// pressure, the solver's work arrays (zero), the spectrum and the kernel (to be made).
void ExactContact::allocate_solve_grid(const HeightMap& map, double mean) {
  const std::size_t points = sx_ * sy_, half = sx_ / 2 + 1;
  active_.assign(points, 0);
  heights_.assign(points, 0.0);
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i) {
      const double h = map.heights[j * nx_ + i];
      if (std::isnan(h)) continue;
      active_[j * sx_ + i] = 1;
      heights_[j * sx_ + i] = h - mean;
    }
  pressure_.assign(points, 0.0);
  displacement_.assign(points, 0.0);
  ensure_scratch();
  zero_row_.assign(sx_, 0.0);
  partial_sums_.assign(row_blocks(ny_) * sums_per_block, 0.0);
  // the passes over the points share the threads from 256^2 points (below, starting the
  // threads would cost more than the pass)
  loop_threads_ = nx_ * ny_ >= (std::size_t{1} << 16) ? threads_ : 1;
  kernel_.assign((sy_ / 2 + 1) * half, 0.0);  // even in q_y: rows sy - ky are rows ky's
}

// The work arrays (zero), if released: the constrained solve's three, the stiffness solve's fourth
// (not on a coarse level, which solves none, unless capped: its search for the load does), and the
// spectrum.
void ExactContact::ensure_scratch() {
  const std::size_t points = sx_ * sy_, half = sx_ / 2 + 1;
  if (direction_.size() != points) direction_.assign(points, 0.0);
  if (work_.size() != points) work_.assign(points, 0.0);
  if (increment_.size() != points) increment_.assign(points, 0.0);
  if (stiffness_x_.size() != points && (!coarse_level_ || plastic_)) stiffness_x_.assign(points, 0.0);
  if (spectrum_.size() != sy_ * half) spectrum_.assign(sy_ * half, {0.0, 0.0});
}

// While a coarser level solves (and a coarse level between its solves) the work arrays are
// returned to the system: the largest use is then one level's work arrays and every level's
// solution, not every level's work arrays at once.
void ExactContact::release_scratch() {
  std::vector<double>().swap(direction_);
  std::vector<double>().swap(work_);
  std::vector<double>().swap(increment_);
  std::vector<double>().swap(stiffness_x_);
  std::vector<std::complex<double>>().swap(spectrum_);
}

// The padded Love kernel_ and self_compliance_.
void ExactContact::make_padded_love_kernel(double modulus) {
  const std::size_t points = sx_ * sy_;
  // Real-space coefficients for every offset within the map, wrapped onto the doubled grid:
  // the circular convolution is then the linear one (no images).
  std::vector<double> coefficients(points);
  const double a = dx_ / 2, b = dy_ / 2;
  for (std::size_t j = 0; j < sy_; ++j) {
    const double y = static_cast<double>(j <= ny_ ? j : sy_ - j) * dy_;
    for (std::size_t i = 0; i < sx_; ++i) {
      const double x = static_cast<double>(i <= nx_ ? i : sx_ - i) * dx_;
      coefficients[j * sx_ + i] = love_coefficient(x, y, a, b) / (pi * modulus);
    }
  }
  self_compliance_ = coefficients[0];
  detail::forward_2d(coefficients.data(), spectrum_.data(), sy_, sx_);
  for (std::size_t k = 0; k < kernel_.size(); ++k) kernel_[k] = spectrum_[k].real();  // rows 0 to sy/2
}

// kernel_ and self_compliance_ made in Fourier space: the Fourier kernel, or the periodic Love
// kernel.
void ExactContact::make_spectral_kernel(double modulus) {
  const std::size_t points = sx_ * sy_, half = sx_ / 2 + 1;
  const bool love = options_.kernel == ContactKernel::love;
  const int aliases = love ? options_.love_aliases : 0;
  const double alias_x = 2 * pi / dx_, alias_y = 2 * pi / dy_;
  // The periodic Love kernel: the displacement at the pixel centres of the pixel-constant
  // pressure is the sum over aliases q + Q of 2/(E*|q + Q|) sinc(qx dx/2) sinc(qy dy/2); the
  // terms of m and -m nearly cancel (the sines alternate), so the sum over the square
  // |m|, |n| <= M converges like 1/M^2, and Richardson's step on M and M/2 removes that term.
  const int width = 2 * aliases + 1;
  // per column: the aliases' x sinc factors and squared wavenumbers
  std::vector<double> x_factor(half * width), x_squared(half * width);
  for (std::size_t kx = 0; kx < half; ++kx)
    for (int m = -aliases; m <= aliases; ++m) {
      const double q = wavenumber(kx, sx_, dx_) + m * alias_x;
      x_factor[kx * width + m + aliases] = sinc(q * dx_ / 2);
      x_squared[kx * width + m + aliases] = q * q;
    }
  // rows ky and sy - ky have the same kernel (it is even in qy): the first half, kept
  const std::size_t rows = sy_ / 2 + 1;
  in_parallel(threads_, rows, [&](std::size_t first, std::size_t count) {
    std::vector<double> y_factor(width), y_squared(width);
    for (std::size_t ky = first; ky < first + count; ++ky) {
      const double qy = wavenumber(ky, sy_, dy_);
      for (int n = -aliases; n <= aliases; ++n) {
        const double q = qy + n * alias_y;
        y_factor[n + aliases] = sinc(q * dy_ / 2);
        y_squared[n + aliases] = q * q;
      }
      for (std::size_t kx = 0; kx < half; ++kx) {
        const double qx = wavenumber(kx, sx_, dx_);
        double value;
        if (!love) {
          const double q = std::hypot(qx, qy);
          value = q > 0 ? 2 / (modulus * q) : 0.0;
        } else if (kx == 0 && ky == 0) {
          value = 0;  // the mean: every alias's sinc vanishes, and the mean pressure moves no gap
        } else {
          value = 2 / modulus * love_alias_sum(&x_factor[kx * width], &x_squared[kx * width], y_factor, y_squared, aliases);
        }
        kernel_[ky * half + kx] = value;
      }
    }
  });
  // the self-compliance: the real-space kernel at zero offset, the mean of the full spectrum
  double total = 0;
  for (std::size_t ky = 0; ky < sy_; ++ky)
    for (std::size_t kx = 0; kx < half; ++kx) {
      const bool single = kx == 0 || (sx_ % 2 == 0 && kx == sx_ / 2);
      total += (single ? 1.0 : 2.0) * kernel_[kernel_row(ky) * half + kx];
    }
  self_compliance_ = total / static_cast<double>(points);
}

// The preconditioner's stencil: the inverse Green's function K = 1/G (the elastic stiffness,
// E* |q| / 2 for the Fourier kernel) in real space at the offsets (0, 0), (1, 0), (0, 1),
// (1, 1), from its spectrum (even in q; the mean, which G leaves unmoved when periodic, taken
// as 0).
void ExactContact::make_preconditioner_stencil() {
  const std::size_t points = sx_ * sy_, half = sx_ / 2 + 1;
  std::vector<double> cos_x(half), cos_y(sy_);
  for (std::size_t kx = 0; kx < half; ++kx) cos_x[kx] = std::cos(2 * pi * static_cast<double>(kx) / static_cast<double>(sx_));
  for (std::size_t ky = 0; ky < sy_; ++ky) cos_y[ky] = std::cos(2 * pi * static_cast<double>(ky) / static_cast<double>(sy_));
  double centre = 0, along_x = 0, along_y = 0, diagonal = 0;
  for (std::size_t ky = 0; ky < sy_; ++ky)
    for (std::size_t kx = 0; kx < half; ++kx) {
      const double g = kernel_[kernel_row(ky) * half + kx];
      if (!(g > 0)) continue;
      const bool single = kx == 0 || (sx_ % 2 == 0 && kx == sx_ / 2);
      const double k = (single ? 1.0 : 2.0) / g;
      centre += k;
      along_x += k * cos_x[kx];
      along_y += k * cos_y[ky];
      diagonal += k * cos_x[kx] * cos_y[ky];
    }
  stencil_centre_ = centre / static_cast<double>(points);
  stencil_x_ = along_x / static_cast<double>(points);
  stencil_y_ = along_y / static_cast<double>(points);
  stencil_diagonal_ = diagonal / static_cast<double>(points);
  // positive definite on every contact set if its symbol is positive, which (multilinear in
  // cos qx dx and cos qy dy) it is if at the four corners of the Brillouin zone
  stencil_ = std::isfinite(stencil_centre_) && std::isfinite(stencil_x_) && std::isfinite(stencil_y_) &&
             std::isfinite(stencil_diagonal_);
  for (double a : {-1.0, 1.0})
    for (double b : {-1.0, 1.0})
      if (!(stencil_centre_ + 2 * a * stencil_x_ + 2 * b * stencil_y_ + 4 * a * b * stencil_diagonal_ > 0)) stencil_ = false;
}

void ExactContact::out_of_memory(const std::string& doing) const {
  throw Error("out of memory " + doing + " on the " + std::to_string(nx_) + " x " + std::to_string(ny_) +
              " map (the solver needs about " + memory_text(memory_) + "): " + smaller_map_advice(options_.boundary));
}

// The 2-D transform in three parts that the threads share: rows to spectra, then each block of
// columns forward, times the kernel and back, then rows back. On a padded grid the rows beyond
// the map's are zero on the way in and not wanted on the way out: their row transforms are
// skipped.
void ExactContact::apply(const std::vector<double>& in, std::vector<double>& out) {
  const std::size_t half = sx_ / 2 + 1;
  detail::Complex* spectrum = spectrum_.data();
  in_parallel(threads_, ny_, [&](std::size_t first, std::size_t count) {
    detail::forward_rows(in.data() + first * sx_, spectrum + first * half, count, sx_);
  });
  std::fill(spectrum + ny_ * half, spectrum + sy_ * half, detail::Complex{0.0, 0.0});
  in_parallel(threads_, half, [&](std::size_t first, std::size_t count) {
    detail::transform_columns(spectrum, sy_, half, first, count, true);
    for (std::size_t r = 0; r < sy_; ++r)
      for (std::size_t c = first; c < first + count; ++c) spectrum[r * half + c] *= kernel_[kernel_row(r) * half + c];
    detail::transform_columns(spectrum, sy_, half, first, count, false);
  });
  in_parallel(threads_, ny_, [&](std::size_t first, std::size_t count) {
    detail::inverse_rows(spectrum + first * half, out.data() + first * sx_, count, sx_);
  });
}

// M in over the free points of rows [first, end): visit(k, value) for each, skip(k) for the other
// map points. The stencil's value is made here only, so that the sums over it and the direction
// built from it (each pass computing it again: no array holds M in) see the same numbers.
template <class Visit, class Skip>
void ExactContact::over_stencil(const std::vector<double>& in, std::size_t first, std::size_t end, Visit&& visit,
                                Skip&& skip) const {
  const std::vector<double>& p = pressure_;
  const std::size_t nx = nx_, ny = ny_, sx = sx_, sy = sy_;
  const double centre = stencil_centre_, along_x = stencil_x_, along_y = stencil_y_, diagonal = stencil_diagonal_;
  const double hardness = hardness_;
  for (std::size_t j = first; j < end; ++j) {
    // the neighbouring rows and columns, wrapped across the solve grid: on a padded grid
    // the wrapped neighbours of the map's edges are the padding's zeros
    const std::size_t above = (j + sy - 1) % sy, below = (j + 1) % sy;
    const double* middle = &in[j * sx];
    const double* up = above < ny ? &in[above * sx] : zero_row_.data();
    const double* down = below < ny ? &in[below * sx] : zero_row_.data();
    auto at = [nx](const double* row, std::size_t i) { return i < nx ? row[i] : 0.0; };
    for (std::size_t i = 0, k = j * sx; i < nx; ++i, ++k) {
      if (!(p[k] > 0 && p[k] < hardness)) {  // off the free set
        skip(k);
        continue;
      }
      const std::size_t left = i == 0 ? sx - 1 : i - 1, right = i + 1 == sx ? 0 : i + 1;
      const double value = centre * middle[i] + along_x * (at(middle, left) + at(middle, right)) +
                           along_y * (up[i] + down[i]) +
                           diagonal * (at(up, left) + at(up, right) + at(down, left) + at(down, right));
      visit(k, value);
    }
  }
}

ExactContact::Sums3 ExactContact::precondition(const std::vector<double>& in, const std::vector<double>& other) {
  const auto sums = over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
    double sum = 0, product = 0, other_sum = 0;
    over_stencil(
        in, first, end,
        [&](std::size_t k, double value) {
          sum += value;
          product += value * other[k];
          other_sum += other[k];
        },
        [](std::size_t) {});
    s[0] = sum;
    s[1] = product;
    s[2] = other_sum;
  });
  Sums3 result;
  result.out = sums[0];
  result.out_other = sums[1];
  result.other = sums[2];
  return result;
}

void ExactContact::report(const char* stage, int iteration, double residual, std::size_t contact) const {
  if (!options_.progress) return;
  ContactProgress progress;
  progress.stage = stage;
  progress.iteration = iteration;
  progress.residual = residual;
  progress.contact_points = contact;
  options_.progress(progress);
}

// Polonsky and Keer (1999): conjugate gradients on the contact set, projected on p >= 0, with
// the points that penetrate the flat outside it added back (and the conjugation restarted when
// the set grows). By pressure, the flat's position is the one that makes the mean gap over the
// contact set zero, and the pressures are rescaled to the load after each step; by approach the
// flat's position is given.
//
// Preconditioned (ContactSolver::preconditioned): the direction is built from M g instead of
// the gap g, M the 3 x 3 stencil of the inverse Green's function on the contact set (symmetric
// positive definite there; by pressure projected on the directions that keep the load), so
// that the CG on the contact set converges like that of M G, whose eigenvalues no longer spread
// with the pixel count as G's do (G ~ 1/|q|); the points added back get the pressure -step M g
// of an isolated point. Polonsky and Keer restart the conjugation whenever the contact set
// grows, which in a rough contact is nearly every iteration (a steepest descent, whose
// iterations grow like G's condition number); here it is kept while the set grows by at most
// max_growth of its points. A solve whose residual has not halved in stall_iterations goes on as
// Polonsky and Keer's, whose convergence is proven.
ExactContact::Solve ExactContact::constrained(bool by_pressure, double target) {
  constexpr double max_growth = 0.01;
  constexpr int stall_iterations = 200;
  std::vector<double>& p = pressure_;
  std::vector<double>& t = direction_;
  std::vector<double>& g = work_;
  std::vector<double>& w = increment_;
  const double map_points = static_cast<double>(nx_ * ny_);
  const double total = by_pressure ? target * map_points : 0.0;
  const double tolerance = options_.tolerance;

  seed_pressure(by_pressure, target, total);
  std::fill(t.begin(), t.end(), 0.0);
  bool preconditioned = options_.solver == ContactSolver::preconditioned && stencil_;
  double growth_allowed = options_.solver == ContactSolver::preconditioned ? max_growth : 0.0;
  bool conjugate = false;
  double previous = 0, scale = 1;  // scale: the load's rescaling of p, applied with the next convolution
  double reference = INFINITY;     // the residual to halve, and when it was reached
  int reference_iteration = 0;
  Solve solve;
  // Every pass runs over the map's points only (a padded grid's other three quarters never
  // carry pressure); k = j * sx + i.
  for (int iteration = 0;; ++iteration) {
    poll_interrupt();  // an iteration of a large map takes up to a second: Ctrl-C (asperity/interrupt.hpp)
    apply(p, displacement_);
    const PassSums placed = scale_and_sum_contact_gaps(scale);
    scale = 1;
    const std::size_t contact = static_cast<std::size_t>(placed[1]);  // the free points (0 < p < hardness)
    const std::size_t plastic = static_cast<std::size_t>(placed[2]);  // at the hardness
    double approach = target;
    if (by_pressure)
      approach = contact > 0 ? -placed[0] / static_cast<double>(contact) : plastic > 0 ? plastic_approach() : 0.0;
    // the gaps, and the residual; preconditioned, w takes the gap on the contact set (0 off it)
    const PassSums gaps = gaps_and_residual_sums(approach, preconditioned);
    const double weighted = gaps[0], load = gaps[1], squares = gaps[2], penetration = gaps[5];
    double residual =
        std::max(load > 0 ? weighted / (load * rms_) : (contact == 0 ? 0.0 : INFINITY), penetration / rms_);
    // capped, the load is the target only once the free points can carry what the plastic ones do not
    if (plastic_ && by_pressure) residual = std::max(residual, std::fabs(load - total) / total);
    report(by_pressure ? "pressure" : "gap", iteration, residual, contact);
    if (residual <= tolerance) {
      solve.iterations = iteration;
      solve.residual = residual;
      solve.approach = approach;
      approach_ = approach;
      return solve;
    }
    if (iteration >= options_.max_iterations)
      throw Error("the contact solve did not converge: " + std::to_string(iteration) + " iterations reached a residual of " +
                  number(residual) + " (tolerance " + number(tolerance) + ")");
    if (contact == 0 && plastic == 0) {
      // nothing in contact yet something penetrates (by approach): start again from the overlap
      pressure_from_overlap(target);
      conjugate = false;
      continue;
    }
    if (residual <= 0.5 * reference) {
      reference = residual;
      reference_iteration = iteration;
    } else if (plastic_ && by_pressure && iteration - reference_iteration >= stall_iterations) {
      // the rescaling of a capped load can cycle (points pushed to the cap and scaled off it)
      solve.iterations = iteration;
      solve.residual = residual;
      solve.approach = approach_ = approach;
      solve.stalled = true;
      return solve;
    } else if (growth_allowed > 0 && iteration - reference_iteration >= stall_iterations) {
      preconditioned = false;  // stalled: Polonsky and Keer from here
      growth_allowed = 0;
      conjugate = false;
    }
    // the direction's source: g, or M g (less its mean over the set, by pressure)
    double source_product = squares, source_mean = 0;
    if (preconditioned) {
      const Sums3 m = precondition(w, g);
      source_mean = by_pressure ? m.out / static_cast<double>(contact) : 0.0;
      source_product = m.out_other - source_mean * m.other;
    }
    if (!(previous > 0 && source_product > 0)) conjugate = false;
    const double beta = conjugate ? source_product / previous : 0.0;
    previous = source_product;
    set_direction(preconditioned, source_mean, conjugate, beta);
    apply(t, w);
    // step = sum g t / sum (w - mean w) t over the contact set (by pressure the mean of w is the
    // flat's move); sum t is near zero, so w's mean enters through a small product
    const PassSums products = step_products();
    const double mean_w = by_pressure ? products[0] / static_cast<double>(contact) : 0.0;
    const double denominator = products[2] - mean_w * products[1], numerator = products[3];
    double step;
    if (denominator > 0 && std::isfinite(numerator)) {
      step = numerator / denominator;
    } else if (conjugate) {
      conjugate = false;  // steepest descent from the same point
      continue;
    } else {
      // the gap is uniform over the contact set, yet points outside it penetrate: no step on the
      // set, and the penetrating points get the pressure that would lift an isolated pixel
      step = 0;
    }
    // a point added back gets -step g times what the direction's operator (M, or Polonsky and
    // Keer's identity) gives a point amid a patch of uniform gap: the stencil's sum
    const double stencil_sum = stencil_centre_ + 2 * stencil_x_ + 2 * stencil_y_ + 4 * stencil_diagonal_;
    const double overlap_step = step > 0 ? (preconditioned ? step * stencil_sum : step) : 1 / self_compliance_;
    const PassSums moved = move_pressure(step, overlap_step);
    const double total_now = moved[0];
    conjugate = moved[1] <= growth_allowed * static_cast<double>(contact);
    if (by_pressure) {
      if (!(total_now > 0)) {
        seed_pressure(by_pressure, target, total);
        conjugate = false;
      } else if (plastic_) {
        rescale_capped(total);  // now: a capped scaling is not linear, G p is made anew next
      } else {
        scale = total / total_now;
      }
    }
  }
}

// The constrained solve's start: by pressure the last pressure scaled to the load `total` (or,
// with none, the load spread evenly); by approach the last pressure, or with none the overlap's.
void ExactContact::seed_pressure(bool by_pressure, double target, double total) {
  const std::size_t points = sx_ * sy_;
  std::vector<double>& p = pressure_;
  if (by_pressure) {
    double sum = 0;
    for (std::size_t k = 0; k < points; ++k) sum += active_[k] ? p[k] : 0.0;
    if (sum > 0 && plastic_) {
      rescale_capped(total);
    } else if (sum > 0) {
      for (double& value : p) value *= total / sum;
    } else {
      for (std::size_t k = 0; k < points; ++k)
        p[k] = active_[k] ? total / static_cast<double>(valid_points_) : 0.0;
    }
  } else {
    double sum = 0;
    for (std::size_t k = 0; k < points; ++k) sum += active_[k] ? p[k] : 0.0;
    if (!(sum > 0)) pressure_from_overlap(target);
  }
}

// The pressure of the flat at approach `target` pressed into the undeformed map, each point
// on its own: its overlap over the self-compliance.
void ExactContact::pressure_from_overlap(double target) {
  const std::size_t points = sx_ * sy_;
  std::vector<double>& p = pressure_;
  for (std::size_t k = 0; k < points; ++k)
    p[k] = active_[k] ? std::min(std::max(heights_[k] - target, 0.0) / self_compliance_, hardness_) : 0.0;
}

// The constrained solve's passes over the map's points (k = j * sx + i), their sums added in
// over_rows' fixed order.

// Pressure and displacement times `scale` (the load's rescaling); sums [0] the displacement
// less the height over the contact set's free points (0 < p < hardness), [1] those points, [2]
// the plastic ones (p = hardness).
ExactContact::PassSums ExactContact::scale_and_sum_contact_gaps(double scale) {
  std::vector<double>& p = pressure_;
  std::vector<double>& u = displacement_;
  const std::size_t nx = nx_, sx = sx_;
  const double hardness = hardness_;
  return over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
    double sum = 0, contact = 0, plastic = 0;
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q) {
        p[q] *= scale;
        u[q] *= scale;
        const bool in = active_[q] && p[q] > 0 && p[q] < hardness;
        sum += in ? u[q] - heights_[q] : 0.0;
        contact += in;
        plastic += p[q] >= hardness;
      }
    s[0] = sum;
    s[1] = contact;
    s[2] = plastic;
  });
}

// The gaps g at the flat's `approach` (and, preconditioned, w: the gap on the free points, 0
// off them); sums [0] pressure times |gap| and [2] the squared gaps over the free points, [1] the
// load, [5] the largest violation: a penetration outside the contact set, or a plastic point's
// gap above 0 (the flat has left it).
ExactContact::PassSums ExactContact::gaps_and_residual_sums(double approach, bool preconditioned) {
  const std::vector<double>& p = pressure_;
  const std::vector<double>& u = displacement_;
  std::vector<double>& g = work_;
  std::vector<double>& w = increment_;
  const std::size_t nx = nx_, sx = sx_;
  const double hardness = hardness_;
  return over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
    double weighted = 0, load = 0, squares = 0, penetration = 0;
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q) {
        const double gap = active_[q] ? u[q] - heights_[q] + approach : 0.0;
        g[q] = gap;
        const bool free = p[q] > 0 && p[q] < hardness;
        if (free) {
          weighted += p[q] * std::fabs(gap);
          load += p[q];
          squares += gap * gap;
        } else if (p[q] > 0) {
          load += p[q];
          penetration = std::max(penetration, gap);
        } else if (active_[q]) {
          penetration = std::max(penetration, -gap);
        }
        if (preconditioned) w[q] = free ? gap : 0.0;
      }
    s[0] = weighted;
    s[1] = load;
    s[2] = squares;
    s[5] = penetration;
  });
}

// The direction t on the contact set (0 off it): the source (the gap g, or preconditioned M w,
// w the gap on the free points) less source_mean, plus beta times the last direction when
// `conjugate`.
void ExactContact::set_direction(bool preconditioned, double source_mean, bool conjugate, double beta) {
  const std::vector<double>& p = pressure_;
  const std::vector<double>& g = work_;
  std::vector<double>& t = direction_;
  const std::size_t nx = nx_, sx = sx_;
  const double hardness = hardness_;
  over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double*) {
    if (preconditioned) {
      over_stencil(
          increment_, first, end,
          [&](std::size_t k, double source) {
            const double value = source - source_mean;
            t[k] = conjugate ? value + beta * t[k] : value;
          },
          [&](std::size_t k) { t[k] = 0.0; });
      return;
    }
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q) {
        const double value = g[q] - source_mean;
        t[q] = p[q] > 0 && p[q] < hardness ? (conjugate ? value + beta * t[q] : value) : 0.0;
      }
  });
}

// The step's sums over the free points: [0] w, [1] t, [2] w t, [3] g t.
ExactContact::PassSums ExactContact::step_products() {
  const std::vector<double>& p = pressure_;
  const std::vector<double>& t = direction_;
  const std::vector<double>& g = work_;
  const std::vector<double>& w = increment_;
  const std::size_t nx = nx_, sx = sx_;
  const double hardness = hardness_;
  return over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
    double sum_w = 0, sum_t = 0, sum_wt = 0, numerator = 0;
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q)
        if (p[q] > 0 && p[q] < hardness) {
          sum_w += w[q];
          sum_t += t[q];
          sum_wt += w[q] * t[q];
          numerator += g[q] * t[q];
        }
    s[0] = sum_w;
    s[1] = sum_t;
    s[2] = sum_wt;
    s[3] = numerator;
  });
}

// The pressure moved by -step t on the free points, projected on 0 <= p <= hardness, the
// points that penetrate outside the contact set added back with -overlap_step g and the plastic
// points the flat has left (g > 0) released by as much; sums [0] the new load, [1] the points
// added back or released.
ExactContact::PassSums ExactContact::move_pressure(double step, double overlap_step) {
  std::vector<double>& p = pressure_;
  const std::vector<double>& t = direction_;
  const std::vector<double>& g = work_;
  const std::size_t nx = nx_, sx = sx_;
  const double hardness = hardness_;
  return over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
    double total_now = 0, overlaps = 0;
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q) {
        double value;
        if (p[q] >= hardness) {
          value = g[q] > 0 ? std::max(hardness - overlap_step * g[q], 0.0) : hardness;
          overlaps += g[q] > 0;
        } else {
          value = p[q] > 0 ? std::min(std::max(p[q] - step * t[q], 0.0), hardness) : 0.0;
          if (value == 0 && active_[q] && g[q] < 0) {
            value = std::min(-overlap_step * g[q], hardness);
            ++overlaps;
          }
        }
        p[q] = value;
        total_now += value;
      }
    s[0] = total_now;
    s[1] = overlaps;
  });
}

void ExactContact::rescale_capped(double total) {
  std::vector<double>& p = pressure_;
  const std::size_t nx = nx_, sx = sx_;
  const double hardness = hardness_;
  // [0] the free points' load, [1] the plastic ones'
  const PassSums loads = over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
    double free_load = 0, held = 0;
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q) {
        if (p[q] >= hardness) held += p[q];
        else if (p[q] > 0) free_load += p[q];
      }
    s[0] = free_load;
    s[1] = held;
  });
  const bool hold = loads[0] > 0 && total - loads[1] > 0;  // the free points carry the rest
  const double target = hold ? total - loads[1] : total;
  const double lower = hold ? 0.0 : 1.0;  // the points scaled: p > 0 and p < hardness, or every p > 0
  // the factor f with sum min(f p, hardness) = target: that sum is concave and increasing in f,
  // so Newton's steps from f = target / sum p (at or below the root) climb to it without passing it
  double factor = target / (hold ? loads[0] : loads[0] + loads[1]);
  double carried = 0;
  for (int pass = 0; pass < 100; ++pass) {
    const PassSums sums = over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
      double carried = 0, slope = 0;
      for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
        for (std::size_t q = k, row_end = k + nx; q < row_end; ++q) {
          if (!(p[q] > 0 && (p[q] < hardness || lower > 0))) continue;
          const double value = factor * p[q];
          carried += std::min(value, hardness);
          slope += value < hardness ? p[q] : 0.0;
        }
      s[0] = carried;
      s[1] = slope;
    });
    carried = sums[0];
    const double excess = carried - target;
    if (std::fabs(excess) <= 1e-15 * total || !(sums[1] > 0)) break;  // exact, or every point capped
    factor -= excess / sums[1];
  }
  over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double*) {
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q)
        if (p[q] > 0 && (p[q] < hardness || lower > 0)) p[q] = std::min(factor * p[q], hardness);
  });
  // every point capped and the load still short: the rest on the points out of contact that the
  // flat overlaps most (h - u largest), a pixel at most H each, so that some point is free again
  double rest = target - carried;
  for (int added = 0; rest > 1e-15 * total && added < 1000; ++added) {
    std::size_t best = p.size();
    for (std::size_t j = 0; j < ny_; ++j)
      for (std::size_t k = j * sx, end = k + nx; k < end; ++k)
        if (active_[k] && p[k] == 0 &&
            (best == p.size() || heights_[k] - displacement_[k] > heights_[best] - displacement_[best]))
          best = k;
    if (best == p.size()) break;
    p[best] = std::min(rest, hardness);
    rest -= p[best];
  }
}

double ExactContact::plastic_approach() const {
  double approach = INFINITY;
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t k = j * sx_, end = k + nx_; k < end; ++k)
      if (pressure_[k] >= hardness_) approach = std::min(approach, heights_[k] - displacement_[k]);
  return std::isfinite(approach) ? approach : 0.0;
}

// The incremental problem: the flat moves by a unit approach with the contact set held; the
// pressure increment x on the contact set C solves G_CC x = 1 (conjugate gradients,
// preconditioned as the constrained solve is). The stiffness of a held contact set is the
// tangent of the load-approach curve (Barber 2003: the contact set grows by a set of zero
// pressure), so this is dP/d(approach) without the noise of a finite difference; the mean gap
// moves by 1 - <G x> over the map. With a hardness the set held is the free points' (0 < p <
// hardness): a plastic point's pressure cannot grow, and its gap (flattened to the flat) stays 0.
void ExactContact::stiffness_of(ContactStep& step) {
  const std::size_t free_points = step.contact_points - step.plastic_points;
  if (free_points == 0) return;  // no contact, or every contact point plastic: no load added
  if (free_points == sx_ * sy_) {  // periodic, full contact: no approach moves the flat
    step.stiffness = step.stiffness_per_area = step.approach_stiffness = INFINITY;
    return;
  }
  std::vector<double>& x = stiffness_x_;
  std::vector<double>& w = increment_;
  std::vector<double>& r = work_;
  std::vector<double>& d = direction_;
  const bool preconditioned = options_.solver == ContactSolver::preconditioned && stencil_;
  const std::size_t nx = nx_, sx = sx_;
  const std::vector<double>& p = pressure_;
  const double hardness = hardness_;
  // from an isolated pixel's increment (the last step's increments, tried, took more iterations)
  over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double*) {
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q)
        x[q] = p[q] > 0 && p[q] < hardness ? 1 / self_compliance_ : 0.0;
  });
  apply(x, w);
  // r: the residual, 0 off the contact set (as precondition() wants it)
  double squares = over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
    double sum = 0;
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q) {
        r[q] = p[q] > 0 && p[q] < hardness ? 1 - w[q] : 0.0;
        sum += r[q] * r[q];
      }
    s[0] = sum;
  })[0];
  double product = preconditioned ? precondition(r, r).out_other : squares;  // r . z, z = M r
  // d = z + beta d on the free points, 0 off them (z = M r preconditioned, else r)
  const auto set_search_direction = [&](double beta) {
    over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double*) {
      if (preconditioned) {
        over_stencil(
            r, first, end, [&](std::size_t k, double z) { d[k] = z + beta * d[k]; }, [&](std::size_t k) { d[k] = 0.0; });
        return;
      }
      for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
        for (std::size_t q = k, row_end = k + nx; q < row_end; ++q)
          d[q] = p[q] > 0 && p[q] < hardness ? r[q] + beta * d[q] : 0.0;
    });
  };
  set_search_direction(0.0);
  const double norm = std::sqrt(static_cast<double>(free_points));
  int iteration = 0;
  for (;; ++iteration) {
    poll_interrupt();
    const double residual = std::sqrt(squares) / norm;
    report("stiffness", iteration, residual, step.contact_points);
    if (residual <= options_.tolerance) {
      step.stiffness_residual = residual;
      break;
    }
    if (iteration >= options_.max_iterations)
      throw Error("the stiffness solve did not converge: " + std::to_string(iteration) +
                  " iterations reached a residual of " + number(residual) + " (tolerance " +
                  number(options_.tolerance) + ")");
    apply(d, w);
    const double curvature = over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
      double sum = 0;
      for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
        for (std::size_t q = k, row_end = k + nx; q < row_end; ++q) sum += d[q] * w[q];  // d is 0 off contact
      s[0] = sum;
    })[0];
    if (!(curvature > 0)) throw Error("the stiffness solve broke down (a search direction of no curvature)");
    const double alpha = product / curvature;
    squares = over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
      double sum = 0;
      for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
        for (std::size_t q = k, row_end = k + nx; q < row_end; ++q)
          if (p[q] > 0 && p[q] < hardness) {
            x[q] += alpha * d[q];
            r[q] -= alpha * w[q];
            sum += r[q] * r[q];
          }
      s[0] = sum;
    })[0];
    const double next = preconditioned ? precondition(r, r).out_other : squares;
    const double beta = next / product;
    product = next;
    set_search_direction(beta);
  }
  apply(x, w);
  const auto sums = over_rows(ny_, loop_threads_, partial_sums_, [&](std::size_t first, std::size_t end, double* s) {
    double increment = 0, opened = 0;
    for (std::size_t k = first * sx, last = end * sx; k < last; k += sx)
      for (std::size_t q = k, row_end = k + nx; q < row_end; ++q) {
        increment += x[q];
        opened += active_[q] && p[q] == 0 ? 1 - w[q] : 0.0;
      }
    s[0] = increment;
    s[1] = opened;
  });
  const double mean_pressure = sums[0] / static_cast<double>(nx_ * ny_);
  // Periodic without missing points the displacements have zero mean: the mean gap moves with
  // the approach. Otherwise only the points out of contact move it (by 1 - w each): a contact
  // point's gap stays 0 (its 1 - w is the CG's residual, which summed over a padded map in full
  // contact was the whole change: a stiffness of -1.7e15 N/m), as does a plastic point's.
  const bool moves_with_approach = options_.boundary == ContactBoundary::periodic && valid_points_ == nx_ * ny_ &&
                                   step.plastic_points == 0;
  const double gap_change = moves_with_approach ? 1.0 : std::max(sums[1], 0.0) / static_cast<double>(valid_points_);
  step.stiffness_iterations = iteration;
  step.stiffness_per_area = mean_pressure / gap_change;
  step.stiffness = step.stiffness_per_area * nominal_area_;
  step.approach_stiffness = mean_pressure * nominal_area_;
}

ContactStep ExactContact::describe(const Solve& solve) {
  ContactStep step;
  std::vector<unsigned char> contact(nx_ * ny_, 0);
  double load = 0, gaps = 0, highest = 0;
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i) {
      const std::size_t k = j * sx_ + i;
      if (!active_[k]) continue;
      if (pressure_[k] > 0) {
        contact[j * nx_ + i] = 1;
        ++step.contact_points;
        step.plastic_points += pressure_[k] >= hardness_;
        load += pressure_[k];
        highest = std::max(highest, pressure_[k]);
      } else {
        gaps += std::max(displacement_[k] - heights_[k] + solve.approach, 0.0);
      }
    }
  const double map_points = static_cast<double>(nx_ * ny_);
  step.pressure = load / map_points;
  step.load = step.pressure * nominal_area_;
  step.mean_gap = gaps / static_cast<double>(valid_points_);
  step.separation_from_mean_summit = step.mean_gap - mean_summit_;
  step.approach = solve.approach;
  step.area_fraction = static_cast<double>(step.contact_points) / map_points;
  step.real_area = step.area_fraction * nominal_area_;
  step.plastic_area_fraction = static_cast<double>(step.plastic_points) / map_points;
  step.max_pressure = highest;
  step.clusters = count_clusters(contact, nx_, ny_, options_.boundary == ContactBoundary::periodic);
  if (adhesive_) {
    // the tension sigma0 on the cohesive zone (every contact point is in it: its gap is 0)
    for (std::size_t j = 0; j < ny_; ++j)
      for (std::size_t i = 0; i < nx_; ++i) step.adhesive_points += cohesive_[j * sx_ + i];
    step.adhesive_pressure = adhesive_stress_ * static_cast<double>(step.adhesive_points) / map_points;
    step.pressure -= step.adhesive_pressure;
    step.load = step.pressure * nominal_area_;
    step.max_pressure = step.contact_points > 0 ? highest - adhesive_stress_
                                                : (step.adhesive_points > 0 ? -adhesive_stress_ : 0.0);
  }
  step.iterations = solve.iterations;
  step.solves = 1;
  step.residual = solve.residual;
  return step;
}

void ExactContact::start_from_coarse() {
  const std::size_t coarse_sx = coarse_->sx_;
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i) {
      const std::size_t k = j * sx_ + i;
      pressure_[k] = active_[k] ? coarse_->pressure_[(j / 2) * coarse_sx + i / 2] : 0.0;
    }
}

// K[h]: the pressure that flattens the map less its mean, the heights through the inverse of the
// solver's own kernel (the mean left out, as G leaves it).
void ExactContact::stiffness_times_heights(std::vector<double>& out) {
  const std::size_t half = sx_ / 2 + 1;
  detail::forward_2d(heights_.data(), spectrum_.data(), sy_, sx_);
  for (std::size_t ky = 0; ky < sy_; ++ky)
    for (std::size_t kx = 0; kx < half; ++kx) {
      const double g = kernel_[kernel_row(ky) * half + kx];
      spectrum_[ky * half + kx] *= g > 0 ? 1 / g : 0.0;
    }
  in_parallel(threads_, half, [&](std::size_t first, std::size_t count) {
    detail::transform_columns(spectrum_.data(), sy_, half, first, count, false);
  });
  detail::inverse_rows(spectrum_.data(), out.data(), sy_, sx_);
}

void ExactContact::find_pressure_range() {
  const double map_points = static_cast<double>(nx_ * ny_);
  const double resolved = options_.tolerance * rms_;
  range_.one_node = self_compliance_ > 0 ? resolved / (self_compliance_ * map_points) : 0.0;
  double compliance = 0;
  for (double g : kernel_)
    if (std::isfinite(g)) compliance = std::max(compliance, std::fabs(g));
  compliance = std::max(compliance, std::fabs(self_compliance_));
  largest_compliance_ = compliance;
  range_.numerical_limit = resolved / (8 * std::numeric_limits<double>::epsilon() * compliance);
  range_.full_contact = INFINITY;
  range_.plastic_limit = plastic_ ? hardness_ * static_cast<double>(valid_points_) / map_points : INFINITY;
  if (options_.boundary == ContactBoundary::periodic && valid_points_ == nx_ * ny_) {
    stiffness_times_heights(work_);
    double least = INFINITY, most = -INFINITY;
    for (std::size_t k = 0; k < nx_ * ny_; ++k) {
      least = std::min(least, work_[k]);
      most = std::max(most, work_[k]);
    }
    range_.full_contact = std::max(-least, 0.0);
    flattening_peak_ = most;
    std::fill(work_.begin(), work_.end(), 0.0);
  }
}

void ExactContact::check_pressure(double pressure) const {
  if (adhesive_) refuse_pressure_with_adhesion(pressure);
  if (!(std::isfinite(pressure) && pressure >= 0))
    throw Error("the mean pressure must be finite and non-negative, got " + number(pressure));
  const double modulus = options_.contact_modulus;
  const std::string asked = "the mean pressure " + number(pressure) + " Pa (p/E* " + number(pressure / modulus) + ")";
  if (pressure >= range_.plastic_limit)
    throw Error(asked + " is at or beyond what the map can carry at the hardness " + number(hardness_) +
                " Pa: every point plastic carries " + number(range_.plastic_limit) +
                " Pa (the hardness times the valid points' share of the map); ask for less, or check the hardness [Pa]");
  if (pressure == 0 || closed_form_full_contact(pressure)) return;
  if (pressure < range_.one_node)
    throw Error(asked + " is below one node of contact: the whole load on the map's highest point would deflect it by " +
                number(self_compliance_ * pressure * static_cast<double>(nx_ * ny_)) +
                " m, less than the solve resolves (the tolerance times the rms height, " +
                number(options_.tolerance * rms_) +
                " m), so the answer would be the undeformed map resting on its highest point; ask for at least " +
                number(range_.one_node) + " Pa (p/E* " + number(range_.one_node / modulus) +
                "), check the modulus E* [Pa], or give a smaller tolerance");
  if (pressure > range_.numerical_limit)
    throw Error(asked + " is beyond the solver's numerical range: its displacements (about " +
                number(pressure * largest_compliance_) +
                " m) round by more than the tolerance resolves, and the solve could not converge; at most " +
                number(range_.numerical_limit) + " Pa (p/E* " + number(range_.numerical_limit / modulus) +
                ") can. Check the modulus E* [Pa] and the pressure's unit; a map pressed flat (full contact) is "
                "answered in closed form with the periodic boundary on a map without missing points");
}

// Every point in contact: the flattened map's pressure p + K[h] (> 0 above range_.full_contact),
// its displacement the heights (G K h = h, the mean left out), the flat at the mean plane.
ContactStep ExactContact::full_contact(double pressure) {
  stiffness_times_heights(work_);
  for (std::size_t k = 0; k < pressure_.size(); ++k) {
    pressure_[k] = pressure + work_[k];
    displacement_[k] = heights_[k];
  }
  Solve exact;
  exact.approach = approach_ = 0;
  ContactStep step = describe(exact);
  step.pressure = pressure;
  step.load = pressure * nominal_area_;
  if (options_.stiffness) stiffness_of(step);
  return step;
}

ContactStep ExactContact::at_pressure(double pressure) {
  check_pressure(pressure);
  try {
    ensure_scratch();  // a coarse level's were released after its last solve
  } catch (const std::bad_alloc&) {
    out_of_memory("solving at " + number(pressure) + " Pa");
  }
  if (pressure == 0) {
    std::fill(pressure_.begin(), pressure_.end(), 0.0);
    std::fill(displacement_.begin(), displacement_.end(), 0.0);
    Solve none;
    none.approach = approach_ = max_height_;
    return describe(none);
  }
  try {
    return closed_form_full_contact(pressure) ? full_contact(pressure) : solve_pressure(pressure);
  } catch (const std::bad_alloc&) {
    out_of_memory("solving at " + number(pressure) + " Pa");
  }
}

ContactStep ExactContact::solve_pressure(double pressure) {
  int coarse_iterations = 0;
  bool coarse_answers = false;
  if (coarse_) {
    try {
      coarse_->check_pressure(pressure);
      coarse_answers = true;
    } catch (const Error&) {
      // outside the coarse map's range (its nodes are larger): this step starts from the last solution
    }
  }
  if (coarse_answers) {
    release_scratch();
    try {
      const ContactStep coarse = coarse_->at_pressure(pressure);
      coarse_->release_scratch();
      coarse_iterations = coarse.iterations + coarse.coarse_iterations;
      start_from_coarse();
    } catch (const Error&) {
      coarse_.reset();  // the coarse start did not converge: the last solution is the start, now and after
    }
    ensure_scratch();
  }
  const Solve solve = constrained(true, pressure);
  if (solve.stalled) {
    ContactStep step = plastic_pressure_search(pressure, solve.approach, solve.iterations);
    step.coarse_iterations = coarse_iterations;
    return step;
  }
  ContactStep step = describe(solve);
  // the pressures' mean is the target by construction (each iteration rescales them to it); the
  // sum in describe() differs from it by rounding, in the order of the threads' blocks
  step.pressure = pressure;
  step.load = pressure * nominal_area_;
  step.coarse_iterations = coarse_iterations;
  if (options_.stiffness) stiffness_of(step);
  return step;
}

ContactStep ExactContact::plastic_pressure_search(double pressure, double approach, int iterations) {
  // as the mean-gap search: ten times the solves' own tolerance, which their load carries as noise
  const double tolerance = 10 * options_.tolerance * pressure;
  double low = -INFINITY, high = INFINITY;  // positions with too much load, too little
  double unbracketed = 1e-3 * rms_;         // the step while a side is missing, doubled each time
  ContactStep step;
  for (int solves = 1;; ++solves) {
    const Solve solve = constrained(false, approach);
    iterations += solve.iterations;
    step = describe(solve);
    const double excess = step.pressure - pressure;
    if (std::fabs(excess) <= tolerance) {
      step.solves = solves;
      break;
    }
    if (solves >= 60)
      throw Error("the capped contact's search for the load did not converge: " + std::to_string(solves) +
                  " solves left a pressure error of " + number(excess) + " Pa");
    if (excess > 0) low = std::max(low, approach);
    else high = std::min(high, approach);
    stiffness_of(step);  // -dp/d(approach) with the free points held
    const double slope = step.approach_stiffness / nominal_area_;
    double next = slope > 0 ? approach + excess / slope : NAN;
    if (!(next > low && next < high)) {
      if (std::isfinite(low) && std::isfinite(high)) {
        next = 0.5 * (low + high);
      } else {
        next = approach + (excess > 0 ? unbracketed : -unbracketed);
        unbracketed *= 2;
      }
    }
    approach = next;
  }
  step.iterations = iterations;
  step.pressure = pressure;  // within the tolerance of it
  step.load = pressure * nominal_area_;
  if (options_.stiffness) stiffness_of(step);
  return step;
}

ContactStep ExactContact::at_mean_gap(double mean_gap) {
  if (!(std::isfinite(mean_gap) && mean_gap > 0))
    throw Error("the mean gap must be finite and positive, got " + number(mean_gap));
  if (adhesive_ && !(options_.boundary == ContactBoundary::periodic && valid_points_ == nx_ * ny_))
    throw Error("adhesive contact is solved at the flat's positions (at_approach; by mean gap only on a periodic map "
                "without missing points, where the mean gap is the position): the mean gap of a " +
                std::string(valid_points_ < nx_ * ny_ ? "map with missing points" : "padded map") +
                " jumps with the contact (jump-in, pull-off) and is searched for by no solve");
  try {
    if (adhesive_) return solve_adhesive(mean_gap);  // periodic, no missing points: the mean gap is the position
    return solve_mean_gap(mean_gap);
  } catch (const std::bad_alloc&) {
    out_of_memory("solving at a mean gap of " + number(mean_gap) + " m");
  }
}

ContactStep ExactContact::solve_mean_gap(double mean_gap) {
  ensure_scratch();  // a coarse level's were released after its last solve
  if (mean_gap >= max_height_) {
    std::fill(pressure_.begin(), pressure_.end(), 0.0);
    std::fill(displacement_.begin(), displacement_.end(), 0.0);
    Solve none;
    none.approach = approach_ = mean_gap;
    return describe(none);
  }
  // The mean gap is the approach plus the mean displacement over the map: equal for a periodic
  // map without missing points (one solve), otherwise a secant search on the approach (the
  // mean gap grows with it), bracketed once the target is passed.
  const double tolerance = 10 * options_.tolerance * rms_;
  if (mean_gap <= tolerance && closed_form_full_contact(std::nextafter(range_.full_contact, INFINITY))) {
    // closed within what the search resolves: full contact (its closed form, mean gap 0), which
    // the search would only approach, a point at a time, over thousands of iterations
    return full_contact(std::nextafter(range_.full_contact, INFINITY));
  }
  bool had_contact = false;
  for (std::size_t k = 0; k < pressure_.size(); ++k)
    if (pressure_[k] > 0) had_contact = true;
  double offset = 0;
  int coarse_iterations = 0;
  bool coarse_started = false;
  if (coarse_) {
    release_scratch();
    try {
      // the coarse map's offset between approach and mean gap, a good first guess
      const ContactStep coarse = coarse_->at_mean_gap(mean_gap);
      coarse_->release_scratch();
      coarse_iterations = coarse.iterations + coarse.coarse_iterations;
      start_from_coarse();
      offset = coarse.approach - coarse.mean_gap;
      coarse_started = true;
    } catch (const Error&) {
      coarse_.reset();
    }
    ensure_scratch();
  }
  if (had_contact && !coarse_started) {
    // the offset between approach and mean gap of the last solution, a good first guess
    Solve last;
    last.approach = approach_;
    offset = approach_ - describe(last).mean_gap;
  }
  int iterations = 0, solves = 0;
  double low = -INFINITY, low_value = 0, high = INFINITY, high_value = 0;  // approaches bracketing the target
  double approach = mean_gap + offset, previous = NAN, previous_value = NAN;
  ContactStep step;
  for (;;) {
    const Solve solve = constrained(false, approach);
    iterations += solve.iterations;
    ++solves;
    step = describe(solve);
    const double f = step.mean_gap - mean_gap;
    if (std::fabs(f) <= tolerance) break;
    if (solves >= 60)
      throw Error("the mean-gap search did not converge: " + std::to_string(solves) + " solves left a gap error of " +
                  number(f) + " m");
    if (f < 0 && approach > low) {
      low = approach;
      low_value = f;
    }
    if (f > 0 && approach < high) {
      high = approach;
      high_value = f;
    }
    double next = std::isnan(previous) ? approach - f : approach - f * (approach - previous) / (f - previous_value);
    if (std::isfinite(low) && std::isfinite(high) && !(next > low && next < high)) {
      next = low - low_value * (high - low) / (high_value - low_value);  // regula falsi in the bracket
      if (!(next > low && next < high)) next = 0.5 * (low + high);
    }
    if (!std::isfinite(next)) next = approach - f;
    previous = approach;
    previous_value = f;
    approach = next;
  }
  step.iterations = iterations;
  step.solves = solves;
  step.coarse_iterations = coarse_iterations;
  if (options_.stiffness) stiffness_of(step);
  return step;
}

std::vector<double> ExactContact::pressure_field() const {
  std::vector<double> field(nx_ * ny_);
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i) {
      const std::size_t k = j * sx_ + i;
      field[j * nx_ + i] = pressure_[k] - (adhesive_ && cohesive_[k] ? adhesive_stress_ : 0.0);  // net: tension < 0
    }
  return field;
}

std::vector<double> ExactContact::gap_field() const {
  std::vector<double> field(nx_ * ny_);
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i) {
      const std::size_t k = j * sx_ + i;
      field[j * nx_ + i] = !active_[k] ? std::numeric_limits<double>::quiet_NaN()
                           : pressure_[k] > 0 ? 0.0
                                              : std::max(displacement_[k] - heights_[k] + approach_, 0.0);
    }
  return field;
}

std::size_t count_clusters(const std::vector<unsigned char>& contact, std::size_t nx, std::size_t ny, bool periodic) {
  if (contact.size() != nx * ny) throw Error("count_clusters: the mask is not nx x ny");
  if (contact.size() > std::numeric_limits<std::uint32_t>::max())
    throw Error("count_clusters: more than 2^32 - 1 points");
  // 32-bit labels: half the memory of size_t's, on a map of up to 2^32 - 1 points
  std::vector<std::uint32_t> parent(contact.size());
  std::iota(parent.begin(), parent.end(), std::uint32_t{0});
  auto root = [&](std::size_t k) -> std::size_t {
    while (parent[k] != k) {
      parent[k] = parent[parent[k]];
      k = parent[k];
    }
    return k;
  };
  auto join = [&](std::size_t a, std::size_t b) {
    if (!contact[a] || !contact[b]) return;
    a = root(a);
    b = root(b);
    if (a != b) parent[std::max(a, b)] = static_cast<std::uint32_t>(std::min(a, b));
  };
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t k = j * nx + i;
      if (!contact[k]) continue;
      if (i + 1 < nx) join(k, k + 1);
      else if (periodic && nx > 1) join(k, j * nx);
      if (j + 1 < ny) join(k, k + nx);
      else if (periodic && ny > 1) join(k, i);
    }
  std::size_t clusters = 0;
  for (std::size_t k = 0; k < contact.size(); ++k)
    if (contact[k] && root(k) == k) ++clusters;
  return clusters;
}

}  // namespace asperity::topography
