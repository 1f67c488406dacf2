// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/placed_rail.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/numerics/brent.hpp"

namespace wrc {
namespace {
constexpr int kScanSamples = 4000;
constexpr int kTableNodes = 4096;
// Steepest rail face (track frame) kept in the surface graph z(y): tan(80.5 deg). A wheel flange
// (S1002: 70 deg, plus roll) never touches steeper faces; they would only make z(y) ill-conditioned.
constexpr double kMaxRailSlope = 6.0;
}  // namespace

PlacedRail::PlacedRail(ProfilePtr rail, const TrackParameters& track, WheelSide side)
    : rail_(std::move(rail)), side_(side), side_sign_(side_sign(side)) {
  if (!rail_) throw std::invalid_argument("PlacedRail: no rail profile");
  if (rail_->side() != ProfileSide::kRail)
    throw std::invalid_argument("profile '" + rail_->name() + "' is a wheel profile, a rail profile is needed");
  track.validate();
  alpha_ = track.inclination - rail_->built_in_cant();
  cos_ = std::cos(alpha_);
  sin_ = std::sin(alpha_);

  const double lo = rail_->lower(), hi = rail_->upper();
  const double du = (hi - lo) / kScanSamples;
  find_top_of_rail(lo, hi, du);      // top of rail: the highest point of the inclined profile
  find_surface_range(lo, hi, du);    // the rail surface seen from above
  place_gauge_point(track, lo, du);  // the gauge point at |y| = gauge / 2 places the profile
  build_inverse_table();             // u(y) for the Newton start, and the lateral extent
  build_envelope_and_breaks();       // the step-size bounds and curvature breaks
}

// Rail-local profile rotated by the inclination (before the shift to z = 0).
double PlacedRail::inclined_height(double u) const { return u * sin_ + rail_->evaluate(u).height * cos_; }

// Its derivative dz/du.
double PlacedRail::inclined_slope(double u) const { return sin_ + rail_->evaluate(u).slope * cos_; }

// Part of the rail surface graph: y(u) increasing and |dz/dy| <= kMaxRailSlope.
bool PlacedRail::on_surface(double u) const {
  const double v1 = rail_->evaluate(u).slope;
  const double dy = cos_ - v1 * sin_, dz = sin_ + v1 * cos_;
  return dy > 0 && std::fabs(dz) <= kMaxRailSlope * dy;
}

// The highest of kScanSamples + 1 samples, refined to the root of dz/du between its neighbours.
void PlacedRail::find_top_of_rail(double lo, double hi, double du) {
  int best = 0;
  double best_z = -1e300;
  for (int i = 0; i <= kScanSamples; ++i) {
    const double z = inclined_height(lo + i * du);
    if (z > best_z) {
      best_z = z;
      best = i;
    }
  }
  u_top_ = lo + best * du;
  {
    auto dz_du = [&](double u) { return inclined_slope(u); };
    const double a = std::max(lo, u_top_ - du), b = std::min(hi, u_top_ + du);
    const double fa = dz_du(a), fb = dz_du(b);
    if (fa > 0 && fb < 0) {
      u_top_ = require_converged(brent_root(dz_du, a, b, fa, fb, 1e-13),
                                 "rail profile '" + rail_->name() + "': highest point");
    }
  }
  z0_ = -inclined_height(u_top_);
}

// From the top of rail outwards in steps of du while the profile stays on the surface graph.
void PlacedRail::find_surface_range(double lo, double hi, double du) {
  u_lower_ = u_top_;
  while (u_lower_ - du >= lo && on_surface(u_lower_ - du)) u_lower_ -= du;
  u_upper_ = u_top_;
  while (u_upper_ + du <= hi && on_surface(u_upper_ + du)) u_upper_ += du;
}

// Gauge point: innermost point of the head between the top of rail and gauge_depth below it,
// searched over the whole gauge side where y(u) still increases (steep faces included).
void PlacedRail::place_gauge_point(const TrackParameters& track, double lo, double du) {
  double u_gauge_side = u_top_;
  while (u_gauge_side - du >= lo && cos_ - rail_->evaluate(u_gauge_side - du).slope * sin_ > 0) u_gauge_side -= du;
  auto depth = [&](double u) { return inclined_height(u) + z0_ + track.gauge_depth; };
  double u_gauge = u_top_;
  if (track.gauge_depth > 0) {
    if (depth(u_gauge_side) > 0) {
      std::ostringstream msg;
      msg << "rail profile '" << rail_->name() << "' does not reach " << track.gauge_depth
          << " m below its top on the gauge side: no gauge point";
      throw std::invalid_argument(msg.str());
    }
    u_gauge = require_converged(brent_root(depth, u_gauge_side, u_top_, depth(u_gauge_side), depth(u_top_), 1e-13),
                                "rail profile '" + rail_->name() + "': gauge point");
  }
  double inner = u_gauge * cos_ - rail_->evaluate(u_gauge).height * sin_;
  for (int i = 0; i <= 200; ++i) {
    const double u = u_gauge + (u_top_ - u_gauge) * i / 200.0;
    inner = std::min(inner, u * cos_ - rail_->evaluate(u).height * sin_);
  }
  axis_ = 0.5 * track.gauge - inner;
  gauge_point_y_ = side_sign_ * 0.5 * track.gauge;
}

// Inverse table u(y) on uniform y nodes, for a direct-indexed starting value of the Newton solve,
// and the surface's lateral extent in the track frame.
void PlacedRail::build_inverse_table() {
  const double y_first = local_y(u_lower_, rail_->evaluate(u_lower_).height);
  const double y_last = local_y(u_upper_, rail_->evaluate(u_upper_).height);
  table_y0_ = y_first;
  table_dy_ = (y_last - y_first) / (kTableNodes - 1);
  table_u_.assign(kTableNodes, 0.0);
  table_u_.front() = u_lower_;
  table_u_.back() = u_upper_;
  double guess = u_lower_;
  for (int i = 1; i + 1 < kTableNodes; ++i) {
    const double target = y_first + table_dy_ * i;
    // Bracketed Newton from the previous node (y(u) is increasing on [u_lower_, u_upper_]).
    double a = guess, b = u_upper_, u = guess;
    for (int iter = 0; iter < 100; ++iter) {
      const ProfileSample p = rail_->evaluate(u);
      const double f = local_y(u, p.height) - target;
      if (f > 0) b = u; else a = u;
      double next = u - f / (cos_ - p.slope * sin_);
      if (!(next >= a && next <= b)) next = 0.5 * (a + b);
      if (std::fabs(next - u) < 1e-15 || b - a < 1e-15) { u = next; break; }
      u = next;
    }
    table_u_[i] = u;
    guess = u;
  }
  table_du_.resize(kTableNodes);
  for (int i = 0; i < kTableNodes; ++i)
    table_du_[i] = table_dy_ / (cos_ - rail_->evaluate(table_u_[i]).slope * sin_);  // du/dy * dy
  table_y_last_ = y_last;
  if (side_sign_ > 0) {
    y_lower_ = table_y0_;
    y_upper_ = table_y_last_;
  } else {
    y_lower_ = -table_y_last_;
    y_upper_ = -table_y0_;
  }
}

// The slope envelope over the surface's extent, and the positions where its curvature may jump.
void PlacedRail::build_envelope_and_breaks() {
  envelope_ = SlopeEnvelope(y_lower_, y_upper_, 1e-3, 32, 1.25, [this](double y, double& d1, double& d2) {
    const RailSample r = at(y);
    d1 = r.slope;
    d2 = r.d2;
  });
  for (double u : rail_->breakpoints()) {
    double y, z;
    profile_to_track(u, y, z);
    surface_breaks_.push_back(y);
  }
  surface_breaks_.push_back(y_lower_ + 1e-9);
  surface_breaks_.push_back(y_upper_ - 1e-9);
}

bool PlacedRail::height_and_slope_at(double y, double& z, double& slope) const {
  // One profile evaluation: the Newton correction du of solve_u moves height and slope by the
  // first terms of their Taylor series; the neglected terms are O(v''' du^2) ~ 1e-15 relative.
  const double ly = side_sign_ * y;
  if (!(ly >= table_y0_ && ly <= table_y_last_)) return false;
  const double u = hermite_u(ly);
  const ProfileSample p = rail_->evaluate(u);
  const double inverse_stretch = 1.0 / (cos_ - p.slope * sin_);
  const double du = -(local_y(u, p.height) - ly) * inverse_stretch;
  const double v1 = p.slope + p.second_derivative * du;
  const double v = p.height + du * (p.slope + 0.5 * p.second_derivative * du);
  z = local_z(u + du, v);
  // 1/(cos - v1 sin) to first order in du (v1 - p.slope is of order 1e-9): saves a division.
  const double stretch_correction = 1.0 + p.second_derivative * du * sin_ * inverse_stretch;
  slope = side_sign_ * (sin_ + v1 * cos_) * inverse_stretch * stretch_correction;
  return true;
}

void PlacedRail::profile_to_track(double u, double& y, double& z) const {
  const double v = rail_->evaluate(u).height;
  y = side_sign_ * local_y(u, v);
  z = local_z(u, v);
}

double PlacedRail::hermite_u(double ly) const {
  const double x = (ly - table_y0_) / table_dy_;
  const int k = std::clamp(static_cast<int>(x), 0, kTableNodes - 2);
  const double t = x - k, t2 = t * t, t3 = t2 * t;
  const double u = (2 * t3 - 3 * t2 + 1) * table_u_[k] + (t3 - 2 * t2 + t) * table_du_[k] +
                   (-2 * t3 + 3 * t2) * table_u_[k + 1] + (t3 - t2) * table_du_[k + 1];
  return std::clamp(u, table_u_[k], table_u_[k + 1]);
}

double PlacedRail::solve_u(double ly) const {
  // Cubic Hermite interpolation of u(y) between table nodes (exact values and slopes there), then
  // one Newton step on y(u) = ly: the start is within ~1e-9 m even across a curvature jump, so
  // the step leaves an error of order 1e-18 m.
  const double u = hermite_u(ly);
  const ProfileSample p = rail_->evaluate(u);
  return u - (local_y(u, p.height) - ly) / (cos_ - p.slope * sin_);
}

bool PlacedRail::slope_at(double y, double& slope) const {
  double z;
  return height_and_slope_at(y, z, slope);
}

RailSample PlacedRail::at(double y) const {
  RailSample r;
  const double ly = side_sign_ * y;
  if (!(ly >= table_y0_ && ly <= table_y_last_)) return r;
  r.u = solve_u(ly);
  const ProfileSample p = rail_->evaluate(r.u);
  const double stretch = cos_ - p.slope * sin_;
  r.valid = true;
  r.z = local_z(r.u, p.height);
  r.slope = side_sign_ * (sin_ + p.slope * cos_) / stretch;
  r.d2 = p.second_derivative / (stretch * stretch * stretch);
  return r;
}

double PlacedRail::curvature_at(double u) const {
  const ProfileSample p = rail_->evaluate(u);
  return -p.second_derivative / std::pow(1 + p.slope * p.slope, 1.5);
}

}  // namespace wrc
