// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/rigid_wheelset.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace wrc {
namespace {

std::vector<double> minima_of(const std::vector<ContactPoint>& points) {
  std::vector<double> s;
  for (const auto& p : points)
    if (p.is_minimum) s.push_back(p.s);
  return s;
}

[[noreturn]] void no_contact(double y, double yaw, WheelSide side) {
  std::ostringstream msg;
  msg << "no contact between the " << side_name(side) << " wheel and its rail at y = " << y
      << " m, yaw = " << yaw << " rad (wheel off the rail or beyond flange climb)";
  throw std::runtime_error(msg.str());
}

constexpr WheelSide kSides[2] = {WheelSide::kLeft, WheelSide::kRight};

// The search for the roll angle at one (y, yaw): the minima tracked per wheel and the result
// with its counters.
struct RollSearch {
  const WheelsetGeometry& geometry;
  const RigidSolverOptions& options;
  double y, yaw;
  std::array<std::vector<double>, 2> seeds;
  RigidContact result;

  // The pose at roll phi (z = 0: distances are affine in z with unit slope).
  WheelsetPose pose_at(double phi) const {
    WheelsetPose p;
    p.y = y;
    p.yaw = yaw;
    p.roll = phi;
    return p;
  }
  // Every potential point of wheel w at roll phi.
  std::vector<ContactPoint> scan(int w, double phi) {
    ++result.scans;
    return geometry.potential_points(kSides[w], pose_at(phi), options.search);
  }
  // Seeds for a cold start: the minima below the lowest of a coarse sampling of the distance
  // (the global minimum is among them).
  std::vector<double> seed(int w, double phi) {
    ++result.scans;
    std::vector<double> s;
    if (auto c = geometry.common_point(kSides[w], pose_at(phi), options.search)) s.push_back(c->s);
    return s;
  }
  // Seeds of a wheel without a neighbour's minima; no contact when none is found.
  void seed_cold(double roll) {
    for (int w = 0; w < 2; ++w) {
      if (seeds[w].empty()) seeds[w] = options.all_potential_points ? minima_of(scan(w, roll)) : seed(w, roll);
      if (seeds[w].empty()) no_contact(y, yaw, kSides[w]);
    }
  }
  // Minimum distance of wheel w over its tracked local minima at roll phi (z = 0).
  double min_distance(int w, double phi) {
    const ContactLocus locus = geometry.locus(kSides[w], pose_at(phi));
    double best = std::numeric_limits<double>::infinity();
    std::vector<double> kept;
    for (double s : seeds[w]) {
      if (auto m = track_minimum(locus, s, 5e-3, options.search.tolerance)) {
        if (!kept.empty() && std::fabs(kept.back() - m->s) < 1e-9) continue;
        kept.push_back(m->s);
        best = std::min(best, m->distance);
      }
    }
    if (kept.empty()) {
      kept = minima_of(find_potential_points(locus, options.search));
      ++result.scans;
      for (double s : kept) best = std::min(best, locus.at(s).distance);
      if (kept.empty()) no_contact(y, yaw, kSides[w]);
    }
    seeds[w] = kept;
    return best;
  }
  // Roll residual g(phi) = min distance left - min distance right; g increases with phi
  // (about 2 * taping half-distance per radian).
  double residual(double phi) {
    ++result.roll_iterations;
    return min_distance(0, phi) - min_distance(1, phi);
  }
  double settle_roll(double roll, double slope_guess);
  bool verify(double roll, double (&z_side)[2]);
  void finish(double roll, const double (&z_side)[2]);
};

// The root of the residual from roll: safeguarded secant (regula falsi with Illinois
// modification once bracketed).
double RollSearch::settle_roll(double roll, double slope_guess) {
  double a = roll, ga = residual(a);
  double b = a - ga / slope_guess, gb = residual(b);
  bool bracketed = (ga < 0) != (gb < 0);
  for (int it = 0; it < options.max_iterations && std::fabs(gb) > options.height_tolerance; ++it) {
    double next;
    if (gb != ga) next = b - gb * (b - a) / (gb - ga);
    else next = b - gb / slope_guess;
    if (bracketed && !(next > std::min(a, b) && next < std::max(a, b))) next = 0.5 * (a + b);
    const double gn = residual(next);
    if (bracketed) {
      if ((gn < 0) == (gb < 0)) {
        ga *= 0.5;  // Illinois: keep a, shrink its weight
      } else {
        a = b;
        ga = gb;
      }
    } else {
      a = b;
      ga = gb;
      bracketed = (ga < 0) != (gn < 0);
    }
    b = next;
    gb = gn;
    if (std::fabs(b - a) < 1e-15) break;
  }
  return b;
}

// Verification: the tracked minima must include the global minimum of each wheel (false: the
// seeds are reset to the minima found). z_side receives each wheel's touching height [m].
bool RollSearch::verify(double roll, double (&z_side)[2]) {
  bool complete = true;
  for (int w = 0; w < 2; ++w) {
    const double tracked = min_distance(w, roll);
    if (options.all_potential_points) {
      result.potential[w] = scan(w, roll);
    } else {
      ++result.scans;
      result.potential[w] = find_minima_below(geometry.locus(kSides[w], pose_at(roll)), tracked + 1e-9, options.search);
    }
    auto common = select_common_point(result.potential[w], 0.0);
    if (!common) no_contact(y, yaw, kSides[w]);
    if (common->distance < tracked - 1e-11) {
      complete = false;
      seeds[w] = minima_of(result.potential[w]);
    }
    z_side[w] = -common->distance;
  }
  return complete;
}

// The result at the verified roll: its pose, the points at that height and the common points
// (an error when a flange has climbed beyond its apex).
void RollSearch::finish(double roll, const double (&z_side)[2]) {
  result.pose = pose_at(roll);
  result.pose.z = 0.5 * (z_side[0] + z_side[1]);
  for (int w = 0; w < 2; ++w) {
    for (auto& p : result.potential[w]) {
      p.distance += result.pose.z;
      p.wheel_point.z() += result.pose.z;
    }
    result.contact[w] = *select_common_point(result.potential[w]);
    if (geometry.beyond_flange_apex(result.contact[w])) {
      std::ostringstream msg;
      msg << "the " << side_name(kSides[w]) << " wheel's flange has climbed onto the rail at y = " << y
          << " m, yaw = " << yaw << " rad (contact at s = " << result.contact[w].s << " m, beyond the flange apex)";
      throw std::runtime_error(msg.str());
    }
  }
}

}  // namespace

