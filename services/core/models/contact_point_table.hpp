// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The table of the interpolated Hertzian model (MEDYNA), on the rigid manifold: at each node
/// (y, yaw) the rigid wheelset's roll and height from the exact geometry, and per wheel the common
/// point, with everything a Hertz patch needs, at a few roll angles closely around the rigid roll;
/// its interpolation, and the exact derivative of the interpolated gap, at any configuration.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/contact_point.hpp"
#include "core/geometry/contact_point_fields.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/model_interface/contact_model_options.hpp"

namespace wrc {

/// One wheel's interpolated contact: the point (distance = the interpolated gap) and the exact
/// gradient of that gap.
struct TableContact {
  ContactPoint point;
  /// d point.distance / d(y, z, roll, yaw) of the interpolated distance [-, -, m/rad, m/rad].
  Eigen::Vector4d gap_gradient{0, 1, 0, 0};
};

/// Common-point parameters on the rigid manifold, interpolated.
///
/// Nodes: y_i, yaw_k (InterpolationGrid); at each, the rigid roll phi_r and height z_r of the
/// exact geometry (RigidWheelsetSolver: both wheels touch), and per wheel the exact common point at
/// the roll nodes phi_r + delta_j (delta_j in [-roll_band, roll_band], delta = 0 a node).
///
/// The gap of a wheel is distance(y, z, roll, yaw) = z + D(y, roll - phi_r(y, yaw), yaw):
///  - phi_r(y, yaw): cubic Hermite in y with the exact slope d phi_r / dy at the nodes (implicit
///    differentiation of the two contact conditions with the envelope gradients);
///  - D at a node line (delta_j, yaw_k): cubic Hermite in y with the exact slope of the distance at
///    fixed delta (envelope gradient: d/dy + d phi_r/dy d/droll);
///  - in delta: cubic Hermite between the roll nodes with the exact slope d distance / droll at
///    each (itself interpolated in y), continued linearly beyond the band;
///  - in yaw: the Lagrange polynomial through the yaw nodes.
/// The gap is C1 and its gradient (TableContact::gap_gradient) is its exact derivative. At
/// delta = 0 both wheels interpolate the same data (both touch at the rigid pose), so gap_L =
/// gap_R = 0 is solved exactly by roll = phi_r(y, yaw) and z = -D(y, 0, yaw): the rigid height is
/// exact at the nodes and a C1 interpolant of it in between.
///
/// The other parameters (the contact point's fields, core/geometry/contact_point_fields.hpp; the
/// normal renormalised): cubic Hermite with monotone (Fritsch-Carlson) slopes in y and in delta
/// (held beyond the band), Lagrange in yaw; exact at the nodes, without overshoot at the common
/// point's jumps, which are thereby smoothed over one y cell (Arnold, section 3). The
/// interpolated point is always marked a local minimum.
class ContactPointTable {
 public:
  /// Solves the rigid wheelset at every (y_i, yaw_k) and evaluates the exact common point of both
  /// wheels at every roll node (y_points yaw_points rigid solves and 2 y_points yaw_points
  /// roll_points potential-point scans).
  /// @throws std::invalid_argument for an invalid grid; ContactConfigurationError naming the node
  ///         when a wheel has no contact there (y_max too large for the profiles).
  ContactPointTable(const WheelsetGeometry& geometry, const InterpolationGrid& grid,
                    const PotentialPointSearch& search = {});

  /// The interpolated contact of one wheel at pose (x only shifts positions; the distance is
  /// affine in z with unit slope).
  /// @throws OutsideModelError naming the coordinate when y or yaw lies outside the grid or
  ///         |roll| > roll_max.
  TableContact evaluate(WheelSide side, const WheelsetPose& pose) const;
  /// evaluate(side, pose).point.
  ContactPoint at(WheelSide side, const WheelsetPose& pose) const { return evaluate(side, pose).point; }

  /// The interpolated rigid roll phi_r(y, yaw) [rad] (both wheels' gaps vanish there).
  /// @throws OutsideModelError as evaluate().
  double rigid_roll(double y, double yaw) const;
  /// The interpolated rigid height z_r(y, yaw) [m]: the z at which both gaps vanish at
  /// roll = rigid_roll(y, yaw). @throws OutsideModelError as evaluate().
  double rigid_height(double y, double yaw) const;

  const InterpolationGrid& grid() const { return grid_; }
  /// Node coordinate i in y [m], roll offset j about the rigid roll [rad], yaw k [rad] (equally
  /// spaced from -max to +max).
  double y_node(int i) const { return node(i, grid_.y_points, grid_.y_max); }
  double roll_offset(int j) const { return node(j, grid_.roll_points, grid_.roll_band); }
  double yaw_node(int k) const { return node(k, grid_.yaw_points, grid_.yaw_max); }
  /// The rigid roll at node (y_i, yaw_k) from the exact geometry [rad].
  double rigid_roll_node(int i, int k) const { return roll_[index(k, i) * 2]; }

  /// Every tabulated number (node values and slopes, both wheels), for hashing the model data.
  std::vector<double> data() const;

 private:
  /// Per-node fields: the contact point's (ContactPointField order) interpolated with monotone
  /// slopes, then the distance at z = 0 and its roll derivative.
  static constexpr int kFields = kContactPointFieldCount + 2;
  static double node(int i, int count, double half_range) {
    return -half_range + 2.0 * half_range * i / (count - 1);
  }
  size_t index(int k, int i) const {
    return static_cast<size_t>(k) * static_cast<size_t>(grid_.y_points) + static_cast<size_t>(i);
  }
  // Offset of field f's value at node (k, j, i); its y slope follows at + kFields.
  size_t offset(int k, int j, int i) const {
    return ((static_cast<size_t>(k) * static_cast<size_t>(grid_.roll_points) + static_cast<size_t>(j)) *
                static_cast<size_t>(grid_.y_points) +
            static_cast<size_t>(i)) *
           (2 * kFields);
  }
  InterpolationGrid grid_;
  // Per wheel, layout [yaw][roll][y][value 0..kFields-1, y slope 0..kFields-1].
  std::array<std::vector<double>, 2> values_;
  // Rigid roll and its exact y slope, layout [yaw][y][roll, slope].
  std::vector<double> roll_;
};

}  // namespace wrc
