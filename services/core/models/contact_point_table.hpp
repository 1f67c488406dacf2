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
#include "core/models/jump_transitions.hpp"

namespace wrc {

/// One wheel's interpolated contact: the point (distance = the interpolated gap) and the exact
/// gradient of that gap.
struct TableContact {
  ContactPoint point;
  /// d point.distance / d(y, z, roll, yaw) of the interpolated distance [-, -, m/rad, m/rad].
  Eigen::Vector4d gap_gradient{0, 1, 0, 0};
  /// Within a jump's band: the two points that carry the load, the lower-y branch's [0] and the
  /// higher-y one's [1], each its share [-] and its normal's inclination n_y / n_z [-] (shares
  /// add up to 1, the inclinations weighted by them to the blended point's, inclination);
  /// false outside every band.
  bool shared = false;
  std::array<ContactPoint, 2> branch_points;
  std::array<double, 2> branch_shares{0, 0}, branch_inclinations{0, 0};
  double inclination = 0;  ///< the blended point's n_y / n_z [-] (set when shared)
};

/// Common-point parameters on the rigid manifold, interpolated.
///
/// Nodes: y_i, yaw_k (InterpolationGrid); at each, the rigid roll phi_r and height z_r of the
/// exact geometry (RigidWheelsetSolver: both wheels touch), and per wheel the exact common point at
/// the roll nodes phi_r + delta_j (delta_j in [-roll_band, roll_band], delta = 0 a node).
///
/// The y nodes are the grid's equally spaced ones, except around each jump of a common point on
/// the rigid manifold (at any yaw node): there the nodes inside the band in which an elastic
/// contact loads both points (find_jump_transitions(), InterpolationGrid::transition) give way to
/// two nodes at the band's ends, so that the table ramps from one point to the other over the
/// physical width of the transition, not over one grid cell. At the band's ends each point is
/// exact; across the band the gap is the cubic through both branches' heights and slopes, the
/// same end data as the spline model's smooth maximum (docs/spline-model.md).
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
/// (held beyond the band), Lagrange in yaw; exact at the nodes. In the cell of a jump on the
/// rigid manifold (delta = 0, at its yaw node) they are the two points' fields continued linearly
/// from the cell's ends, f = (1 - w) f_a + w f_b, with the spline model's load share
/// w = u^3 (10 - 15 u + 6 u^2), u = (1 + t) / 2, t the height difference over h taken linear in y
/// on each side of the jump (-1 at the cell's lower end, 0 at the jump, 1 at the upper): the
/// second point's share grows as the elastic contact's does, not as a cubic in y (Arnold,
/// section 3, smooths a jump over one cell by the interpolation itself). The interpolated point is
/// always marked a local minimum.
class ContactPointTable {
 public:
  /// Solves the rigid wheelset at every (y_i, yaw_k), finds the jumps and their bands, and
  /// evaluates the exact common point of both wheels at every roll node (about y_points yaw_points
  /// rigid solves and 2 y_points yaw_points roll_points potential-point scans, and the walks past
  /// each jump). Uses options.interp, options.search and options.lateral_curvature_floor.
  /// @throws std::invalid_argument for invalid options; ContactConfigurationError naming the node
  ///         when a wheel has no contact there (y_max too large for the profiles).
  explicit ContactPointTable(const WheelsetGeometry& geometry, const ContactModelOptions& options = {});

  /// The interpolated contact of one wheel at pose (x only shifts positions; the distance is
  /// affine in z with unit slope).
  /// @throws OutsideModelError naming the coordinate when y or yaw lies outside the grid or
  ///         |roll| > roll_max.
  TableContact evaluate(WheelSide side, const WheelsetPose& pose) const;
  /// evaluate(side, pose).point.
  ContactPoint at(WheelSide side, const WheelsetPose& pose) const { return evaluate(side, pose).point; }

  /// The interpolated rigid roll phi_r(y, yaw) of the exact geometry [rad]: both wheels' gaps
  /// vanish there outside the jumps' bands (inside, the blend lifts one wheel's touching height
  /// by up to the band's half-width, and the table's rigid pose rolls by as much over the gauge).
  /// @throws OutsideModelError as evaluate().
  double rigid_roll(double y, double yaw) const;
  /// The interpolated rigid height z_r(y, yaw) [m]: the z at which the left wheel's gap vanishes
  /// at roll = rigid_roll(y, yaw), and the right one's too outside the jumps' bands.
  /// @throws OutsideModelError as evaluate().
  double rigid_height(double y, double yaw) const;

