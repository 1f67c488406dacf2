// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The contact area of the paper's figures 1-3: the region of the common tangent plane E where the
/// distance between the undeformed wheel and rail surfaces, measured along the common normal, is
/// below a threshold eps0.
///
/// The wheel is first placed vertically so that it touches the rail in the common point P (the
/// wheelset centre is lowered by the common point's distance). E passes through P with the common
/// normal n (pointing from the rail into the wheel); t1 is the rolling direction (the track x axis
/// projected onto E), t2 = n x t1 the lateral direction (towards +y of the track for both wheels).
/// For a point q = P + xi t1 + eta t2 of E, the line q + lambda n meets the rail at lambda_rail and
/// the wheel at lambda_wheel (the intersections nearest to E); the distance is
/// lambda_wheel - lambda_rail (>= 0 where the undeformed bodies do not overlap).

#include <Eigen/Core>
#include <vector>

#include "core/geometry/contact_locus.hpp"
#include "core/geometry/contact_point.hpp"
#include "core/geometry/potential_points.hpp"
#include "core/geometry/wheel_side.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/geometry/wheelset_pose.hpp"

namespace wrc {

/// Grid and root-finding settings of compute_contact_area().
struct ContactAreaOptions {
  int n_xi = 61;                   ///< grid nodes in the rolling direction xi [-] (>= 2; odd puts a node on P)
  int n_eta = 61;                  ///< grid nodes in the lateral direction eta [-] (>= 2; odd puts a node on P)
  double half_width_xi = 0.02;     ///< the grid covers xi in [-half_width_xi, half_width_xi] [m]
  double half_width_eta = 0.02;    ///< the grid covers eta in [-half_width_eta, half_width_eta] [m]
  double root_tolerance = 1e-12;   ///< absolute tolerance of each intersection along the normal [m]
  double max_normal_distance = 0.05;  ///< intersections farther than this from E count as missing [m]
  PotentialPointSearch search;     ///< settings of the potential-point search that finds P
};

/// One connected part of the region distance < eps0 (4-neighbour connectivity of grid nodes).
struct ContactAreaPatch {
  double area = 0;          ///< area in E [m^2] (column chords with interpolated ends, summed over xi)
  double xi_min = 0;        ///< smallest xi of the patch (interpolated along grid rows) [m]
  double xi_max = 0;        ///< largest xi of the patch [m]
  double eta_min = 0;       ///< smallest eta of the patch (interpolated along grid columns) [m]
  double eta_max = 0;       ///< largest eta of the patch [m]
  double xi_centroid = 0;   ///< area centroid, rolling coordinate [m]
  double eta_centroid = 0;  ///< area centroid, lateral coordinate [m]
  double min_distance = 0;  ///< smallest grid distance inside the patch [m]
  int nodes = 0;            ///< grid nodes inside the patch [-]
  /// The patch reaches the grid border or a node where a surface is missing: its size is a lower bound.
  bool truncated = false;
};

/// Derived quantities of the region distance < eps0.
struct ContactAreaSummary {
  double eps0 = 0;          ///< threshold [m]
  double area = 0;          ///< total area of all patches [m^2]
  double xi_min = 0;        ///< extent of the whole region in xi [m] (0 when empty)
  double xi_max = 0;        ///< [m]
  double eta_min = 0;       ///< extent of the whole region in eta [m] (0 when empty)
  double eta_max = 0;       ///< [m]
  double xi_centroid = 0;   ///< area centroid of the whole region [m]
  double eta_centroid = 0;  ///< [m]
  std::vector<ContactAreaPatch> patches;  ///< the connected parts, ordered by eta centroid
  bool truncated = false;   ///< some patch is truncated (enlarge the grid)

  /// Number of separate patches [-].
  int patch_count() const { return static_cast<int>(patches.size()); }
};

/// Distances on a rectangular grid of the plane E; NaN where a surface is missing (beyond the rail's
/// lateral extent, outside the wheel profile, or farther than max_normal_distance from E).
struct ContactAreaGrid {
  std::vector<double> xi;        ///< node coordinates in the rolling direction, increasing, uniform [m]
  std::vector<double> eta;       ///< node coordinates in the lateral direction, increasing, uniform [m]
  std::vector<double> distance;  ///< distance [m] at (xi[i], eta[j]) stored at j * xi.size() + i

