// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What the spline contact model is fitted over and how: the configuration box, knots, degrees,
/// sampling, weights and the flange split (Arnold, section 4, equation (1)).

#include <array>
#include <string>
#include <vector>

#include "core/geometry/potential_points.hpp"
#include "core/model_interface/jump_transition.hpp"

namespace wrc {

/// How the breakpoints in y are placed when none are given.
enum class KnotPlacement {
  kUniform,  ///< equal intervals over the box
  kGraded,   ///< denser where the common point's jumps sweep across the box (found from the samples)
};

/// Everything that determines a fitted spline contact model besides the geometry. Boxes and
/// breakpoints are the LEFT wheel's; the right wheel uses the mirror image (y, roll, yaw) ->
/// (-y, -roll, -yaw), sampled from its own exact geometry.
/// The most memory a fit may take [B]: 1 GiB (the machines wrc runs on have 4 GB or more, and a
/// fit shares them with the services and the runs).
inline constexpr double kMaxFitMemory = 1073741824.0;
/// The most branches (stretches of the tread contact point between jumps) a wheel's fit may have
/// [-]: S1002 on UIC60 has 3; a fit that finds more is refused (its memory bound assumes this).
inline constexpr int kMaxFitBranches = 8;

struct SplineFitOptions {
  // Box of the left wheel. A wheelset query needs both wheels inside their boxes, and the right
  // box is the mirror image, so the wheelset's range in y is [max(y_min, -y_max), min(y_max,
  // -y_min)]: a left box reaching below -y_max would only cost knots.
  double y_min = -0.006;    ///< lower end of the lateral shift [m]
  double y_max = 0.006;     ///< upper end [m]: flange contact of S1002/UIC60 starts at ~6.2 mm
  double roll_max = 0.001;  ///< roll in [-roll_max, roll_max] [rad] (rigid contact: |roll| < 0.65 mrad for |y| <= 6 mm)
  double yaw_max = 0.005;   ///< yaw in [-yaw_max, yaw_max] [rad]

  std::array<int, 3> intervals{10, 2, 2};  ///< knot intervals in y, roll, yaw [-], each >= 1
  std::array<int, 3> degrees{3, 3, 3};     ///< polynomial degree in y, roll, yaw [-], 0..3
  KnotPlacement placement = KnotPlacement::kGraded;  ///< breakpoints in y when y_breakpoints is empty
  /// Explicit breakpoints in y (left wheel) [m], strictly increasing from y_min to y_max; when set
  /// they replace intervals[0] and placement.
  std::vector<double> y_breakpoints;
  double grading = 3.0;     ///< kGraded: knot density where jumps sweep, relative to elsewhere, minus 1 [-], >= 0

  double sample_step_y = 1e-4;  ///< spacing of the exact-geometry samples in y [m]
  int roll_samples = 9;     ///< samples in roll [-], at least the basis size in roll (intervals + degree)
  int yaw_samples = 9;      ///< samples in yaw [-], at least the basis size in yaw

  /// The paper's form (transition = 0): weight of samples within jump_band of a jump of the
  /// common point on the tread (an artefact of the rigid one-point view, smoothed by the fit) [-],
  /// in (0, 1]; elsewhere 1. The branch fits do not use it.
  double jump_weight = 1e-2;
  /// Half-width in y of the band around each jump [m]: down-weighted in the paper's form, and in
  /// both forms what the accuracy report leaves out of the continuous region.
  double jump_band = 5e-4;
  /// Largest half-width of the smooth transition between two branches at a jump, in the
  /// difference d of their touching heights [m], >= 0. When > 0 and every sample line has the
  /// same number of tread jumps, each stretch between jumps is a branch of the tread contact
  /// point, fitted on its own (with its continuation past the jumps as a non-lowest minimum), and
  /// two branches are joined by a C2 smooth maximum of their heights within |d| < h, h the
  /// smallest of this value, the Hertz approach at transition_load (the height difference within
  /// which an elastic contact loads both points) and the height difference at which a branch
  /// ends (a fold) on the sample lines; elsewhere the model is that branch's fit alone. 0: one
  /// fit across the jumps, down-weighted within jump_band (the paper's form).
  double transition = kDefaultTransition;
  /// Normal load per wheel whose Hertz approach bounds the transition [N], in [1, 1e6]: the
  /// benchmark's Fz / 2.
  double transition_load = kDefaultTransitionLoad;

  /// Wheel profile slope angle [rad] that separates tread (and flange root) from the flange: the
  /// flange region is s below the first point, going from the taping line towards the flange,
  /// where the profile's slope exceeds this angle. Contact there is flange contact (physical: not
  /// smoothed). 0.7 rad = 40 deg lies between S1002's flange-root contacts (< 25 deg) and its
  /// flank (> 45 deg).
  double flange_angle = 0.7;
  double clearance_cap = 1e-3;  ///< the flange clearance is capped at this value [m] (only its zero matters)

  PotentialPointSearch search;  ///< potential-point scan of the exact geometry
  int threads = 0;              ///< sampling threads; 0 = one per core

  /// The paper's benchmark variant: cubic in (y, roll) on 15 x 4 intervals, quadratic
  /// interpolation in yaw (3 yaw samples, one quadratic interval).
  static SplineFitOptions paper_benchmark();

  /// Throws std::invalid_argument naming the first bad value (box not increasing or not finite,
  /// yaw beyond the validated 0.06 rad, counts or degrees out of range, too few samples for the
  /// basis, weights or band not positive, breakpoints not spanning the box in order).
  void validate() const;

  /// Parses "NxMxK" (or one number N for all three) as three whole numbers in [lo, hi]; throws
  /// std::invalid_argument "<what>: '<text>' ..." otherwise.
  static std::array<int, 3> parse_triple(const std::string& text, const std::string& what, int lo, int hi);

  /// Samples of each line in y: (y_max - y_min) / sample_step_y, rounded, + 1 [-].
  int y_samples() const;

  /// The most memory a fit of these options needs [B], known before any sampling: both wheels'
  /// exact samples (kept for the report), one wheel's continuations of up to kMaxFitBranches
  /// branches, one branch's fitted values and its normal equations, and 16 MB for the sampling
  /// threads and the profiles' tables. validate() refuses options above kMaxFitMemory.
  double fit_memory_bytes() const;

  /// Canonical text of every option (numbers with 17 digits): part of the model's cache key.
  std::string canonical_text() const;
};

}  // namespace wrc
