// SPDX-License-Identifier: Apache-2.0
#include "core/spline/spline_geometry_fit.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <Eigen/Dense>

#include "core/model_interface/contact_model.hpp"
#include "core/model_interface/contact_model_options.hpp"
#include "core/model_interface/jump_transition.hpp"

namespace wrc {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A jump of the tread point between two samples is accepted when, after bisecting the interval
// to kJumpResolution, the wheel coordinate still differs by more than kJumpMinimum; candidates
// are neighbours that differ by more than kJumpCandidate (continuous motion between samples
// 0.1 mm apart stays well below: ds/dy is a few units on S1002's tread).
constexpr double kJumpCandidate = 5e-4;    // [m]
constexpr double kJumpMinimum = 1e-4;      // [m]
constexpr double kJumpResolution = 1e-7;   // [m]

int thread_count(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(std::min(hw, 8u));
}

// Runs work(line) for every line on threads; reports progress from the calling thread.
template <typename Work>
void for_each_line(int lines, int threads, Work work, const FitProgress& progress, long offset, long total,
                   const std::string& stage) {
  std::atomic<int> next{0}, done{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (int line = next++; line < lines; line = next++) {
      try {
        work(line);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
      ++done;
    }
  };
  // Every thread works; the calling thread only reports progress (the callback needs no locking).
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, threads); ++t) pool.emplace_back(worker);
  while (progress && done.load() < lines) {
    progress(offset + done.load(), total, stage);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  for (std::thread& t : pool) t.join();
  if (progress) progress(offset + lines, total, stage);
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

std::vector<double> sample_values(double lo, double hi, int n, bool midpoints) {
  std::vector<double> v;
  if (n < 2) return {lo};
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / (n - 1);
    v.push_back(i == n - 1 ? hi : lo + (hi - lo) * t);
  }
  if (!midpoints) return v;
  std::vector<double> m;
  for (size_t i = 0; i + 1 < v.size(); ++i) m.push_back(0.5 * (v[i] + v[i + 1]));
  return m;
}

double WheelSampleGrid::jump_distance(size_t i, size_t j, size_t k) const {
  double best = std::numeric_limits<double>::infinity();
  for (const TreadJump& jump : line_jumps[j * yaw.size() + k]) best = std::min(best, std::abs(y[i] - jump.y));
  return best;
}

WheelSampleGrid sample_wheel_grid(const WheelsetGeometry& geometry, WheelSide side, std::vector<double> y,
                                  std::vector<double> roll, std::vector<double> yaw, const SplineFitOptions& options,
                                  double s_split, int threads, const FitProgress& progress, long progress_offset,
                                  long progress_total) {
  WheelSampleGrid grid;
  grid.side = side;
  grid.y = std::move(y);
  grid.roll = std::move(roll);
  grid.yaw = std::move(yaw);
  const size_t ny = grid.y.size(), nk = grid.yaw.size();
  const int lines = static_cast<int>(grid.roll.size() * nk);
  grid.samples.resize(ny * static_cast<size_t>(lines));
  grid.line_jumps.resize(static_cast<size_t>(lines));
  const double floor = ContactModelOptions{}.lateral_curvature_floor;
  std::atomic<int> evaluations{0};
  auto work = [&](int line) {
    const size_t j = static_cast<size_t>(line) / nk, k = static_cast<size_t>(line) % nk;
    WheelsetPose pose;
    pose.z = geometry.track().nominal_radius;
    pose.roll = grid.roll[j];
    pose.yaw = grid.yaw[k];
    auto sample_at = [&](double at) {
      pose.y = at;
      ++evaluations;
      return sample_wheel(geometry, side, pose, s_split, options.clearance_cap, floor, options.search);
    };
    WheelSample* row = &grid.samples[static_cast<size_t>(line) * ny];
    for (size_t i = 0; i < ny; ++i) row[i] = sample_at(grid.y[i]);
    for (size_t i = 0; i + 1 < ny; ++i) {
      if (!row[i].valid || !row[i + 1].valid) continue;
      double lo = grid.y[i], hi = grid.y[i + 1], s_lo = row[i].tread.s, s_hi = row[i + 1].tread.s;
      if (std::abs(s_hi - s_lo) <= kJumpCandidate) continue;
      bool lost = false;
      while (hi - lo > kJumpResolution) {
        const double mid = 0.5 * (lo + hi);
        const WheelSample m = sample_at(mid);
        if (!m.valid) {
          lost = true;
          break;
        }
        if (std::abs(m.tread.s - s_lo) > std::abs(s_hi - m.tread.s)) {
          hi = mid, s_hi = m.tread.s;
        } else {
          lo = mid, s_lo = m.tread.s;
        }
      }
      if (!lost && std::abs(s_hi - s_lo) > kJumpMinimum)
        grid.line_jumps[static_cast<size_t>(line)].push_back({0.5 * (lo + hi), pose.roll, pose.yaw, s_lo, s_hi});
    }
  };
  for_each_line(lines, threads, work, progress, progress_offset, progress_total,
                std::string("sampling the ") + side_name(side) + " wheel");
  grid.exact_evaluations = evaluations.load();

  size_t invalid = 0;
  const WheelSample* first_invalid = nullptr;
  size_t first_index = 0;
  for (size_t n = 0; n < grid.samples.size(); ++n) {
    if (grid.samples[n].valid) continue;
    if (!first_invalid) first_invalid = &grid.samples[n], first_index = n;
    ++invalid;
  }
  if (invalid * 100 > grid.samples.size()) {
    const size_t i = first_index % ny, line = first_index / ny;
    std::ostringstream msg;
    msg << "spline fit: the " << side_name(side) << " wheel has no tread contact point at " << invalid << " of "
        << grid.samples.size() << " samples, e.g. y = " << grid.y[i] << " m, roll = " << grid.roll[line / nk]
        << " rad, yaw = " << grid.yaw[line % nk] << " rad (shrink the box)";
    throw std::runtime_error(msg.str());
  }
  return grid;
}

std::vector<double> place_y_breakpoints(const SplineFitOptions& options, const SplineBox& box,
                                        const std::vector<TreadJump>& jumps, int lines) {
  if (!options.y_breakpoints.empty()) return options.y_breakpoints;  // left wheel's; callers mirror
  const int n = options.intervals[0];
  if (options.placement == KnotPlacement::kUniform || jumps.empty() || lines <= 0)
    return sample_values(box.y_min, box.y_max, n + 1);
  // Density on a fine grid: 1 + grading * (share of lines whose jump band covers the cell).
  const int cells = 4000;
  const double h = (box.y_max - box.y_min) / cells;
  std::vector<double> density(static_cast<size_t>(cells), 0.0);
  for (const TreadJump& jump : jumps) {
    const double reach = options.jump_band + 0.5 * h;
    const int c0 = std::max(0, static_cast<int>(std::floor((jump.y - reach - box.y_min) / h)));
    const int c1 = std::min(cells - 1, static_cast<int>(std::floor((jump.y + reach - box.y_min) / h)));
    for (int c = c0; c <= c1; ++c) density[static_cast<size_t>(c)] += 1.0 / lines;
  }
  std::vector<double> cumulative(static_cast<size_t>(cells) + 1, 0.0);
  for (int c = 0; c < cells; ++c)
    cumulative[static_cast<size_t>(c) + 1] =
        cumulative[static_cast<size_t>(c)] + 1.0 + options.grading * std::min(1.0, density[static_cast<size_t>(c)]);
  std::vector<double> breaks{box.y_min};
  size_t c = 0;
  for (int b = 1; b < n; ++b) {
    const double target = cumulative.back() * b / n;
    while (cumulative[c + 1] < target) ++c;
    const double t = (target - cumulative[c]) / (cumulative[c + 1] - cumulative[c]);
    breaks.push_back(box.y_min + (static_cast<double>(c) + t) * h);
  }
  breaks.push_back(box.y_max);
  // Every interval keeps at least two samples.
  for (size_t i = 1; i < breaks.size(); ++i)
    if (breaks[i] - breaks[i - 1] < 2.0 * options.sample_step_y) return sample_values(box.y_min, box.y_max, n + 1);
  return breaks;
}

namespace {

// Weight of the values filled in where a branch has no sample of its own (extrapolated linearly
// along the line from its last two samples): enough to keep every basis function of the branch
// determined by a smooth continuation instead of the ridge's pull to 0, too little to move the
// fit where the branch has samples.
constexpr double kFillWeight = 1e-4;
// A branch continued past a jump is followed from sample to sample while its minimum moves by
// less than this in s [m] (ds/dy stays below 10 there; a larger step means it has vanished).
constexpr double kContinuationShift = 1e-3;
// Margin of a branch's basis beyond the farthest sampled jump plus its y reach [m]: the fitted
// jump surface may lie a little beyond the sampled jumps between the lines.
constexpr double kBranchMargin = 2.5e-4;
// Weight of a branch's continuation samples past its jumps [-] (its own samples weigh 1). The
// transition needs the continuation only where the two heights differ by less than its
// half-width, where the other branch carries most of the load; at full weight its curvature
// pulls the own stretch's fit (10 x 2 x 2, rms in the continuous region, weight 1 -> 0.1:
// flange clearance 2.25 -> 1.54 um, s 2.65 -> 1.79 um, rolling radius 0.361 -> 0.332 um, hertz_B
// 9.5e-4 -> 8.3e-4 1/m), while the continuation itself stays within 0.1 um of z and 1.1 mrad of
// the contact angle (tests/unit/spline_branch_test.cpp).
constexpr double kContinuationWeight = 0.1;
// Farthest a branch is followed past its jump in y [m]: beyond it the two heights of S1002 on
// UIC60 differ by more than any Hertz approach the fit options allow.
constexpr double kMaxContinuation = 3e-3;

// The Hertz approach [m] of the contact described by a sample's fields under the normal load [N]
// (sharing_approach()).
double hertz_approach(const WheelSample& s, double normal_load) {
  return sharing_approach(s.fields[kFieldHertzA], s.fields[kFieldHertzB], normal_load);
}

// What following one branch past one jump on one line found.
struct ContinuationTrace {
  double approach = std::numeric_limits<double>::infinity();  // mean Hertz approach of both sides [m]
  double fold = std::numeric_limits<double>::infinity();      // height difference where it vanished [m]
  std::vector<std::pair<double, double>> heights;  // (|y - y_jump| [m], own z minus continued z [m])
};

// The basis of one fit over [y_lo, y_hi] and the wheel's roll and yaw ranges.
TensorBasis branch_basis(const SplineFitOptions& options, const SplineBox& box, const std::vector<double>& y_breaks) {
  return TensorBasis({BSplineBasis(options.degrees[0], y_breaks),
                      BSplineBasis::uniform(options.degrees[1], -box.roll_max, box.roll_max, options.intervals[1]),
                      BSplineBasis::uniform(options.degrees[2], -box.yaw_max, box.yaw_max, options.intervals[2])});
}

// Least-squares jump surface through the m-th jump of every line.
JumpSurface fit_jump_surface(const WheelSampleGrid& grid, size_t m) {
  const int na = std::min<int>(3, static_cast<int>(grid.roll.size())), nb = std::min<int>(3, static_cast<int>(grid.yaw.size()));
  Eigen::MatrixXd a(static_cast<Eigen::Index>(grid.line_jumps.size()), na * nb);
  Eigen::VectorXd y(a.rows());
  for (size_t line = 0; line < grid.line_jumps.size(); ++line) {
    const TreadJump& j = grid.line_jumps[line][m];
    for (int p = 0; p < na; ++p)
      for (int q = 0; q < nb; ++q)
        a(static_cast<Eigen::Index>(line), p * nb + q) = std::pow(j.roll, p) * std::pow(j.yaw, q);
    y(static_cast<Eigen::Index>(line)) = j.y;
  }
  const Eigen::VectorXd c = a.completeOrthogonalDecomposition().solve(y);
  JumpSurface out;
  for (int p = 0; p < na; ++p)
    for (int q = 0; q < nb; ++q) out.c[static_cast<size_t>(3 * p + q)] = c(p * nb + q);
  return out;
}

// Every line holds the same number of jumps (> 0): the branches are well defined.
size_t common_jump_count(const WheelSampleGrid& grid) {
  const size_t n = grid.line_jumps.front().size();
  for (const auto& line : grid.line_jumps)
    if (line.size() != n) return 0;
  return n;
}

// The report's counts of one wheel's samples: its jumps, samples, those in flange contact and
// those near a jump.
void count_samples(const WheelSampleGrid& grid, const SplineFitOptions& options, WheelFitReport& report) {
  for (const auto& line : grid.line_jumps) report.jumps.insert(report.jumps.end(), line.begin(), line.end());
  for (size_t l = 0; l < grid.line_jumps.size(); ++l) {
    const int n = static_cast<int>(grid.line_jumps[l].size());
    report.fewest_line_jumps = l == 0 ? n : std::min(report.fewest_line_jumps, n);
    report.most_line_jumps = l == 0 ? n : std::max(report.most_line_jumps, n);
  }
  report.exact_evaluations = grid.exact_evaluations;
  const size_t count = grid.samples.size();
  const size_t nyy = grid.y.size(), nk = grid.yaw.size();
  report.samples = static_cast<int>(count);
  for (size_t n = 0; n < count; ++n) {
    const size_t i = n % nyy, line = n / nyy;
    const WheelSample& s = grid.samples[n];
    if (s.valid && s.flange_clearance <= 0.0) ++report.samples_in_flange_contact;
    if (s.valid && grid.jump_distance(i, line / nk, line % nk) < options.jump_band) ++report.samples_near_jumps;
  }
}

// The breakpoints in y of the fit across the jumps: the options' (mirrored for the right wheel)
// or placed from the wheel's jumps.
std::vector<double> across_jumps_breakpoints(const SplineFitOptions& options, const SplineBox& box, WheelSide side,
                                             const std::vector<TreadJump>& jumps, long lines) {
  std::vector<double> y_breaks;
  if (!options.y_breakpoints.empty() && side == WheelSide::kRight) {
    for (auto it = options.y_breakpoints.rbegin(); it != options.y_breakpoints.rend(); ++it) y_breaks.push_back(-*it);
  } else {
    y_breaks = place_y_breakpoints(options, box, jumps, static_cast<int>(lines));
  }
  return y_breaks;
}

// The samples of the fit across the jumps: jump_weight within jump_band of a jump, 0 where no
// tread point exists (values of the previous valid sample on the line, so the ridge has nothing
// to pull towards 0).
WeightedSamples across_jumps_samples(const WheelSampleGrid& grid, const SplineFitOptions& options) {
  const size_t count = grid.samples.size();
  WeightedSamples samples;
  samples.dimension = 3;
  samples.points.reserve(3 * count);
  samples.weights.reserve(count);
  samples.values.resize(static_cast<Eigen::Index>(count), kSplineFieldCount);
  size_t n = 0;
  for (size_t j = 0; j < grid.roll.size(); ++j) {
    for (size_t k = 0; k < grid.yaw.size(); ++k) {
      const WheelSample* last_valid = nullptr;
      for (size_t i = 0; i < grid.y.size(); ++i, ++n) {
        const WheelSample& s = grid.at(i, j, k);
        samples.points.insert(samples.points.end(), {grid.y[i], grid.roll[j], grid.yaw[k]});
        double weight = 1.0;
        if (!s.valid) {
          weight = 0.0;
        } else if (grid.jump_distance(i, j, k) < options.jump_band) {
          weight = options.jump_weight;
        }
        if (s.valid) last_valid = &s;
        const WheelSample* source = s.valid ? &s : last_valid;
        for (int f = 0; f < kSplineFieldCount; ++f)
          samples.values(static_cast<Eigen::Index>(n), f) = source ? source->fields[static_cast<size_t>(f)] : 0.0;
        samples.weights.push_back(weight);
      }
    }
  }
  return samples;
}

// One fit across the jumps (the paper's form) of one wheel.
void fit_across_jumps(const WheelSampleGrid& grid, const SplineFitOptions& options, const SplineBox& box,
                      WheelSide side, long lines, WheelFitReport& report, SplineWheel& wheel) {
  const std::vector<double> y_breaks = across_jumps_breakpoints(options, box, side, report.jumps, lines);
  report.y_breakpoints = {y_breaks};
  const WeightedSamples samples = across_jumps_samples(grid, options);
  wheel.branches.push_back(fit_tensor_spline(branch_basis(options, box, y_breaks), samples, &report.fit));
}

// Follows the branches of one wheel past their jumps (sample_wheel_branch()), line by line.
struct BranchFollower {
  BranchFollower(const WheelsetGeometry& g, const WheelSampleGrid& samples, const SplineFitOptions& o, double split,
                 double curvature_floor, size_t jump_count)
      : geometry(g), side(samples.side), grid(samples), options(o), s_split(split), floor(curvature_floor),
        jumps(jump_count), continued(jump_count + 1, std::vector<WheelSample>(samples.samples.size())),
        traces(jump_count, std::vector<ContinuationTrace>(2 * samples.line_jumps.size())) {}
  const WheelsetGeometry& geometry;
  WheelSide side;
  const WheelSampleGrid& grid;
  const SplineFitOptions& options;
  double s_split, floor;
  size_t jumps;
  // Per branch, its continuation past its jumps (index as WheelSampleGrid::samples).
  std::vector<std::vector<WheelSample>> continued;
  // traces[m][2 line + (dir < 0)]: jump m on the line, followed upwards (branch m) or downwards.
  std::vector<std::vector<ContinuationTrace>> traces;
  std::atomic<int> evaluations{0};

