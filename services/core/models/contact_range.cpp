// SPDX-License-Identifier: Apache-2.0
#include "core/models/contact_range.hpp"

#include <cmath>

#include "core/model_interface/no_contact_error.hpp"
#include "core/models/one_point_model.hpp"
#include "core/numerics/length_text.hpp"

namespace wrc {

void check_contact_range(const ContactQuery& query, const ContactResult& result) {
  // The pose is written out only for an error: formatting it costs more than the checks.
  const auto at = [&query] { return " at " + describe_pose(query.pose); };
  if (query.formulation == ContactFormulation::kRigid) {
    // The wheel nearer to contact: a roll may lift the other one (its load is the caller's).
    const std::size_t w = std::fabs(result.wheels[0].gap) <= std::fabs(result.wheels[1].gap) ? 0 : 1;
    const double gap = result.wheels[w].gap;
    if (std::fabs(gap) > kMaxRigidGap)
      throw ContactConfigurationError(std::string("rigid contact: the ") + side_name(static_cast<WheelSide>(w)) +
                                      " wheel, the nearer to contact, has a gap of " + in_mm(gap) + ", beyond +-" +
                                      in_mm(kMaxRigidGap) + " (" +
                                      (gap > 0 ? "lifted off" : "sunk into") +
                                      " its rail: z is not a contact height)" + at());
    return;
  }
  for (const ContactPatch& patch : result.patches) {
    if (patch.penetration > kMaxElasticPenetration)
      throw ContactConfigurationError("elastic contact: penetration " + in_mm(patch.penetration) + " at s = " +
                                      in_mm(patch.point.s) + " is beyond " + in_mm(kMaxElasticPenetration) +
                                      ", where Hertz's theory holds (the wheelset is sunk into its rails)" + at());
  }
  const double lowest = std::fmin(result.wheels[0].gap, result.wheels[1].gap);
  if (lowest > kMaxElasticLift)
    throw NoContactError("no contact: the wheelset is lifted, the left wheel " + in_mm(result.wheels[0].gap) +
                         " and the right wheel " + in_mm(result.wheels[1].gap) + " above its rail (more than " +
                         in_mm(kMaxElasticLift) + ")" + at());
}

}  // namespace wrc
