// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The profile abstraction: a wheel or rail cross-section as a piecewise smooth (C1, C2 inside each
/// piece) function of one lateral coordinate, in SI units (metres). Coordinates and signs:
/// docs/conventions.md.
///
/// Wheel profiles: lateral coordinate s [m] from the taping line (70 mm from the inner face),
/// positive towards the field side (flange at s < 0); height F(s) [m] = radius above the nominal
/// rolling radius r0, so the wheel radius is R(s) = r0 + F(s). F(0) = 0 for standard profiles.
///
/// Rail profiles: lateral coordinate u [m] from the profile's reference point (the crown top of
/// the untilted rail for analytic profiles), positive towards the field side (gauge corner at u < 0);
/// height v(u) [m] upwards, v = 0 at the reference point. A rail profile may already contain the
/// rail inclination (cant), as the Manchester benchmark file does: built_in_cant() says by how much.

#include <memory>
#include <string>
#include <vector>

namespace wrc {

/// Which body a profile describes.
enum class ProfileSide { kWheel, kRail };

/// Height and its first two derivatives at one lateral coordinate.
struct ProfileSample {
  double height = 0;             ///< F(s) or v(u) [m]
  double slope = 0;              ///< dF/ds or dv/du [-]
  /// d2F/ds2 or d2v/du2 [1/m]: the plain second derivative, not the geometric curvature
  /// -F'' / (1 + F'^2)^{3/2} of ContactPoint (docs/conventions.md, "Profile coordinates").
  double second_derivative = 0;
};

/// A wheel or rail profile function on [lower(), upper()]. Smoothness of the implementations:
/// the height and slope are continuous (C1) over the whole domain, and inside each piece of its
/// definition (between consecutive breakpoints()) the function is C2, usually analytic. At a
/// breakpoint the second derivative may jump: arcs, lines and polynomials joined tangentially
/// (UIC60, S1002) meet with equal slope but different curvature. Interpolating file splines are
/// C2 everywhere and list no breakpoints; cones and circular heads are a single piece. The one
/// exception to C1 is the published S1002 data, whose height and slope jump very slightly at two
/// section joints (s1002.hpp, docs/profiles.md).
class Profile {
 public:
  virtual ~Profile() = default;

  /// Height and derivatives at lateral coordinate s [m]; s must lie in [lower(), upper()]
  /// (callers clamp); implementations never return NaN inside the domain.
  virtual ProfileSample evaluate(double s) const = 0;

  /// Domain of the lateral coordinate [m].
  virtual double lower() const = 0;
  virtual double upper() const = 0;

  /// Lateral coordinates [m] where the definition changes piece (arc ends, polynomial ends; the
  /// knots of an interpolating spline are not listed, it is C2 across them): the second
  /// derivative may jump there, so root scanners use them as extra sample points.
  virtual std::vector<double> breakpoints() const { return {}; }

  /// Wheel or rail.
  virtual ProfileSide side() const = 0;

  /// Human-readable name, e.g. "S1002 (analytic)" or "file MBench_S1002_v3.prw".
  virtual std::string name() const = 0;

  /// Rail inclination already contained in the profile data [rad] (rotation of the rail's own
  /// vertical axis towards the track centre); 0 for untilted profiles. Always 0 for wheels.
  virtual double built_in_cant() const { return 0.0; }
};

using ProfilePtr = std::shared_ptr<const Profile>;

}  // namespace wrc
