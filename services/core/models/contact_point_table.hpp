#pragma once
/// @file
/// The table of the interpolated Hertzian model (MEDYNA): the common point of each wheel, with
/// everything a Hertz patch needs, at a grid of interpolation configurations (y, roll, yaw), and
/// its interpolation at any configuration inside the grid.

#include <array>
#include <vector>

#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/models/contact_model_options.hpp"

namespace wrc {

/// Common-point parameters tabulated over (y, roll, yaw) and interpolated: in y linearly or by a
/// natural cubic spline (InterpolationGrid::y_method), in roll and yaw linearly.
/// Interpolated per wheel: s, s_rail, theta, the wheel point relative to the wheelset centre
/// (3 components), the rail height, the distance at z = 0 (the distance is affine in z with unit
/// slope, so distance(z) = distance(0) + z exactly), contact angle, rolling radius, the normal
/// (3 components, renormalised), the four principal curvatures and distance_curvature.
/// The interpolated point is always marked a local minimum. Because every parameter is a
/// continuous function of the configuration, the common point's jumps are smoothed over one grid
/// cell (Arnold, section 3), and the table reproduces the exact common point at the nodes.
class ContactPointTable {
 public:
  /// Evaluates the exact common point of both wheels at every node (2 y_points roll_points
  /// yaw_points potential-point scans), at z = the track's nominal radius.
  /// @throws std::invalid_argument for an invalid grid; ContactConfigurationError naming the node
  ///         when a wheel has no contact there (y_max too large for the profiles).
  ContactPointTable(const WheelsetGeometry& geometry, const InterpolationGrid& grid,
                    const PotentialPointSearch& search = {});

  /// The interpolated common point of one wheel at pose (x and z only shift positions and the
  /// distance). @throws ContactConfigurationError when y, roll or yaw lies outside the grid.
  ContactPoint at(WheelSide side, const WheelsetPose& pose) const;

  const InterpolationGrid& grid() const { return grid_; }
  /// Node coordinate i in y [m], roll [rad], yaw [rad] (equally spaced from -max to +max).
  double y_node(int i) const { return node(i, grid_.y_points, grid_.y_max); }
  double roll_node(int j) const { return node(j, grid_.roll_points, grid_.roll_max); }
  double yaw_node(int k) const { return node(k, grid_.yaw_points, grid_.yaw_max); }

 private:
  static constexpr int kFields = 18;
  static double node(int i, int count, double half_range) {
    return -half_range + 2.0 * half_range * i / (count - 1);
  }
  size_t offset(int field, int j, int k) const {
    return (static_cast<size_t>(field) * grid_.roll_points * grid_.yaw_points +
            static_cast<size_t>(j) * grid_.yaw_points + static_cast<size_t>(k)) *
           static_cast<size_t>(grid_.y_points);
  }
  InterpolationGrid grid_;
  // Per wheel: values and (spline) second derivatives in y, layout [field][roll][yaw][y].
  std::array<std::vector<double>, 2> values_;
  std::array<std::vector<double>, 2> second_;
};

}  // namespace wrc