  void follow_line(int line);
  void follow_past(const TreadJump& jump, size_t b, int dir, size_t above, size_t row, double approach,
                   WheelsetPose& pose, ContinuationTrace& trace);
};

// Every jump of one line, both branches next to it.
void BranchFollower::follow_line(int line) {
  const size_t nyy = grid.y.size(), nk = grid.yaw.size();
  const size_t j = static_cast<size_t>(line) / nk, k = static_cast<size_t>(line) % nk;
  WheelsetPose pose;
  pose.z = geometry.track().nominal_radius;
  pose.roll = grid.roll[j];
  pose.yaw = grid.yaw[k];
  const size_t row = static_cast<size_t>(line) * nyy;
  const std::vector<TreadJump>& line_jumps = grid.line_jumps[static_cast<size_t>(line)];
  for (size_t m = 0; m < jumps; ++m) {
    const TreadJump& jump = line_jumps[m];
    const size_t above = static_cast<size_t>(std::upper_bound(grid.y.begin(), grid.y.end(), jump.y) - grid.y.begin());
    // The elastic contact shares the load while the two heights differ by less than the
    // approach (the mean of the samples on either side of the jump), at most the transition.
    double approach = options.transition;
    if (above > 0 && above < nyy && grid.samples[row + above].valid && grid.samples[row + above - 1].valid)
      approach = std::min(approach, 0.5 * (hertz_approach(grid.samples[row + above], options.transition_load) +
                                           hertz_approach(grid.samples[row + above - 1], options.transition_load)));
    // Branch m upwards past its upper jump, branch m + 1 downwards past its lower one.
    for (int dir : {1, -1}) {
      const size_t b = dir > 0 ? m : m + 1;
      ContinuationTrace& trace = traces[m][2 * static_cast<size_t>(line) + (dir < 0 ? 1 : 0)];
      follow_past(jump, b, dir, above, row, approach, pose, trace);
    }
  }
}

// Branch b past the jump in direction dir while it exists and its height lies less than the
// approach below the lowest minimum's (and one sample more).
void BranchFollower::follow_past(const TreadJump& jump, size_t b, int dir, size_t above, size_t row, double approach,
                                 WheelsetPose& pose, ContinuationTrace& trace) {
  const size_t nyy = grid.y.size();
  trace.approach = approach;
  double s_near = dir > 0 ? jump.s_before : jump.s_after;
  double last_gap = 0.0;
  for (size_t step = 0; step < nyy; ++step) {
    const size_t i = dir > 0 ? above + step : above - 1 - step;
    if (i >= nyy || std::abs(grid.y[i] - jump.y) > kMaxContinuation) break;
    pose.y = grid.y[i];
    ++evaluations;
    WheelSample c = sample_wheel_branch(geometry, side, pose, s_split, options.clearance_cap, floor, options.search,
                                        s_near, kContinuationShift);
    if (!c.valid) {
      // Vanished (a fold) before reaching the approach: the height difference of its last
      // sample bounds the transition. Gone at the first sample, the fold lies closer to the
      // jump than the sampling resolves, and bounds nothing.
      if (!trace.heights.empty()) trace.fold = last_gap;
      break;
    }
    s_near = c.tread.s;
    const WheelSample& own = grid.samples[row + i];
    const double gap = own.valid ? own.fields[kFieldZ] - c.fields[kFieldZ] : approach;
    continued[b][row + i] = std::move(c);
    trace.heights.emplace_back(std::abs(grid.y[i] - jump.y), gap);
    last_gap = gap;
    if (gap > approach) break;
  }
}

// The jump surface of jump m with its height half-width (the smallest approach or fold over its
// lines) and y reach (within which the two heights differ by less on some line, one sample more).
JumpSurface jump_surface(const WheelSampleGrid& grid, const SplineFitOptions& options, size_t m,
                         const std::vector<ContinuationTrace>& traces, WheelFitReport& report) {
  JumpSurface surface = fit_jump_surface(grid, m);
  double half_width = std::numeric_limits<double>::infinity(), y_reach = options.sample_step_y;
  for (const ContinuationTrace& t : traces) half_width = std::min({half_width, t.approach, t.fold});
  half_width = std::max(half_width, 1e-9);
  for (const ContinuationTrace& t : traces)
    for (const auto& [dy, gap] : t.heights)
      if (gap <= half_width) y_reach = std::max(y_reach, dy + options.sample_step_y);
  surface.height_half_width = half_width;
  surface.y_reach = y_reach;
  report.jump_half_widths.push_back({half_width, y_reach});
  return surface;
}

// The breakpoints of branch b over its basis [lo, hi], which reaches past each of its jumps as
// far as the transition needs the branch: intervals[0] intervals over its own stretch (between
// its jumps on every line), and the continuations at the same spacing (a wider transition adds
// knots rather than coarsening the branch), at most twice intervals[0] (what fit_memory_bytes()
// assumes) and at least two samples each.
std::vector<double> branch_breakpoints(const SplineFitOptions& options, const SplineBox& box,
                                       const WheelSampleGrid& grid, const std::vector<JumpSurface>& surfaces, size_t b,
                                       size_t jumps, double& lo, double& hi) {
  lo = box.y_min, hi = box.y_max;
  double own_lo = lo, own_hi = hi;
  if (b > 0) {
    own_lo = std::numeric_limits<double>::infinity();
    for (const auto& line : grid.line_jumps) own_lo = std::min(own_lo, line[b - 1].y);
    lo = std::max(box.y_min, own_lo - surfaces[b - 1].y_reach - kBranchMargin);
  }
  if (b < jumps) {
    own_hi = -std::numeric_limits<double>::infinity();
    for (const auto& line : grid.line_jumps) own_hi = std::max(own_hi, line[b].y);
    hi = std::min(box.y_max, own_hi + surfaces[b].y_reach + kBranchMargin);
  }
  const double own_span = std::max(own_hi - own_lo, 2.0 * options.sample_step_y);
  const int wanted = std::min(2 * options.intervals[0],
                              static_cast<int>(std::ceil(options.intervals[0] * (hi - lo) / own_span - 1e-9)));
  const int max_intervals = std::max(1, static_cast<int>(std::floor((hi - lo) / (2.0 * options.sample_step_y))));
  return sample_values(lo, hi, std::min(wanted, max_intervals) + 1);
}

// Per sample of one line: branch b's own value, its continuation or nothing (source), and its
// weight.
void branch_sources(const WheelSampleGrid& grid, const std::vector<WheelSample>& continued, size_t b, size_t jumps,
                    size_t line, std::vector<const WheelSample*>& source, std::vector<double>& weight) {
  const size_t nyy = grid.y.size(), row = line * nyy;
  const std::vector<TreadJump>& line_jumps = grid.line_jumps[line];
  source.assign(nyy, nullptr);
  weight.assign(nyy, 0.0);
  const WheelSample* last_valid = nullptr;
  for (size_t i = 0; i < nyy; ++i) {
    const double y = grid.y[i];
    const bool own = (b == 0 || y > line_jumps[b - 1].y) && (b == jumps || y < line_jumps[b].y);
    const WheelSample& s = grid.samples[row + i];
    if (own) {
      if (s.valid) last_valid = &s;
      source[i] = s.valid ? &s : last_valid;
      weight[i] = s.valid ? 1.0 : 0.0;
    } else if (continued[row + i].valid) {
      source[i] = &continued[row + i];
      weight[i] = kContinuationWeight;
    }
  }
}

// Filled values at sample i of a line where the branch has no sample: linear extrapolation from
// the nearest two samples of the branch on this side, into row n of values; returns the weight.
double fill_sample(const std::vector<double>& y_grid, const std::vector<const WheelSample*>& source,
                   const std::vector<double>& weight, size_t i, Eigen::MatrixXd& values, Eigen::Index n) {
  const size_t nyy = y_grid.size();
  const double y = y_grid[i];
  size_t i0 = i, i1 = i;
  for (size_t q = i + 1; q < nyy && i0 == i; ++q)
    if (source[q] && weight[q] > 0) i0 = q;
  if (i0 != i) {
    i1 = i0 + 1 < nyy && source[i0 + 1] && weight[i0 + 1] > 0 ? i0 + 1 : i0;
  } else {
    for (size_t q = i; q-- > 0 && i0 == i;)
      if (source[q] && weight[q] > 0) i0 = q;
    i1 = i0 > 0 && source[i0 - 1] && weight[i0 - 1] > 0 ? i0 - 1 : i0;
  }
  if (i0 == i) {  // the branch has no sample on this line (not expected): no weight
    for (int f = 0; f < kSplineFieldCount; ++f) values(n, f) = 0.0;
    return 0.0;
  }
  const double t = i1 == i0 ? 0.0 : (y - y_grid[i0]) / (y_grid[i0] - y_grid[i1]);
  for (int f = 0; f < kSplineFieldCount; ++f) {
    const double v0 = source[i0]->fields[static_cast<size_t>(f)], v1 = source[i1]->fields[static_cast<size_t>(f)];
    values(n, f) = v0 + t * (v0 - v1);
  }
  return kFillWeight;
}

// The samples of branch b within [lo, hi]: its own stretch, its continuations and filled values
// elsewhere.
WeightedSamples branch_samples(const WheelSampleGrid& grid, const std::vector<WheelSample>& continued, size_t b,
                               size_t jumps, double lo, double hi) {
  const size_t nyy = grid.y.size(), nk = grid.yaw.size();
  WeightedSamples samples;
  samples.dimension = 3;
  std::vector<double> weights;
  Eigen::MatrixXd values(static_cast<Eigen::Index>(grid.samples.size()), kSplineFieldCount);
  std::vector<const WheelSample*> source;
  std::vector<double> weight;
  for (size_t line = 0; line < grid.line_jumps.size(); ++line) {
    const size_t j = line / nk, k = line % nk;
    branch_sources(grid, continued, b, jumps, line, source, weight);
    for (size_t i = 0; i < nyy; ++i) {
      const double y = grid.y[i];
      if (y < lo - 1e-12 || y > hi + 1e-12) continue;
      samples.points.insert(samples.points.end(), {y, grid.roll[j], grid.yaw[k]});
      const Eigen::Index n = static_cast<Eigen::Index>(weights.size());
      if (source[i]) {
        for (int f = 0; f < kSplineFieldCount; ++f) values(n, f) = source[i]->fields[static_cast<size_t>(f)];
        weights.push_back(weight[i]);
        continue;
      }
      weights.push_back(fill_sample(grid.y, source, weight, i, values, n));
    }
  }
  samples.weights = std::move(weights);
  samples.values = values.topRows(static_cast<Eigen::Index>(samples.weights.size()));
  return samples;
}

// Branches: branch b is the tread point between jumps b - 1 and b of each line. Its samples: its
// own stretch, its continuation past each of its jumps up to the transition (and one sample
// more), followed as a non-lowest minimum while it exists, and filled values elsewhere.
void fit_branches(const WheelsetGeometry& geometry, const WheelSampleGrid& grid, const SplineFitOptions& options,
                  const SplineBox& box, double s_split, double floor, int threads, size_t jumps,
                  WheelFitReport& report, SplineWheel& wheel, SplineFit& out) {
  const size_t branches = jumps + 1;
  if (branches > static_cast<size_t>(kMaxFitBranches))
    throw std::invalid_argument("spline fit: the " + std::string(side_name(grid.side)) +
                                " wheel's tread contact point has " + std::to_string(jumps) +
                                " jumps on every sample line, " + std::to_string(branches) +
                                " branches; a fit may have at most " + std::to_string(kMaxFitBranches) +
                                " (its memory bound assumes it); --transition 0 fits once across the jumps");
  auto start = std::chrono::steady_clock::now();
  BranchFollower follower(geometry, grid, options, s_split, floor, jumps);
  for_each_line(static_cast<int>(grid.line_jumps.size()), threads, [&](int line) { follower.follow_line(line); }, {},
                0, 0, "");
  report.exact_evaluations += follower.evaluations.load();
  out.sampling_seconds += seconds_since(start);
  start = std::chrono::steady_clock::now();

  for (size_t m = 0; m < jumps; ++m) wheel.jumps.push_back(jump_surface(grid, options, m, follower.traces[m], report));
  for (size_t b = 0; b < branches; ++b) {
    double lo, hi;
    const std::vector<double> y_breaks = branch_breakpoints(options, box, grid, wheel.jumps, b, jumps, lo, hi);
    report.y_breakpoints.push_back(y_breaks);
    const WeightedSamples samples = branch_samples(grid, follower.continued[b], b, jumps, lo, hi);
    FitStatistics statistics;
    wheel.branches.push_back(fit_tensor_spline(branch_basis(options, box, y_breaks), samples, &statistics));
    report.fit.seconds += statistics.seconds;
    report.fit.coefficients += statistics.coefficients;
    report.fit.samples += statistics.samples;
    report.fit.nonzeros += statistics.nonzeros;
    report.fit.ridge = statistics.ridge;
  }
  out.fitting_seconds += seconds_since(start);
}

// Residuals of the model on its own samples of the continuous region of one wheel: weight 1 in
// the paper's form, farther than jump_band from every jump, no flange contact.
void add_residuals(const SplineContactGeometry& model, const WheelSampleGrid& grid, const SplineFitOptions& options,
                   WheelFitReport& report) {
  std::array<double, kSplineFieldCount> sum_sq{};
  SplineEvaluation e;
  for (size_t j = 0; j < grid.roll.size(); ++j) {
    for (size_t k = 0; k < grid.yaw.size(); ++k) {
      for (size_t i = 0; i < grid.y.size(); ++i) {
        const WheelSample& s = grid.at(i, j, k);
        if (!s.valid || s.flange_clearance <= 0.0 || grid.jump_distance(i, j, k) < options.jump_band) continue;
        WheelsetPose pose;
        pose.y = grid.y[i], pose.roll = grid.roll[j], pose.yaw = grid.yaw[k];
        model.evaluate(grid.side, pose, SplineDerivatives::kValue, e);
        for (int f = 0; f < kSplineFieldCount; ++f) {
          const double err = std::abs(e.value[static_cast<size_t>(f)] - s.fields[static_cast<size_t>(f)]);
          FieldError& fe = report.residuals[static_cast<size_t>(f)];
          fe.max_error = std::max(fe.max_error, err);
          sum_sq[static_cast<size_t>(f)] += err * err;
          ++fe.samples;
        }
      }
    }
  }
  for (int f = 0; f < kSplineFieldCount; ++f) {
    FieldError& fe = report.residuals[static_cast<size_t>(f)];
    if (fe.samples > 0) fe.rms_error = std::sqrt(sum_sq[static_cast<size_t>(f)] / fe.samples);
  }
}

}  // namespace

SplineFit fit_spline_geometry(const WheelsetGeometry& geometry, const SplineFitOptions& options,
                              const FitProgress& progress) {
  options.validate();
  SplineFit out;
  const double s_split = flange_split(geometry.wheel_profile(), options.flange_angle);
  const int threads = thread_count(options.threads);
  const SplineBox left_box{options.y_min, options.y_max, options.roll_max, options.yaw_max};
  const int ny = options.y_samples();
  const long lines = static_cast<long>(options.roll_samples) * options.yaw_samples;
  const double floor = ContactModelOptions{}.lateral_curvature_floor;
  std::array<SplineWheel, 2> wheels;

  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    // Sample the wheel, count its samples, then fit once across its jumps or per branch.
    const int w = static_cast<int>(side);
    const SplineBox box = side == WheelSide::kLeft ? left_box : left_box.mirrored();
    auto start = std::chrono::steady_clock::now();
    WheelSampleGrid grid = sample_wheel_grid(
        geometry, side, sample_values(box.y_min, box.y_max, ny),
        sample_values(-box.roll_max, box.roll_max, options.roll_samples),
        sample_values(-box.yaw_max, box.yaw_max, options.yaw_samples), options, s_split, threads, progress,
        w * lines, 2 * lines);
    out.sampling_seconds += seconds_since(start);

    WheelFitReport& report = out.wheels[static_cast<size_t>(w)];
    count_samples(grid, options, report);
    const size_t jumps = options.transition > 0.0 && options.y_breakpoints.empty() ? common_jump_count(grid) : 0;
    SplineWheel& wheel = wheels[static_cast<size_t>(w)];
    report.across_jumps = jumps == 0;
    if (jumps == 0) {
      start = std::chrono::steady_clock::now();
      fit_across_jumps(grid, options, box, side, lines, report, wheel);
      out.fitting_seconds += seconds_since(start);
    } else {
      fit_branches(geometry, grid, options, box, s_split, floor, threads, jumps, report, wheel, out);
    }
    out.samples[static_cast<size_t>(w)] = std::make_shared<const WheelSampleGrid>(std::move(grid));
  }
  out.model = std::make_shared<const SplineContactGeometry>(std::move(wheels), left_box, s_split, floor);

  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight})
    add_residuals(*out.model, *out.samples[static_cast<size_t>(side)], options, out.wheels[static_cast<size_t>(side)]);
  return out;
}

std::string across_jumps_note(const SplineFit& fit, const SplineFitOptions& options) {
  if (!(options.transition > 0.0) || !options.y_breakpoints.empty()) return {};
  std::string note;
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const WheelFitReport& r = fit.wheels[static_cast<size_t>(side)];
    if (!r.across_jumps || r.fewest_line_jumps == r.most_line_jumps) continue;
    if (!note.empty()) note += "\n";
    note += std::string("spline fit: the ") + (side == WheelSide::kLeft ? "left" : "right") +
            " wheel's sample lines hold " + std::to_string(r.fewest_line_jumps) + " to " +
            std::to_string(r.most_line_jumps) +
            " tread jumps (the box's roll and yaw move jumps in and out of it), so it is fitted once across "
            "its jumps, which smooths the tread's local conicity near them (a linear critical speed may move "
            "by tens of percent); a smaller roll or yaw range keeps the branch fits";
  }
  return note;
}

}  // namespace wrc
