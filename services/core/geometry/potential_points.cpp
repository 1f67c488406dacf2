// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/potential_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/numerics/brent.hpp"

namespace wrc {
namespace {

struct Sample {
  double s;
  double slope;  // d(distance)/ds, NaN when not over the rail
};

// Golden-section search for the extremum of sign * f in [a, b] (a minimum of sign * f).
template <class F>
Sample golden_extremum(F&& f, double a, double b, double sign, int iterations) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), d = a + r * (b - a);
  double fc = sign * f(c), fd = sign * f(d);
  for (int i = 0; i < iterations; ++i) {
    if (std::isnan(fc) || std::isnan(fd)) break;
    if (fc < fd) {
      b = d; d = c; fd = fc;
      c = b - r * (b - a); fc = sign * f(c);
    } else {
      a = c; c = d; fc = fd;
      d = a + r * (b - a); fd = sign * f(d);
    }
  }
  const double s = fc < fd ? c : d;
  return {s, f(s)};
}

}  // namespace

ContactPoint make_contact_point(const ContactLocus& locus, double s, bool is_minimum) {
  const LocusPoint p = locus.at(s);
  const ProfileSample f = locus.wheel_profile().evaluate(p.s);
  const double sigma = side_sign(locus.side());
  ContactPoint c;
  c.side = locus.side();
  c.s = p.s;
  c.s_rail = p.rail.u;
  c.theta = std::atan2(p.sin_theta, p.cos_theta);
  c.wheel_point = p.wheel;
  c.rail_point = Eigen::Vector3d(p.wheel.x(), p.wheel.y(), p.rail.z);
  c.normal = -locus.wheel_normal(p, f.slope);
  c.distance = p.distance;
  c.contact_angle = std::atan(sigma * p.rail.slope);
  c.rolling_radius = p.radius;
  const double w = 1 + f.slope * f.slope;
  c.wheel_curvature_lateral = -f.second_derivative / (w * std::sqrt(w));
  c.wheel_curvature_rolling = 1.0 / (p.radius * std::sqrt(w));
  c.rail_curvature_lateral = locus.rail().curvature_at(p.rail.u);
  c.rail_curvature_rolling = 0.0;
  const double h = 1e-6;
  c.distance_curvature = (locus.distance_slope(p.s + h) - locus.distance_slope(p.s - h)) / (2 * h);
  c.is_minimum = is_minimum;
  return c;
}

