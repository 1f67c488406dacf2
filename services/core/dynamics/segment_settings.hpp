// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// How IDA integrates a run's segment (IdaSegment): the tolerances and differential flags of a
/// wheelset's unknowns, the Newton matrix rule and the index-2 settings of rigid contact. One place
/// for the lone wheelset's run and a vehicle's, which assembles its wheelsets' unknowns with its
/// other bodies'.

#include "core/dynamics/ida_integrator.hpp"
#include "core/dynamics/wheelset_parameters.hpp"

namespace wrc {

/// [-] IDA's absolute tolerance of the scaled normal forces and multipliers (they are left out of
/// the error test; it only scales the Newton test).
inline constexpr double kScaledForceTolerance = 1e-6;

/// [-] relative change of cj beyond which a vehicle's Newton matrix is rebuilt (IDA's default; the
/// lone wheelset's: at every change, segment_settings.cpp). A vehicle's matrix costs a residual
/// evaluation per column group and unknown (52 for the coach, jacobian_column_groups.hpp), more
/// than the corrector iterations a fresh one saves. Measured, the coach on the R600 layout with
/// irregularities, spline (at every change -> 0.25): 5 s in-process 2.29 -> 1.38 s wall (1871 ->
/// 622 matrices, the same 5.5e3 steps, the wheelsets' final y within 5e-9 m); 3 s over the bus
/// 1.99 -> 1.82 s although with 30 % more contact queries (8509 -> 11049).
inline constexpr double kVehicleNewtonMatrixCjChange = 0.25;

/// The settings of a segment without its unknowns: relative tolerance, largest step, a new Newton
/// matrix at every change of cj, and with rigid contact the index-2 error test and corrector
/// iterations (no event functions).
IdaSegment segment_settings_without_unknowns(const IntegratorSettings& settings, bool rigid);

/// Appends n unknowns of a wheelset in the layout of core/dynamics/wheelset_equations.hpp: the pose
/// (position tolerance), the rates and spin (velocity tolerance) differential, the normal forces
/// and multipliers algebraic.
void append_wheelset_unknowns(IdaSegment& segment, const IntegratorSettings& settings, int n);

/// Appends one unknown [its unit] with absolute tolerance atol, differential or algebraic.
void append_unknown(IdaSegment& segment, double absolute_tolerance, bool differential);

}  // namespace wrc
