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

#include "core/models/contact_model_options.hpp"

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

SplineFit fit_spline_geometry(const WheelsetGeometry& geometry, const SplineFitOptions& options,
                              const FitProgress& progress) {
  options.validate();
  SplineFit out;
  const double s_split = flange_split(geometry.wheel_profile(), options.flange_angle);
  const int threads = thread_count(options.threads);
  const SplineBox left_box{options.y_min, options.y_max, options.roll_max, options.yaw_max};
  const int ny = options.y_samples();
  const long lines = static_cast<long>(options.roll_samples) * options.yaw_samples;
  std::vector<TensorSplineSet> sets;

  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const int w = static_cast<int>(side);
    const SplineBox box = side == WheelSide::kLeft ? left_box : left_box.mirrored();
    auto start = std::chrono::steady_clock::now();
    WheelSampleGrid grid = sample_wheel_grid(
        geometry, side, sample_values(box.y_min, box.y_max, ny),
        sample_values(-box.roll_max, box.roll_max, options.roll_samples),
        sample_values(-box.yaw_max, box.yaw_max, options.yaw_samples), options, s_split, threads, progress,
        w * lines, 2 * lines);
    out.sampling_seconds += seconds_since(start);
    start = std::chrono::steady_clock::now();

    WheelFitReport& report = out.wheels[static_cast<size_t>(w)];
    for (const auto& line : grid.line_jumps) report.jumps.insert(report.jumps.end(), line.begin(), line.end());
    report.exact_evaluations = grid.exact_evaluations;
    std::vector<double> y_breaks;
    if (!options.y_breakpoints.empty() && side == WheelSide::kRight) {
      for (auto it = options.y_breakpoints.rbegin(); it != options.y_breakpoints.rend(); ++it) y_breaks.push_back(-*it);
    } else {
      y_breaks = place_y_breakpoints(options, box, report.jumps, static_cast<int>(lines));
    }
    report.y_breakpoints = y_breaks;
    TensorBasis basis({BSplineBasis(options.degrees[0], y_breaks),
                       BSplineBasis::uniform(options.degrees[1], -box.roll_max, box.roll_max, options.intervals[1]),
                       BSplineBasis::uniform(options.degrees[2], -box.yaw_max, box.yaw_max, options.intervals[2])});

    // Weighted samples: jump_weight near a tread jump, 0 where no tread point exists (values of
    // the previous valid sample on the line, so the ridge has nothing to pull towards 0).
    WeightedSamples samples;
    samples.dimension = 3;
    const size_t count = grid.samples.size();
    samples.points.reserve(3 * count);
    samples.weights.reserve(count);
    samples.values.resize(static_cast<Eigen::Index>(count), kSplineFieldCount);
    std::vector<char> continuous(count, 0);
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
            ++report.samples_near_jumps;
          }
          if (s.valid) last_valid = &s;
          const WheelSample* source = s.valid ? &s : last_valid;
          for (int f = 0; f < kSplineFieldCount; ++f)
            samples.values(static_cast<Eigen::Index>(n), f) = source ? source->fields[static_cast<size_t>(f)] : 0.0;
          samples.weights.push_back(weight);
          if (s.valid && s.flange_clearance <= 0.0) ++report.samples_in_flange_contact;
          continuous[n] = weight == 1.0 && s.valid && s.flange_clearance > 0.0;
        }
      }
    }
    report.samples = static_cast<int>(count);
    TensorSplineSet set = fit_tensor_spline(basis, samples, &report.fit);

    // Residuals on the continuous region's own samples.
    std::array<double, kSplineFieldCount> sum_sq{};
    TensorBasisPoint point;
    std::array<double, kSplineFieldCount> value{};
    for (size_t m = 0; m < count; ++m) {
      if (!continuous[m]) continue;
      basis.evaluate(&samples.points[3 * m], SplineDerivatives::kValue, point);
      set.values(point, value.data());
      for (int f = 0; f < kSplineFieldCount; ++f) {
        const double e = std::abs(value[static_cast<size_t>(f)] - samples.values(static_cast<Eigen::Index>(m), f));
        FieldError& fe = report.residuals[static_cast<size_t>(f)];
        fe.max_error = std::max(fe.max_error, e);
        sum_sq[static_cast<size_t>(f)] += e * e;
        ++fe.samples;
      }
    }
    for (int f = 0; f < kSplineFieldCount; ++f) {
      FieldError& fe = report.residuals[static_cast<size_t>(f)];
      if (fe.samples > 0) fe.rms_error = std::sqrt(sum_sq[static_cast<size_t>(f)] / fe.samples);
    }
    sets.push_back(std::move(set));
    out.fitting_seconds += seconds_since(start);
    out.samples[static_cast<size_t>(w)] = std::make_shared<const WheelSampleGrid>(std::move(grid));
  }
  out.model = std::make_shared<const SplineContactGeometry>(std::move(sets), left_box, s_split,
                                                            ContactModelOptions{}.lateral_curvature_floor);
  return out;
}

}  // namespace wrc
