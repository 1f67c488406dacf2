// SPDX-License-Identifier: Apache-2.0
#include "core/spline/wheel_sample.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/model_interface/patch_builder.hpp"

namespace wrc {

namespace {

// The sample of tread point p at pose: every field, the clearance against the flange's lowest
// distance flange_low [m].
void fill_sample(WheelSample& out, const ContactPoint& tread, const WheelsetPose& pose, double second_gap,
                 double flange_low, double clearance_cap, double lateral_curvature_floor) {
  out.valid = true;
  out.tread = tread;
  out.second_minimum_gap = second_gap;
  out.flange_clearance = std::min(flange_low - tread.distance, clearance_cap);

  const ContactPoint& p = out.tread;
  const PatchShape shape = contact_shape(p, lateral_curvature_floor);
  auto& f = out.fields;
  f[kFieldZ] = pose.z - p.distance;
  const ContactPointFields point = contact_point_fields(p, pose);
  for (int k = 0; k < kContactPointFieldCount; ++k)
    f[kSplineFieldOfPointField[static_cast<size_t>(k)]] = point[static_cast<size_t>(k)];
  f[kFieldHertzA] = shape.shape.A;
  f[kFieldHertzB] = shape.shape.B;
  f[kFieldMinorOverMajor] = shape.shape.minor_over_major;
  f[kFieldEllipticK] = shape.shape.K;
  f[kFieldEllipticE] = shape.shape.E;
  f[kFieldHertzM] = shape.shape.m;
  f[kFieldHertzN] = shape.shape.n;
  f[kFieldFlangeClearance] = out.flange_clearance;
}

}  // namespace

double flange_split(const Profile& wheel, double flange_angle) {
  const double limit = std::tan(flange_angle);
  const double lower = wheel.lower();
  for (double s = 0.0; s > lower; s -= 1e-5) {
    if (std::abs(wheel.evaluate(s).slope) > limit) return s;
  }
  return lower;
}

WheelSample sample_wheel(const WheelsetGeometry& geometry, WheelSide side, const WheelsetPose& pose, double s_split,
                         double clearance_cap, double lateral_curvature_floor, const PotentialPointSearch& search) {
  WheelSample out;
  const std::vector<ContactPoint> points = geometry.potential_points(side, pose, search);
  const double inf = std::numeric_limits<double>::infinity();
  const ContactPoint* lowest = nullptr;
  double second = inf, flange_low = inf;
  for (const ContactPoint& p : points) {
    if (!p.is_minimum) continue;
    if (p.s <= s_split) {
      flange_low = std::min(flange_low, p.distance);
    } else if (!lowest || p.distance < lowest->distance) {
      if (lowest) second = std::min(second, lowest->distance);
      lowest = &p;
    } else {
      second = std::min(second, p.distance);
    }
  }
  const ContactLocus locus = geometry.locus(side, pose);
  const LocusPoint split = locus.at(s_split);
  if (split.over_rail) flange_low = std::min(flange_low, split.distance);
  // Deep in flange contact the tread's minimum can merge into the split point and vanish: the
  // tread's lowest point is then the split point itself (the fields stay continuous, and the
  // clearance is <= 0 there, so the model does not use them).
  ContactPoint boundary;
  if (!lowest) {
    if (!split.over_rail) return out;
    boundary = make_contact_point(locus, s_split, false);
    lowest = &boundary;
  }
  fill_sample(out, *lowest, pose, second - lowest->distance, flange_low, clearance_cap, lateral_curvature_floor);
  return out;
}

WheelSample sample_wheel_branch(const WheelsetGeometry& geometry, WheelSide side, const WheelsetPose& pose,
                                double s_split, double clearance_cap, double lateral_curvature_floor,
                                const PotentialPointSearch& search, double s_near, double max_shift) {
  WheelSample out;
  const std::vector<ContactPoint> points = geometry.potential_points(side, pose, search);
  const double inf = std::numeric_limits<double>::infinity();
  const ContactPoint* nearest = nullptr;
  double flange_low = inf;
  for (const ContactPoint& p : points) {
    if (!p.is_minimum) continue;
    if (p.s <= s_split) {
      flange_low = std::min(flange_low, p.distance);
    } else if (std::abs(p.s - s_near) <= max_shift && (!nearest || std::abs(p.s - s_near) < std::abs(nearest->s - s_near))) {
      nearest = &p;
    }
  }
  if (!nearest) return out;
  const LocusPoint split = geometry.locus(side, pose).at(s_split);
  if (split.over_rail) flange_low = std::min(flange_low, split.distance);
  fill_sample(out, *nearest, pose, 0.0, flange_low, clearance_cap, lateral_curvature_floor);
  return out;
}

}  // namespace wrc
