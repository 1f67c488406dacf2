// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The UIC60 rail head (EN 13674-1 60E1 construction) and its Manchester-benchmark variant.

#include <string>
#include <vector>

#include "core/profile/profile.hpp"

namespace wrc {

/// Which UIC60 head construction to build.
enum class Uic60Variant {
  kEn60E1,     ///< EN 60E1: R300/R80 junction at half-width 10.228 mm, R80 centre at 7.500533 mm.
  kManchester  ///< Manchester benchmark "UIC60-MB": R80 centre at 7.7 mm (junction at 10.5 mm).
};

/// Geometry of the symmetric UIC60 head in rail-local coordinates [m]: u lateral (positive to the
/// field side), v up, origin at the crown top. Neighbouring pieces are tangent by construction
/// (equal slope at each joint), which makes the head C1 but not C2.
struct Uic60Geometry {
  double crown_radius = 0;     ///< R300 [m], centre (0, -crown_radius)
  double shoulder_radius = 0;  ///< R80 [m]
  double corner_radius = 0;    ///< R13 [m]
  double shoulder_centre_u = 0;  ///< |u| of the R80 centre [m]
  double shoulder_centre_v = 0;  ///< v of the R80 centre [m]
  double corner_centre_u = 0;    ///< |u| of the R13 centre [m]
  double corner_centre_v = 0;    ///< v of the R13 centre [m]
  double crown_end = 0;     ///< |u| of the R300/R80 tangency [m]
  double shoulder_end = 0;  ///< |u| of the R80/R13 tangency [m]
  double flank_u = 0;       ///< |u| of the R13/flank tangency [m] (36 mm: head width 72 mm)
  double flank_v = 0;       ///< v of the R13/flank tangency [m]
  double flank_slope = 0;   ///< flank inclination to the vertical, du/dv magnitude [-] (1:20)
  double half_width = 0;    ///< |u| of the domain end on the flank [m]
};

/// Computes the tangent-arc construction for a given R80 centre offset [m] from the rail axis.
/// The R300 crown (centre (0, -0.3)) and the R80 shoulder are internally tangent; the R13 gauge
/// corner is internally tangent to R80 and touches the 1:20 flank at u = 36 mm.
/// @param shoulder_centre_u |u| of the R80 centre [m]: 7.500533e-3 (EN 60E1) or 7.7e-3 (MB).
/// @param depth how far below the crown the flank is continued [m] (domain end).
Uic60Geometry make_uic60_geometry(double shoulder_centre_u, double depth);

/// UIC60 rail head as a function v(u) [m]. Domain: the flanks are continued down to 25 mm below the
/// crown on both sides (|u| <= 36.54 mm). The head is symmetric. Smoothness: C1 everywhere (the
/// arcs and the flank are joined tangentially, so height and slope are continuous), C2 and indeed
/// analytic inside each piece, but NOT C2 at the six joints that breakpoints() lists: there the
/// second derivative jumps with the curvature (1/R300 to 1/R80 at the crown end, 1/R80 to 1/R13,
/// 1/R13 to 0 where the flank begins). Construction and sources: docs/profiles.md, "UIC60 / 60E1
/// rail head".
class Uic60Profile final : public Profile {
 public:
  /// Builds the EN 60E1 construction or the Manchester variant.
  explicit Uic60Profile(Uic60Variant variant);

  /// Height v(u) [m], slope dv/du [-], second derivative d2v/du2 [1/m].
  ProfileSample evaluate(double u) const override;
  /// Gauge-side end of the domain [m] (on the flank, 25 mm below the crown).
  double lower() const override;
  /// Field-side end of the domain [m].
  double upper() const override;
  /// Arc and flank junctions on both sides [m], increasing.
  std::vector<double> breakpoints() const override;
  /// Always ProfileSide::kRail.
  ProfileSide side() const override;
  /// "UIC60 (EN 60E1 analytic)" or "UIC60-MB (Manchester variant, analytic)".
  std::string name() const override;

  /// The construction parameters [m].
  const Uic60Geometry& geometry() const { return geometry_; }

 private:
  Uic60Variant variant_;
  Uic60Geometry geometry_;
};

}  // namespace wrc
