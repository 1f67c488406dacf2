// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The pieces every Hertzian contact model shares: the Hertz ellipse at a contact point (with the
/// conformal-contact fallback), one complete ContactPatch (Hertz, creepages, FASTSIM) from a normal
/// force or from a penetration, and the penetration implied by a vertical overlap.

#include <array>
#include <optional>

#include "core/contact/fastsim.hpp"
#include "core/contact/hertz.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/model_interface/wheelset_motion.hpp"

namespace wrc {

/// The Hertz shape at one contact point.
struct PatchShape {
  HertzShape shape;      ///< from A = relative_curvature_rolling(), B = relative_curvature_lateral() [1/m]
  bool floored = false;  ///< B was raised to lateral_curvature_floor * A
};

/// The Hertz shape at point from its relative curvatures. When B <= floor * A (conformal contact,
/// e.g. a concave flange root on a flatter rail shoulder) B is set to floor * A and the result is
/// flagged; floor = 0 disables this.
/// @param lateral_curvature_floor the floor relative to A [-], >= 0.
/// @throws ContactConfigurationError naming the wheel, s and the curvatures when A is not positive
///         or not finite, or B is not positive with the floor disabled.
PatchShape contact_shape(const ContactPoint& point, double lateral_curvature_floor);

/// Everything a patch needs besides its point: the query, the wheelset motion, the FASTSIM solver
/// for the query's grid and E* = G / (1 - nu) [Pa].
struct PatchContext {
  const ContactQuery& query;
  const WheelsetMotion& motion;
  const Fastsim& fastsim;
  double contact_modulus;
};

/// A patch with a given normal force (rigid formulation): Hertz from force, penetration reported
/// as 0 (ContactPatch's convention for kRigid), creepages at the wheel point, FASTSIM forces.
/// @param normal_force N [N], > 0.
ContactPatch patch_from_force(const ContactPoint& point, const PatchShape& shape, double normal_force,
                              const PatchContext& context);

/// A patch with a given penetration (elastic formulation): N = C_H delta^{3/2} and the semi-axes
/// from delta, creepages at the wheel point, FASTSIM forces.
/// @param penetration delta along the normal [m], > 0.
ContactPatch patch_from_penetration(const ContactPoint& point, const PatchShape& shape, double penetration,
                                    const PatchContext& context);

/// Hertzian one-point contact at point (OnePointModel and InterpolatedModel):
///  - kRigid: the wheel's normal_load is the normal force N; nothing when the load is 0;
///  - kElastic: delta = normal_penetration(point), N = C_H delta^{3/2}; nothing when delta <= 0.
/// @param lateral_curvature_floor as in contact_shape() [-].
std::optional<ContactPatch> one_point_patch(const ContactPoint& point, const PatchContext& context,
                                            double lateral_curvature_floor);

/// The same with the Hertz shape given (the spline model's fitted shape instead of the elliptic
/// inversion at the point's curvatures).
std::optional<ContactPatch> one_point_patch(const ContactPoint& point, const PatchShape& shape,
                                            const PatchContext& context);

/// One of the two points a wheel touches at within a jump's transition (the spline model's and
/// the interpolated model's blend of two branches of the common point).
struct SharedPoint {
  ContactPoint point;
  PatchShape shape;
  double share = 0;        ///< its share of the blended contact's load [-], in [0, 1]
  /// d z_touch / dy of its branch [-], or as well its normal's inclination n_y / n_z (their
  /// squares, which is all the split uses, agree where the normal has no x part)
  double height_slope = 0;
};

/// A wheel's contact within a jump's transition, where it touches at both points: the normal
/// force of the blended contact (the wheel's load, or from the blended gap) shared as the smooth
/// maximum shares the constraint's gradient, each part a Hertz patch of its own point and shape
/// (blending the Hertz fields of a tread and a flange-root patch would make an ellipse neither
/// has). Part k's normal is that of its branch's slope g_k, its force share_k N cos(gamma) /
/// cos(gamma_k): the parts' vertical forces add up to the blend's, their lateral forces to
/// N cos(gamma) (sum share_k g_k) = the blend's, where g = sum share_k g_k is the blend's slope.
/// Elastic formulation: each part reports the blend's penetration.
/// @param blended the blended contact's patch (its normal force N [N]).
/// @param height_slope g, the blended contact's d z_touch / dy (or inclination) [-].
void add_shared_patches(const ContactPatch& blended, double height_slope, const std::array<SharedPoint, 2>& parts,
                        const PatchContext& context, ContactResult& result);

/// The approach of the surfaces along the normal implied by the point's vertical overlap:
/// delta = -distance cos(contact_angle) [m] (< 0: a gap). A vertical rigid approach d of the wheel
/// moves its surface by d cos(angle) along the contact normal, so this is the elastic approach to
/// first order in the overlap (exact for flat surfaces, error O(delta^2 * curvature)).
double normal_penetration(const ContactPoint& point);

/// A patch's forces on the wheel in the track frame, in the contact frame of contact_frame(n).
struct PatchForces {
  Eigen::Vector3d n{0, 0, 1};         ///< unit contact normal [-]
  Eigen::Vector3d normal{0, 0, 0};    ///< normal force N n [N]
  Eigen::Vector3d creep{0, 0, 0};     ///< creep force fx t1 + fy t2 [N]
};
PatchForces patch_forces(const ContactPatch& patch);

/// Adds a patch's normal force N n, creep forces fx t1 + fy t2 and spin moment mz n (contact
/// frame of contact_frame(n)) to the resultant force on the wheelset and to its moment about the
/// wheelset centre [m]; the lever arm is the wheel point minus the centre. The creep part alone
/// goes to creep_force and creep_moment as well.
void add_to_resultant(const ContactPatch& patch, const Eigen::Vector3d& centre, ContactResult& result);

}  // namespace wrc