namespace {

struct ScanSample {
  double s;
  double slope;             // d(distance)/ds, NaN when not over the rail
  double distance;          // distance (only when the scan certifies a level)
  bool clear_after = false; // no distance below the level between this sample and the next
};

// Buffers of one scan, kept per thread so that a scan allocates nothing once they have grown.
struct ScanScratch {
  std::vector<ScanSample> samples;
  std::vector<double> breaks;
  std::vector<double> block_bounds;
};

ScanScratch& scan_scratch() {
  thread_local ScanScratch scratch;
  return scratch;
}

// Samples d(distance)/ds along C into `samples`. Adaptive: no root lies within |g| / max|g'| of a
// sample with value g. With a finite level, a step may also be as long as the distance provably
// stays above the level (quadratic lower bound d - |g| h - M h^2 / 2), and such intervals are
// marked clear.
void sample_locus(const ContactLocus& locus, const PotentialPointSearch& search, double level,
                  ScanScratch& scratch) {
  std::vector<ScanSample>& samples = scratch.samples;
  samples.clear();
  const double lo = locus.s_lower(), hi = locus.s_upper();
  if (!(hi > lo)) return;
  const bool certify = std::isfinite(level);

  // Breakpoints of both profiles: the distance's curvature may jump there, so a pair of roots can
  // hide in a kink between two samples. They are always sampled, as are the edges of the rail
  // surface (so that no stretch next to an edge goes unsampled).
  std::vector<double>& breaks = scratch.breaks;
  breaks.clear();
  for (double b : locus.wheel_profile().breakpoints())
    if (b > lo && b < hi) breaks.push_back(b);
  for (double y : locus.rail().surface_breaks()) {
    const double s = locus.s_at_lateral(y);
    if (s > lo && s < hi) breaks.push_back(s);
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.push_back(hi);

  const bool adaptive = locus.distance_curvature_bound(lo, lo + search.step) > 0;
  const double long_step = 10 * search.step;
  // Bounds of |d2 distance/ds2| per block of two steps; a window's bound is the largest of its blocks.
  const double block = 2 * search.step;
  const int blocks = static_cast<int>(std::ceil((hi - lo) / block)) + 1;
  std::vector<double>& block_bounds = scratch.block_bounds;  // computed when first needed
  block_bounds.assign(adaptive ? blocks : 0, -1.0);
  auto window_bound = [&](double a, double b) {
    const int i0 = std::clamp(static_cast<int>((a - lo) / block), 0, blocks - 1);
    const int i1 = std::clamp(static_cast<int>((b - lo) / block), 0, blocks - 1);
    double m = 0;
    for (int i = i0; i <= i1; ++i) {
      if (block_bounds[i] < 0)
        block_bounds[i] = locus.distance_curvature_bound(lo + i * block, lo + (i + 1) * block);
      m = std::max(m, block_bounds[i]);
    }
    return m;
  };
  double s = lo;
  size_t next_break = 0;
  while (true) {
    ScanSample x{s, 0.0, 0.0, false};
    if (certify) {
      locus.distance_and_slope(s, x.distance, x.slope);
    } else {
      x.slope = locus.distance_slope(s);
    }
    const double g = x.slope;
    if (s >= hi) {
      samples.push_back(x);
      break;
    }
    double h = search.step;
    if (adaptive && !std::isnan(g)) {
      h = std::clamp(std::fabs(g) / window_bound(s, s + search.step), search.min_step, search.step);
      const double excess = x.distance - level;
      if (certify && excess > 0) {
        // Longest step over which the lower bound d + g t - M t^2 / 2 stays above the level, with
        // M bounding |d2 distance/ds2| over the step: first over two steps, then, if the step
        // reaches beyond, over the longer window (the step never leaves the window it was bounded on).
        auto reach = [&](double m) { return (g + std::sqrt(g * g + 2 * m * excess)) / m; };
        double window = 2 * search.step;
        double t = std::min(window, reach(window_bound(s, s + window)));
        if (t >= window) {
          window = long_step;
          t = std::max(t, std::min(window, reach(window_bound(s, s + window))));
        }
        if (t > h) {
          h = t;
          x.clear_after = true;
        }
      }
    }
    double next = s + h;
    while (next_break < breaks.size() && breaks[next_break] <= s) ++next_break;
    if (next_break < breaks.size() && breaks[next_break] < next + 0.25 * search.min_step) next = breaks[next_break];
    s = std::min(next, hi);
    samples.push_back(x);
  }
}

// Zeros of d(distance)/ds between samples (sign changes, and pairs found by the tangency check).
// Intervals marked clear are skipped; with only_minima, maxima are not refined.
std::vector<ContactPoint> roots_of(const ContactLocus& locus, const std::vector<ScanSample>& samples,
                                   const PotentialPointSearch& search, bool only_minima) {
  std::vector<ContactPoint> points;
  auto slope = [&](double s) { return locus.distance_slope(s); };
  auto valid = [](const ScanSample& x) { return !std::isnan(x.slope); };
  auto add_root = [&](double a, double b, double fa, double fb) {
    // Distance decreasing before the root and increasing after it: a local minimum.
    const bool minimum = fa < fb;
    if (only_minima && !minimum) return;
    const RootResult r = brent_root(slope, a, b, fa, fb, search.tolerance);
    // A zero not located to the tolerance would be a potential point in the wrong place or a
    // missed one: the search fails loudly rather than return an uncertified set.
    require_converged(r, "potential points: zero of d(distance)/ds");
    // With yaw, d(distance)/ds jumps at wheel curvature breakpoints (theta' follows F''); a sign
    // change across such a jump is no zero. A true root located to the tolerance leaves
    // |slope| <= tolerance * max|d2 distance/ds2|, far below 1e-6.
    if (!(std::fabs(r.fx) < 1e-6)) return;
    if (!points.empty() && std::fabs(points.back().s - r.x) < 10 * search.tolerance) return;
    points.push_back(make_contact_point(locus, r.x, minimum));
  };

  for (size_t k = 0; k + 1 < samples.size(); ++k) {
    const ScanSample& a = samples[k];
    const ScanSample& b = samples[k + 1];
    if (!valid(a) || !valid(b) || a.clear_after) continue;
    if (a.slope == 0) {
      const double h = 1e-9;
      const double left = slope(a.s - h), right = slope(a.s + h);
      if (!std::isnan(left) && !std::isnan(right)) add_root(a.s - h, a.s + h, left, right);
      continue;
    }
    if ((a.slope < 0) != (b.slope < 0) && b.slope != 0) {
      add_root(a.s, b.s, a.slope, b.slope);
      continue;
    }
    // Tangency check: a local extremum of the slope between samples may reach zero and hide a
    // pair of roots. Fit a parabola through three samples and look closer where it comes near zero.
    if (k == 0 || !valid(samples[k - 1])) continue;
    const ScanSample& p = samples[k - 1];
    const double sign = a.slope > 0 ? 1.0 : -1.0;
    if (sign * a.slope > sign * p.slope || sign * a.slope > sign * b.slope) continue;
    if ((p.slope < 0) != (a.slope < 0)) continue;
    const double h1 = a.s - p.s, h2 = b.s - a.s;
    const double d1 = (a.slope - p.slope) / h1, d2 = (b.slope - a.slope) / h2;
    const double curv = 2 * (d2 - d1) / (h1 + h2);
    double vertex = a.slope;
    if (curv != 0) {
      const double slope_at_a = (d1 * h2 + d2 * h1) / (h1 + h2);
      vertex = a.slope - slope_at_a * slope_at_a / (2 * curv);
    }
    if (sign * vertex > 0.5 * sign * a.slope) continue;
    const Sample e = golden_extremum(slope, p.s, b.s, sign, 60);
    if (std::isnan(e.slope) || (e.slope < 0) == (a.slope < 0)) continue;
    // Two roots: [p, e] and [e, b] (the one in [p, a] may already have been added).
    if (points.empty() || points.back().s < p.s) add_root(p.s, e.s, p.slope, e.slope);
    add_root(e.s, b.s, e.slope, b.slope);
  }
  std::sort(points.begin(), points.end(), [](const ContactPoint& x, const ContactPoint& y) { return x.s < y.s; });
  return points;
}

}  // namespace

double highest_distance_between(const ContactLocus& locus, double s0, double s1) {
  // 60 golden sections shrink [s0, s1] (at most a few centimetres) below 1e-12 m.
  bool off_rail = false;
  auto distance = [&](double s) {
    const double d = locus.at(s).distance;
    off_rail = off_rail || std::isnan(d);
    return d;
  };
  const double s_top = golden_extremum(distance, s0, s1, -1.0, 60).s;
  const double top = distance(s_top);
  return off_rail ? std::numeric_limits<double>::quiet_NaN() : top;
}

std::vector<ContactPoint> find_potential_points(const ContactLocus& locus, const PotentialPointSearch& search) {
  ScanScratch& scratch = scan_scratch();
  sample_locus(locus, search, std::numeric_limits<double>::infinity(), scratch);
  return roots_of(locus, scratch.samples, search, false);
}

std::vector<ContactPoint> find_minima_below(const ContactLocus& locus, double level, const PotentialPointSearch& search) {
  ScanScratch& scratch = scan_scratch();
  sample_locus(locus, search, level, scratch);
  std::vector<ContactPoint> minima = roots_of(locus, scratch.samples, search, true);
  minima.erase(std::remove_if(minima.begin(), minima.end(), [&](const ContactPoint& p) { return !(p.distance < level); }),
               minima.end());
  return minima;
}

std::optional<LocusPoint> track_minimum(const ContactLocus& locus, double s_guess, double max_shift, double tolerance) {
  auto slope = [&](double s) { return locus.distance_slope(s); };
  // Newton with a forward-difference derivative: the minimum moves little between neighbouring
  // configurations, so this converges in a few steps; anything unusual falls back to bracketing.
  {
    double s = s_guess, g = slope(s);
    for (int it = 0; it < 8 && !std::isnan(g); ++it) {
      const double h = 1e-7;
      const double curvature = (slope(s + h) - g) / h;
      if (!(curvature > 0)) break;  // not (or no longer) a minimum here
      const double step = -g / curvature;
      s += step;
      if (std::fabs(s - s_guess) > max_shift) break;
      // The difference quotient is exact to ~1e-5 relative, so after a step below 1e-8 m the
      // remaining error is ~1e-13 m: below the root tolerance without another evaluation.
      if (std::fabs(step) < std::max(tolerance, 1e-8)) return locus.at(s);
      g = slope(s);
    }
  }
  // Grow a bracket [a, b] around s_guess with slope(a) < 0 < slope(b).
  double h = 2e-5;
  double a = s_guess, b = s_guess;
  double fa = slope(a), fb = fa;
  if (std::isnan(fa)) return std::nullopt;
  while (h <= max_shift) {
    if (fa >= 0) {
      const double next = std::max(locus.s_lower(), s_guess - h);
      const double fn = slope(next);
      if (std::isnan(fn)) return std::nullopt;
      if (fn < 0) { b = a; fb = fa; a = next; fa = fn; break; }
      a = next; fa = fn;
    } else if (fb <= 0) {
      const double next = std::min(locus.s_upper(), s_guess + h);
      const double fn = slope(next);
      if (std::isnan(fn)) return std::nullopt;
      if (fn > 0) { a = b; fa = fb; b = next; fb = fn; break; }
      b = next; fb = fn;
    }
    h *= 2;
  }
  if (!(fa < 0 && fb >= 0)) return std::nullopt;
  // The bracket may hold several roots after growing; Brent returns one of them. Accept it only if
  // the distance is a local minimum there.
  const RootResult r = brent_root(slope, a, b, fa, fb, tolerance);
  // Not located to the tolerance: no tracked minimum (RigidWheelsetSolver then drops this seed,
  // re-scans when none is left, and its final certifying scan finds any minimum missed).
  if (!r.converged) return std::nullopt;
  const double step = 1e-7;
  const double left = slope(r.x - step), right = slope(r.x + step);
  if (!(left <= 0 && right >= 0)) return std::nullopt;
  return locus.at(r.x);
}

std::optional<ContactPoint> select_common_point(const std::vector<ContactPoint>& points, double tie_tolerance) {
  std::optional<ContactPoint> best;
  for (const auto& p : points) {
    if (!p.is_minimum) continue;
    if (!best || p.distance < best->distance - tie_tolerance ||
        (std::fabs(p.distance - best->distance) <= tie_tolerance && p.s > best->s)) {
      best = p;
    }
  }
  return best;
}

}  // namespace wrc
