// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The equations of motion of a whole vehicle (docs/vehicle.md, "The vehicle's equations"): its
/// car bodies and bogie frames with the equations of core/vehicle/body_dynamics.hpp, its wheelsets
/// with those of core/dynamics/wheelset_equations.hpp (rigid or elastic contact, the wheelset's
/// spin), each body in the track frame at its own distance along the track, all joined by the
/// elements' forces (core/vehicle/element_forces.hpp). The implicit form F(y, y') = 0 that IDA
/// integrates, given each wheelset's contact result: no contact evaluation, no integrator here.
///
/// The state is the bodies' unknowns one body after another in the order of the vehicle file
/// (VehicleLayout): a car body or frame has 10, its displacement (y, z, roll, yaw, pitch) from the
/// nominal position and their rates; a wheelset has the unknowns of its contact formulation
/// (wheelset_equations.hpp: y, z the centre's height above the rails, roll, yaw, their rates, the
/// spin and, rigid, the normal forces and multipliers).

#include <memory>
#include <vector>

#include "core/dynamics/followed_branches.hpp"
#include "core/dynamics/ida_integrator.hpp"
#include "core/dynamics/wheelset_equations.hpp"
#include "core/dynamics/wheelset_parameters.hpp"
#include "core/track/track_irregularity.hpp"
#include "core/track/track_layout.hpp"
#include "core/vehicle/element_forces.hpp"
#include "core/vehicle/vehicle_description.hpp"

namespace wrc {

/// A car body's or frame's unknowns: its displacement (BodyCoordinate order) then its rates.
inline constexpr int kBodyUnknowns = 2 * static_cast<int>(kBodyCoordinates);

/// Where each body's unknowns lie in the vehicle's state vector.
struct VehicleLayout {
  std::vector<int> offset;  ///< per body, in the order of the vehicle's bodies [-]
  std::vector<int> size;    ///< per body: kBodyUnknowns, or its wheelset's unknown_count() [-]
  int unknowns = 0;         ///< the whole state's [-]
};

/// What a wheelset's block of the residual takes from its contact.
struct WheelsetContactView {
  ContactFormulation formulation = ContactFormulation::kRigid;
  const FollowedBranches* branches = nullptr;
  const ContactResult* result = nullptr;
};

class VehicleEquations {
 public:
  /// @param vehicle a valid description whose wheelsets the wheelset equations can take: on the
  ///        centre line (position y = 0), principal axes along the track (no products of inertia).
  /// @param common the run's values every wheelset shares: speed, material, FASTSIM grid, gravity,
  ///        flange angle (its masses, loads and suspension are the vehicle's instead)
  /// @param nominal_radius r0 of the wheel profile [m]
  /// @param wheel_loads each wheelset's static wheel load, the scale of its normal forces [N]
  /// @throws std::invalid_argument naming the body and key that the equations cannot take.
  VehicleEquations(VehicleDescription vehicle, const WheelsetParameters& common, TrackLayout layout,
                   TrackIrregularity irregularity, double nominal_radius, const std::vector<double>& wheel_loads);

  const VehicleDescription& vehicle() const { return vehicle_; }
  const TrackLayout& layout() const { return layout_; }
  double speed() const { return speed_; }   ///< V [m/s]
  double gravity() const { return gravity_; }  ///< g [m/s^2]
  /// The number of wheelsets [-] and each one's equations, in the order of the bodies.
  size_t wheelset_count() const { return wheelsets_.size(); }
  WheelsetEquations& wheelset(size_t w) { return wheelsets_[w]; }
  const WheelsetEquations& wheelset(size_t w) const { return wheelsets_[w]; }
  /// The body index of wheelset w [-].
  size_t wheelset_body(size_t w) const { return wheelset_bodies_[w]; }
  /// The wheelset index of body b, or -1 for a car body or frame [-].
  int wheelset_of_body(size_t b) const { return wheelset_of_body_[b]; }

  /// The layout of the state with wheelset w having wheelset_unknowns[w] unknowns.
  VehicleLayout layout_of(const std::vector<int>& wheelset_unknowns) const;

  /// Places every wheelset's equations on the track where it is at time t [s]: at s_ref + X with
  /// s_ref = V t (its track point, and with irregularities its rails).
  void place(double t);
  double reference_distance() const { return s_ref_; }  ///< s_ref of the last place() [m]
  /// Whether the track has irregularities.
  bool has_irregularities() const { return !irregularity_.empty(); }
  /// The share of the irregularities the rails take from the next place() on [-], in [0, 1]: 1 the
  /// track as given (the default), 0 the nominal rails; the rest state's continuation
  /// (vehicle_equilibrium.hpp) goes from 0 to 1. @throws std::invalid_argument outside [0, 1].
  void set_irregularity_share(double share);

  /// Each body's displacement from its nominal position and rates at state y (a wheelset's z is
  /// its height minus its position's z; its pitch 0: the axle boxes do not spin).
  std::vector<BodyState> body_states(const VehicleLayout& layout, const double* y) const;

  /// The absolute acceleration [m/s^2] of each body's centre of gravity along y and z of its own
  /// track frame at state y, the place()d time (the frame's motion and turning included, gravity
  /// not: what an accelerometer there reads, less gravity), for every car body and frame; zeros
  /// for the wheelsets. From the bodies' equations with the elements' forces at y.
  std::vector<Eigen::Vector2d> body_accelerations(const VehicleLayout& layout, const double* y) const;

  /// F(y, y') into r at the place()d time, every wheelset's contact given.
  /// @throws what the wheelset equations throw (a two-point wheel without its second point).
  void residual(const VehicleLayout& layout, const double* y, const double* yp,
                const std::vector<WheelsetContactView>& contacts, double* r);

  /// Adds c dF/dy' at y to jac (row i, column k of the whole state) [SI]: the identity on each
  /// displacement row, each body's mass matrix M(q) on its rates, each wheelset's diagonal.
  void add_derivative_terms(const VehicleLayout& layout, const double* y, double c, DenseMatrixView jac) const;

 private:
  VehicleDescription vehicle_;
  TrackLayout layout_;
  TrackIrregularity irregularity_;
  double irregularity_share_ = 1.0;
  double speed_;
  double gravity_;
  std::vector<WheelsetEquations> wheelsets_;
  std::vector<size_t> wheelset_bodies_;
  std::vector<int> wheelset_of_body_;
  double s_ref_ = 0;
};

}  // namespace wrc
