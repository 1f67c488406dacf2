// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/segment_settings.hpp"

#include "core/dynamics/wheelset_equations.hpp"

namespace wrc {
namespace {

// [-] relative change of IDA's cj (alpha / h) beyond which the Newton matrix is rebuilt: 0, at
// every change (IDA's default 0.25). One Jacobian is one batched contact query, a round trip like
// one Newton iteration, and the fresh matrix saves more iterations than it costs. Measured
// in-process (contact queries, IDA's default -> this): the paper's benchmark spline 1173 -> 1115,
// multipoint 5338 -> 4047, interp 1927 -> 1705, onepoint 13509 -> 13791; the 1 km irregular curve
// with the spline model 75806 -> 59355 (Newton iterations 2.15 -> 1.34 per step).
constexpr double kNewtonMatrixCjChange = 0.0;
// Corrector iterations per step of the rigid (index-2) formulation (IDA's default: 4). The index-2
// Newton matrix is ill-conditioned at small steps (~1/h^2); right after a switch on the switching
// surface its corrector may need more than 4 (seen: mu = 0.01, y0 = 1e-8, the first step after a
// restart failing down to h = 2.5e-15 with 4, passing with 8). A step that converges in 4 is
// unchanged.
constexpr int kMaxNewtonIterations = 8;

}  // namespace

IdaSegment segment_settings_without_unknowns(const IntegratorSettings& settings, bool rigid) {
  IdaSegment segment;
  segment.relative_tolerance = settings.relative_tolerance;
  segment.max_step = settings.max_step;
  segment.newton_matrix_cj_change = kNewtonMatrixCjChange;
  if (rigid) {
    segment.index2 = true;  // the multipliers of an index-2 system are left out of the error test
    segment.max_newton_iterations = kMaxNewtonIterations;
  }
  return segment;
}

void append_unknown(IdaSegment& segment, double absolute_tolerance, bool differential) {
  segment.absolute_tolerance.push_back(absolute_tolerance);
  segment.differential.push_back(differential ? 1.0 : 0.0);
}

void append_wheelset_unknowns(IdaSegment& segment, const IntegratorSettings& settings, int n) {
  for (int k = 0; k < n; ++k)
    append_unknown(segment,
                   k < kPoseUnknowns ? settings.position_tolerance
                   : k <= kUnknownSpinRate ? settings.velocity_tolerance
                                           : kScaledForceTolerance,
                   k <= kUnknownSpinRate);
}

}  // namespace wrc
