// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Which bodies' Jacobian columns a forward-difference Jacobian of a vehicle may perturb together
/// (Curtis, Powell and Reid's grouping of structurally orthogonal columns, by body). A body's
/// residual rows depend on its own state and on the states of the bodies an element joins it to
/// (its closed neighbourhood; an element to the track joins nothing, a wheelset's contact is its
/// own). Bodies whose closed neighbourhoods are disjoint share no row, so one residual evaluation
/// with all of them perturbed gives each one's column exactly, as if it were perturbed alone: the
/// rows of its neighbourhood are its column, every other row of it is 0.

#include <cstddef>
#include <vector>

#include "core/vehicle/vehicle_description.hpp"

namespace wrc {

struct JacobianColumnGroups {
  /// Groups of body indices (in the vehicle's order) perturbed together; every body in exactly one.
  std::vector<std::vector<std::size_t>> groups;
  /// Each body's closed neighbourhood: itself and the bodies an element joins it to, ascending.
  std::vector<std::vector<std::size_t>> neighbourhood;
};

/// The groups of a valid vehicle, greedily: each body, in the vehicle's order, joins the first
/// group none of whose bodies' neighbourhoods meets its own. The Cooperrider car and the Manchester
/// coach (car body, two frames, four wheelsets): 4 groups for 7 bodies.
JacobianColumnGroups jacobian_column_groups(const VehicleDescription& vehicle);

}  // namespace wrc
