// SPDX-License-Identifier: Apache-2.0
#include "core/profile/uic60.hpp"

#include <algorithm>
#include <cmath>

namespace wrc {
namespace {

constexpr double kCrownRadius = 0.300;
constexpr double kShoulderRadius = 0.080;
constexpr double kCornerRadius = 0.013;
constexpr double kFlankU = 0.036;        // head width 72.000 mm
constexpr double kFlankSlope = 1.0 / 20.0;  // 1:20 to the vertical
constexpr double kDepth = 0.025;         // flank continued to 25 mm below the crown
constexpr double kEnShoulderCentreU = 7.500533e-3;
constexpr double kMbShoulderCentreU = 7.7e-3;

// Upper half of a circle with centre (cu, cv) and radius r, at |u| = x (x >= 0), in the
// field-side orientation; the caller mirrors the slope for u < 0.
ProfileSample upper_arc(double cu, double cv, double r, double x) {
  const double dx = x - cu;
  const double q = std::max(r * r - dx * dx, 1e-12 * r * r);
  const double root = std::sqrt(q);
  const double inv = 1.0 / root;  // one division: slope -dx/root, second derivative -r^2/root^3
  return {cv + root, -dx * inv, -r * r * inv * inv * inv};
}

}  // namespace

Uic60Geometry make_uic60_geometry(double shoulder_centre_u, double depth) {
  Uic60Geometry g;
  g.crown_radius = kCrownRadius;
  g.shoulder_radius = kShoulderRadius;
  g.corner_radius = kCornerRadius;
  g.flank_u = kFlankU;
  g.flank_slope = kFlankSlope;
  // R80 inside R300, tangent: |c80 - c300| = R300 - R80.
  const double d1 = kCrownRadius - kShoulderRadius;
  g.shoulder_centre_u = shoulder_centre_u;
  g.shoulder_centre_v = -kCrownRadius + std::sqrt(d1 * d1 - shoulder_centre_u * shoulder_centre_u);
  g.crown_end = kCrownRadius * shoulder_centre_u / d1;
  // R13 touches the flank at u = 36 mm: its centre lies 13 mm inside along the flank normal
  // (1, slope)/sqrt(1 + slope^2); R13 inside R80, tangent: |c13 - c80| = R80 - R13.
  const double n = std::sqrt(1.0 + kFlankSlope * kFlankSlope);
  g.corner_centre_u = kFlankU - kCornerRadius / n;
  const double d2 = kShoulderRadius - kCornerRadius;
  const double dx = g.corner_centre_u - g.shoulder_centre_u;
  g.corner_centre_v = g.shoulder_centre_v + std::sqrt(d2 * d2 - dx * dx);
  g.flank_v = g.corner_centre_v + kCornerRadius * kFlankSlope / n;
  g.shoulder_end = g.shoulder_centre_u + kShoulderRadius * dx / d2;
  // Flank u = flank_u + slope * (flank_v - v), continued down to v = -depth.
  g.half_width = kFlankU + kFlankSlope * (g.flank_v + depth);
  return g;
}

Uic60Profile::Uic60Profile(Uic60Variant variant)
    : variant_(variant),
      geometry_(make_uic60_geometry(
          variant == Uic60Variant::kEn60E1 ? kEnShoulderCentreU : kMbShoulderCentreU, kDepth)) {}

ProfileSample Uic60Profile::evaluate(double u) const {
  const Uic60Geometry& g = geometry_;
  const double x = std::fabs(u);
  ProfileSample p;
  if (x <= g.crown_end) {
    // Centre (0, -R300): the top of the arc is the origin.
    p = upper_arc(0.0, -g.crown_radius, g.crown_radius, x);
  } else if (x <= g.shoulder_end) {
    p = upper_arc(g.shoulder_centre_u, g.shoulder_centre_v, g.shoulder_radius, x);
  } else if (x <= g.flank_u) {
    p = upper_arc(g.corner_centre_u, g.corner_centre_v, g.corner_radius, x);
  } else {
    // v = flank_v - (x - flank_u) / slope: a straight line.
    p = {g.flank_v - (x - g.flank_u) / g.flank_slope, -1.0 / g.flank_slope, 0.0};
  }
  if (u < 0.0) {
    p.slope = -p.slope;
  }
  return p;
}

double Uic60Profile::lower() const { return -geometry_.half_width; }
double Uic60Profile::upper() const { return geometry_.half_width; }

std::vector<double> Uic60Profile::breakpoints() const {
  const Uic60Geometry& g = geometry_;
  return {-g.flank_u, -g.shoulder_end, -g.crown_end, g.crown_end, g.shoulder_end, g.flank_u};
}

ProfileSide Uic60Profile::side() const { return ProfileSide::kRail; }

std::string Uic60Profile::name() const {
  return variant_ == Uic60Variant::kEn60E1 ? "UIC60 (EN 60E1 analytic)"
                                            : "UIC60-MB (Manchester variant, analytic)";
}

}  // namespace wrc
