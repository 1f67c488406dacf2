// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Rigid-wheelset contact geometry: for lateral shift y and yaw psi, the roll angle and height at
/// which both wheels touch their rails (both minimal distances zero).

#include <array>
#include <vector>

#include "core/geometry/wheelset_geometry.hpp"

namespace wrc {

/// The solved configuration with the contact data of both wheels.
struct RigidContact {
  WheelsetPose pose;                              ///< y and yaw as asked; z [m] and roll [rad] solved
  std::array<ContactPoint, 2> contact;            ///< common point of the left [0] and right [1] wheel
  /// Potential points per wheel at the solved pose (distances relative to it) [m]: all of them, or
  /// with RigidSolverOptions::all_potential_points = false the lowest local minima only.
  std::array<std::vector<ContactPoint>, 2> potential;
  int roll_iterations = 0;  ///< evaluations of the roll equation
  int scans = 0;            ///< full potential-point scans (2 per verification)

  const ContactPoint& left() const { return contact[0]; }
  const ContactPoint& right() const { return contact[1]; }
  /// Rolling-radius difference r_left - r_right [m].
  double delta_r() const { return contact[0].rolling_radius - contact[1].rolling_radius; }
};

/// Settings of the rigid-wheelset solver.
struct RigidSolverOptions {
  PotentialPointSearch search;      ///< scan step and root tolerance
  double height_tolerance = 1e-12;  ///< |min distance left - min distance right| at the solution [m]
  int max_iterations = 60;          ///< roll iterations per verification round
  /// true: RigidContact::potential holds every potential point of each wheel (a full scan at the
  /// solution). false: only the local minima at the level of the common point are looked for,
  /// which certifies the common point as cheaply as possible (dynamics, tabulation).
  bool all_potential_points = true;
};

/// Solves the two contact conditions of a rigid wheelset for roll and height. The common point
/// of each wheel is the global minimum of its distance function, so contact-point jumps appear as
/// jumps in the result (never smoothed).
class RigidWheelsetSolver {
 public:
  explicit RigidWheelsetSolver(const WheelsetGeometry& geometry, RigidSolverOptions options = {});

  /// Cold start: scans both wheels first. Throws std::runtime_error naming y and yaw when a
  /// wheel has no contact with its rail (shifted off the rail or beyond flange climb).
  RigidContact solve(double y, double yaw) const;

  /// Warm start from a neighbouring solution (its roll angle and local minima); one verification
  /// scan per wheel guarantees the same result as a cold start.
  RigidContact solve(double y, double yaw, const RigidContact& neighbour) const;

  const WheelsetGeometry& geometry() const { return geometry_; }

 private:
  RigidContact solve_from(double y, double yaw, double roll, std::array<std::vector<double>, 2> seeds) const;
  const WheelsetGeometry& geometry_;
  RigidSolverOptions options_;
};

}  // namespace wrc
