// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The equations of motion of a rigid wheelset at constant speed along the track (docs/dynamics.md;
/// in curves, transitions and cant: docs/track.md), in coordinates relative to the track frame,
/// in the implicit form F(y, y') = 0 that IDA integrates, for both contact formulations:
///  - rigid contact (a DAE, index 2 with Gear-Gupta-Leimkuhler stabilisation): unknowns
///    q = (y, z, roll, yaw), their rates v, the spin rate Omega, the normal forces N_L, N_R
///    (scaled) and the GGL multipliers mu_L, mu_R; equations q' = v - G^T mu, the Newton-Euler
///    equations with the contact forces N_i n_z,i G_i, gap_i(q) = 0 and G_i v = 0, G_i the gap
///    gradients of the contact reply;
///  - elastic contact (an ODE in implicit form): q, v, Omega; the normal forces come from the
///    penetration in the contact reply.

#include <array>

#include <Eigen/Core>

#include "core/dynamics/followed_branches.hpp"
#include "core/dynamics/wheelset_parameters.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/track/track_layout.hpp"

namespace wrc {

/// Index of each unknown in the state vector.
enum WheelsetUnknown : int {
  kUnknownY = 0,      ///< lateral shift [m]
  kUnknownZ,          ///< centre height above the top-of-rail plane [m]
  kUnknownRoll,       ///< [rad]
  kUnknownYaw,        ///< [rad]
  kUnknownYDot,       ///< [m/s]
  kUnknownZDot,       ///< [m/s]
  kUnknownRollDot,    ///< [rad/s]
  kUnknownYawDot,     ///< [rad/s]
  kUnknownSpinRate,   ///< Omega [rad/s]
  kUnknownNormalLeft,   ///< rigid only: N_L / force_scale [-]
  kUnknownNormalRight,  ///< rigid only: N_R / force_scale [-]
  kUnknownMuLeft,       ///< rigid only: GGL multiplier of the left gap [m/s]
  kUnknownMuRight,      ///< rigid only: GGL multiplier of the right gap [m/s]
  // Rigid two-point contact only (a wheel sliding on a switching surface, FollowedBranches); the
  // unknowns of a wheel in one-point contact are 0 there (their equations: unknown = 0).
  kUnknownSecondNormalLeft,   ///< N of the left wheel's second point / force_scale [-]
  kUnknownSecondNormalRight,  ///< N of the right wheel's second point / force_scale [-]
  kUnknownSecondMuLeft,       ///< GGL multiplier of the left wheel's second gap [m/s]
  kUnknownSecondMuRight,      ///< GGL multiplier of the right wheel's second gap [m/s]
};

constexpr int kElasticUnknowns = 9;
constexpr int kRigidUnknowns = 13;
constexpr int kTwoPointRigidUnknowns = 17;
constexpr int kPoseUnknowns = 4;

/// Number of unknowns of a formulation; rigid with a wheel in two-point contact: 17.
constexpr int unknown_count(ContactFormulation f, bool two_point = false) {
  return f == ContactFormulation::kRigid ? (two_point ? kTwoPointRigidUnknowns : kRigidUnknowns) : kElasticUnknowns;
}

/// Whether unknown k enters the contact query (pose, rates, spin, the normal loads of the
/// points in contact) in a state of unknown_count(f, two_point) unknowns.
constexpr bool enters_contact_query(ContactFormulation f, bool two_point, int k) {
  if (f == ContactFormulation::kElastic) return k < kElasticUnknowns;
  return k <= kUnknownNormalRight ||
         (two_point && (k == kUnknownSecondNormalLeft || k == kUnknownSecondNormalRight));
}

/// The equations of one wheelset with fixed parameters.
class WheelsetEquations {
 public:
  /// @param z_reference height of the centred wheelset in contact, where the vertical
  ///        suspension is relaxed [m].
  WheelsetEquations(WheelsetParameters parameters, double z_reference, double nominal_radius);
  /// @param force_scale N per unit of the scaled normal forces [N], > 0 (a vehicle's wheelset: its
  ///        static wheel load, which its own load does not give).
  WheelsetEquations(WheelsetParameters parameters, double z_reference, double nominal_radius, double force_scale);

  const WheelsetParameters& parameters() const { return parameters_; }
  double force_scale() const { return force_scale_; }  ///< N per unit of the scaled normal forces [N]
  double nominal_radius() const { return nominal_radius_; }
  double z_reference() const { return z_reference_; }
  void set_z_reference(double z) { z_reference_ = z; }  ///< [m]
  /// The track where the wheelset is now (curvature, cant and their rates along s): every query,
  /// force and residual below is taken there. The simulation sets it from the time before each
  /// evaluation; default: straight, level track, where the equations are those of straight track
  /// bit for bit.
  void set_track(const TrackPoint& track) { track_ = track; }
  const TrackPoint& track() const { return track_; }
  /// Where the rails lie at the wheelset, moved by the track's irregularities (rail_placement.hpp):
  /// every query carries them. Default: the nominal rails.
  void set_rails(const std::array<RailOffset, 2>& rails) { rails_ = rails; }
  const std::array<RailOffset, 2>& rails() const { return rails_; }
  /// Generalised forces (y, z, roll, yaw) [N, N, N m, N m] of the bodies the wheelset is joined to
  /// (a vehicle's elements at its axle boxes), added to applied_forces() until set again; none by
  /// default (the lone wheelset's suspension is its PrimarySuspension).
  void set_element_forces(const Eigen::Vector4d& forces) {
    element_forces_ = forces;
    has_element_forces_ = true;
  }

  /// The contact query at state y (formulation f): pose and rates, rigid loads N_i, the followed
  /// branches (and in two-point contact the second points and their loads), material and grid.
  ContactQuery query(ContactFormulation f, const double* y, const FollowedBranches& branches) const;

  /// F(y, y') with the contact result of query(f, y, branches): writes
  /// unknown_count(f, branches.any_two_point()) values to residual. A wheel in two-point contact
  /// adds its second constraint (gap = 0, G v = 0) and force.
  /// @throws std::runtime_error when such a wheel's result has no second constraint.
  void residual(ContactFormulation f, const double* y, const double* yp, const ContactResult& contact,
                const FollowedBranches& branches, double* residual) const;

  /// dF/dy' (constant, diagonal): the coefficient of each y'_k in row k [SI].
  double derivative_coefficient(int k) const;

  /// The generalised forces (y, z, roll, yaw) and the axle moment of everything but the
  /// constraint forces: external loads, suspension, contact (elastic: all of it; rigid: creep
  /// only) [N, N, N m, N m] and [N m].
  Eigen::Vector4d applied_forces(ContactFormulation f, const double* y, const ContactResult& contact,
                                 double* axle_moment) const;

  /// The normal force of wheel i at state y [N]: rigid, from the unknowns (both points of a wheel
  /// in two-point contact); elastic, the sum of the wheel's patches in contact.
  double normal_force(ContactFormulation f, const double* y, const ContactResult& contact, int wheel,
                      const FollowedBranches& branches = {}) const;

  /// The mass matrix of (y, z, roll, yaw) [kg, kg, kg m^2, kg m^2].
  Eigen::Vector4d mass_diagonal() const;

 private:
  WheelsetParameters parameters_;
  double z_reference_;
  double nominal_radius_;
  double force_scale_;
  TrackPoint track_;
  std::array<RailOffset, 2> rails_{};
  Eigen::Vector4d element_forces_ = Eigen::Vector4d::Zero();
  bool has_element_forces_ = false;  // a lone wheelset adds nothing (not even +0.0)
};

}  // namespace wrc