  const InterpolationGrid& grid() const { return grid_; }
  /// Number of y nodes: grid().y_points, less those inside the jumps' bands, plus the bands' ends.
  int y_node_count() const { return static_cast<int>(y_nodes_.size()); }
  /// Node coordinate i in y [m] (increasing from -y_max to y_max), roll offset j about the rigid
  /// roll [rad], yaw k [rad] (equally spaced from -max to +max).
  double y_node(int i) const { return y_nodes_[static_cast<size_t>(i)]; }
  /// The jumps of the common points on the rigid manifold at every yaw node, with their bands
  /// (empty when InterpolationGrid::transition is 0).
  const std::vector<JumpTransition>& jump_transitions() const { return transitions_; }
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
    return static_cast<size_t>(k) * y_nodes_.size() + static_cast<size_t>(i);
  }
  // Offset of field f's value at node (k, j, i); its y slope follows at + kFields.
  size_t offset(int k, int j, int i) const {
    return ((static_cast<size_t>(k) * static_cast<size_t>(grid_.roll_points) + static_cast<size_t>(j)) *
                y_nodes_.size() +
            static_cast<size_t>(i)) *
           (2 * kFields);
  }
  // The y cell of y and the local coordinate t in [0, 1] in it.
  void locate_y(double y, int& cell, double& t) const;
  // The steps of the constructor, in order: the rigid wheelset at the equally spaced y nodes of
  // every yaw node (returned, per yaw node) and the jumps between them (transitions_);
  std::vector<std::vector<RigidContact>> find_jumps(const RigidWheelsetSolver& solver,
                                                    const ContactModelOptions& options,
                                                    const std::vector<double>& uniform);
  // the y nodes around the jumps' bands (y_nodes_) and the bands' node ranges (bands_);
  void place_bands(const std::vector<double>& uniform);
  // at yaw node k, the rigid roll and its y slope (roll_) and both wheels' node values (values_),
  // line the rigid wheelset at the equally spaced nodes there;
  void tabulate_nodes(const WheelsetGeometry& geometry, const RigidWheelsetSolver& solver,
                      const PotentialPointSearch& search, double steepest, int k, const std::vector<RigidContact>& line);
  // the monotone y slopes of the fields of yaw node k (all but the distance's, which is exact);
  void add_monotone_slopes(int k);
  // in each band of yaw node k, at every node on the manifold (delta = 0), the other point: the
  // minimum that continues the point across the jump, followed node by node outwards from the
  // jump's cell (Band::other, Band::usable).
  void follow_other_points(const WheelsetGeometry& geometry, const PotentialPointSearch& search, int k);
  // A jump's band at one yaw node: its node range, the cell of the jump, and at every node of the
  // range the other point on the manifold (kBandValues per node: the fields of the table, then the
  // distance's y slope).
  static constexpr int kBandValues = kFields + 1;
  struct Band {
    int yaw_node = 0, low = 0, high = 0, jump_cell = 0;
    bool usable = false;  // the other point was found at every node
    std::vector<double> other;
  };
  // The usable band of wheel side at yaw node k that covers cell (nullptr: none).
  const Band* band_at(int k, WheelSide side, int cell) const;
  // The manifold line's (delta = 0) values at y in cell of a band: f[kFields] and fy[2] (d/dy of
  // the distance and of its roll derivative), from the two points' branches.
  // branch[b] receives branch b's fields.
  void blend_branches(const Band& band, const JumpTransition& jump, int k, WheelSide side, int cell, double y,
                      double* f, double* fy, double (*branch)[kFields]) const;
  // The two branches' points in c (TableContact::shared) from their fields' shifts off the
  // blended ones, at the blend's distance shifted likewise [m].
  void add_branches(const double (*branch_shift)[kFields], WheelSide side, const WheelsetPose& pose, double distance,
                    const ContactPointFields& blended, TableContact& c) const;
  InterpolationGrid grid_;
  std::vector<double> y_nodes_;
  std::vector<JumpTransition> transitions_;
  // Per transition: its yaw node, and its band.
  std::vector<int> transition_yaw_node_;
  std::vector<Band> bands_;
  // Per wheel, layout [yaw][roll][y][value 0..kFields-1, y slope 0..kFields-1].
  std::array<std::vector<double>, 2> values_;
  // Rigid roll and its exact y slope, layout [yaw][y][roll, slope].
  std::vector<double> roll_;
};

}  // namespace wrc
