// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The range of configurations the Hertzian contact models are valid for, checked on a computed
/// result: the one place of these limits (the services and the CLI get them through the models).

#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// Largest normal penetration of one patch in the elastic formulation [m]. Hertz's theory holds for
/// an approach small against the profiles' radii of curvature and the patch small against the
/// bodies; the benchmark's wheels settle at about 0.1 mm. At 5 mm, 50 times that, the Hertz force
/// is about 350 times the benchmark's wheel load (N grows as penetration^1.5), beyond any wheel
/// load even in an impact: a deeper penetration is a wheelset placed into its rails (a wrong z),
/// not a contact. (Tests and studies do use approaches of a few millimetres.)
inline constexpr double kMaxElasticPenetration = 5e-3;

/// Largest height of the wheelset above contact in the elastic formulation [m]: when both wheels'
/// gaps exceed it, the answer is NoContactError. 25 mm is just below the smallest standard flange
/// height (S1002: 28 mm): lifted less, the flanges still hold the wheelset in the track and it
/// may come down again (a bounce, or one wheel lifting in a flange climb while the other touches);
/// lifted more, nothing guides it. A lift up to this answers with no patches and zero forces.
inline constexpr double kMaxElasticLift = 25e-3;

/// Largest |gap| of the wheel nearer to contact in the rigid formulation [m]. There z only sets the
/// gap the constraint reports (the loads are given); an integrator keeps it at micrometres. At a
/// fixed z a roll within the interpolation table (15 mrad) moves the gaps by 11 mm, so the limit is
/// the flange height argument of kMaxElasticLift, both ways: lifted or sunk by more than a flange,
/// z is not a contact height. The other wheel is not checked: a roll given apart from the rigid
/// solution may lift it.
inline constexpr double kMaxRigidGap = 25e-3;

/// Checks a result of query against the limits above:
///  - kElastic: a patch penetrating more than kMaxElasticPenetration -> ContactConfigurationError;
///    both wheels' gaps above kMaxElasticLift -> NoContactError (no_contact_error.hpp);
///  - kRigid: the smaller |gap| of the two wheels above kMaxRigidGap -> ContactConfigurationError.
/// The messages name the wheel, the value, the limit and the pose.
void check_contact_range(const ContactQuery& query, const ContactResult& result);

}  // namespace wrc
