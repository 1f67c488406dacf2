// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Following contact points from one answer to the next query: the rule a caller applies after an
/// accepted step (the points it tracks become the points the model answered), and the same rule
/// inside one batch, where a configuration may follow the points answered for an earlier one
/// (ContactQuery::follows), so that a state and the state the caller will ask next, after
/// following the first's points, travel in one round trip.

#include <array>
#include <vector>

#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// The points a caller tracks after answered: tracked[w] becomes the wheel's answered point
/// (WheelConstraint::s_wheel), and second_tracked[w], where set (not NaN) and answered has a
/// second point on that wheel, that second point's [m].
void follow_answered_points(const ContactResult& answered, std::array<double, 2>& tracked,
                            std::array<double, 2>& second_tracked);

/// Applies query's ContactQuery::follows before it is evaluated as configuration index of a batch
/// whose earlier answers are answered (answered.size() == index; an entry without a value had no
/// answer): nothing for follows == 0, else follow_answered_points() of answer follows - 1.
/// @throws std::invalid_argument naming the configuration when follows is not in [0, index], or
///         the configuration it follows has no answer.
void apply_follows(const std::vector<const ContactResult*>& answered, int index, ContactQuery& query);

}  // namespace wrc