  /// Distance at node (i, j) = (xi[i], eta[j]) [m].
  double at(size_t i, size_t j) const { return distance[j * xi.size() + i]; }

  /// Area, extents, centroid and connected patches of the region distance < eps0 [m]. Crossings of
  /// eps0 between neighbouring nodes are interpolated quadratically through a third node of the same
  /// grid line (linearly when there is none; never into a NaN node), so they are exact for a gap
  /// quadratic along the line; the area is the sum over grid columns of the chord lengths times the
  /// column spacing (error O(h^1.5) from the tips of each patch).
  /// Throws std::invalid_argument for fewer than 2 nodes per direction or mismatched sizes.
  ContactAreaSummary summary(double eps0) const;
};

/// A local minimum of the distance along C, placed like the wheel in the contact area and
/// projected onto E.
struct ProjectedMinimum {
  double s = 0;         ///< wheel profile coordinate [m]
  double xi = 0;        ///< rolling coordinate of its projection onto E [m]
  double eta = 0;       ///< lateral coordinate of its projection onto E [m]
  double distance = 0;  ///< its vertical distance above the common point's [m] (0 for P itself)
};

/// The contact area of one wheel for one pose, with its frame.
struct ContactArea {
  WheelSide side = WheelSide::kLeft;  ///< the wheel
  WheelsetPose pose;                  ///< the pose asked for, with z lowered so that the wheel touches [m, rad]
  ContactPoint common;                ///< the common point P (distance 0 at the touching pose)
  Eigen::Vector3d origin{0, 0, 0};    ///< P in the track frame [m]
  Eigen::Vector3d normal{0, 0, 1};    ///< n: common normal, rail into wheel, track frame [-]
  Eigen::Vector3d t1{1, 0, 0};        ///< rolling direction in E, track frame [-]
  Eigen::Vector3d t2{0, 1, 0};        ///< lateral direction n x t1, track frame [-]
  std::vector<ProjectedMinimum> minima;  ///< every local minimum of the distance along C
  ContactAreaGrid grid;               ///< distances on the grid of E

  /// Track-frame point of E at (xi, eta) [m].
  Eigen::Vector3d point(double xi, double eta) const { return origin + xi * t1 + eta * t2; }
  /// Shortcut for grid.summary(eps0) [m].
  ContactAreaSummary summary(double eps0) const { return grid.summary(eps0); }
};

/// Distance between the undeformed surfaces along the normal through E at (xi, eta) [m] for a wheel
/// already placed by area (lambda_wheel - lambda_rail); NaN where a surface is missing.
double normal_distance(const WheelsetGeometry& geometry, const ContactArea& area, double xi, double eta,
                       const ContactAreaOptions& options = {});

/// The contact area of one wheel at pose (pose.z is irrelevant: the wheel is placed touching).
/// Throws std::invalid_argument for bad options and std::runtime_error when the wheel has no
/// common point with its rail (off the rail).
ContactArea compute_contact_area(const WheelsetGeometry& geometry, WheelSide side, const WheelsetPose& pose,
                                 const ContactAreaOptions& options = {});

/// One sample of the distance along C relative to the common point (the paper's left plots).
struct LocusDistanceSample {
  double s = 0;         ///< wheel profile coordinate [m]
  double y = 0;         ///< track lateral position of the wheel point [m]
  double distance = 0;  ///< vertical distance minus the common point's [m]; NaN when not over the rail
};

/// n equally spaced samples (n >= 2) of the distance along C over [locus.s_lower(), locus.s_upper()]
/// [m], shifted by common_distance [m] so that the common point reads 0.
std::vector<LocusDistanceSample> sample_locus_distance(const ContactLocus& locus, double common_distance, int n);

}  // namespace wrc