RigidWheelsetSolver::RigidWheelsetSolver(const WheelsetGeometry& geometry, RigidSolverOptions options)
    : geometry_(geometry), options_(options) {}

RigidContact RigidWheelsetSolver::solve(double y, double yaw) const {
  return solve_from(y, yaw, 0.0, {});
}

RigidContact RigidWheelsetSolver::solve(double y, double yaw, const RigidContact& neighbour) const {
  return solve_from(y, yaw, neighbour.pose.roll, {minima_of(neighbour.potential[0]), minima_of(neighbour.potential[1])});
}

RigidContact RigidWheelsetSolver::solve_from(double y, double yaw, double roll,
                                             std::array<std::vector<double>, 2> seeds) const {
  if (!std::isfinite(y) || !std::isfinite(yaw) || !std::isfinite(roll)) {
    std::ostringstream msg;
    msg << "rigid wheelset: non-finite input y = " << y << " m, yaw = " << yaw << " rad";
    throw std::invalid_argument(msg.str());
  }
  RollSearch search{geometry_, options_, y, yaw, std::move(seeds), {}};
  search.seed_cold(roll);
  const double slope_guess = 2 * geometry_.track().taping_half_distance();
  for (int round = 0; round < 8; ++round) {
    roll = search.settle_roll(roll, slope_guess);
    double z_side[2];
    if (!search.verify(roll, z_side)) continue;
    search.finish(roll, z_side);
    return std::move(search.result);
  }
  std::ostringstream msg;
  msg << "rigid wheelset: roll iteration did not settle at y = " << y << " m, yaw = " << yaw << " rad";
  throw std::runtime_error(msg.str());
}

}  // namespace wrc
