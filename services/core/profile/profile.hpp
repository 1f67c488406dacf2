#pragma once
/// @file
/// The profile abstraction: a wheel or rail cross-section as a C2 function of one lateral
/// coordinate, in SI units (metres).
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
  double height = 0;     ///< F(s) or v(u) [m]
  double slope = 0;      ///< dF/ds or dv/du [-]
  double curvature = 0;  ///< d2F/ds2 or d2v/du2 [1/m] (second derivative, not the geometric curvature)
};

/// A wheel or rail profile function, continuous with continuous first and second derivatives
/// inside [lower(), upper()].
class Profile {
 public:
  virtual ~Profile() = default;

  /// Height and derivatives at lateral coordinate s [m]; s must lie in [lower(), upper()]
  /// (callers clamp); implementations never return NaN inside the domain.
  virtual ProfileSample evaluate(double s) const = 0;

  /// Domain of the lateral coordinate [m].
  virtual double lower() const = 0;
  virtual double upper() const = 0;

  /// Lateral coordinates [m] where the definition changes piece (arc ends, polynomial ends,
  /// spline knots are not listed): root scanners use them as extra sample points.
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
