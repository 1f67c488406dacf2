// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The first speed of a scan where a growth rate crosses 0 from below, refined by the Illinois
/// variant of regula falsi: one search for the wheelset's and the vehicle's linear stability
/// (linear_stability.hpp, core/vehicle_dynamics/vehicle_linear_stability.hpp).

#include <cmath>
#include <cstddef>
#include <vector>

namespace wrc {

/// Where the growth rate crossed 0, and the linearisation there.
template <typename Linearised>
struct GrowthCrossing {
  bool found = false;      ///< false: no crossing in the scan
  double speed = 0;        ///< [m/s]
  Linearised at{};         ///< the linearisation at speed
  int linearisations = 0;  ///< linearisations of the refinement [-]
};

/// The first pair of neighbours of scan (linearisations at increasing speeds, each with a member
/// speed [m/s]) whose growth goes from < 0 to >= 0, refined until the bracket is below
/// relative_tolerance of the speed (at most 100 linearisations). growth(l) gives a linearisation's
/// largest real part [1/s]; linearise(v) linearises at v [m/s].
template <typename Linearised, typename Linearise, typename Growth>
GrowthCrossing<Linearised> first_growth_crossing(const std::vector<Linearised>& scan, Linearise linearise,
                                                 Growth growth, double relative_tolerance) {
  GrowthCrossing<Linearised> c;
  for (std::size_t i = 0; i + 1 < scan.size(); ++i) {
    if (!(growth(scan[i]) < 0.0 && growth(scan[i + 1]) >= 0.0)) continue;
    double a = scan[i].speed, fa = growth(scan[i]);
    double b = scan[i + 1].speed, fb = growth(scan[i + 1]);
    Linearised at = scan[i + 1];
    // Illinois: regula falsi that halves the value of an end kept twice, so both ends move.
    for (int iteration = 0; iteration < 100 && std::abs(b - a) > relative_tolerance * b && fb != 0.0; ++iteration) {
      const double v = (a * fb - b * fa) / (fb - fa);
      at = linearise(v);
      ++c.linearisations;
      const double fv = growth(at);
      if ((fv < 0.0) == (fb < 0.0)) {
        fa *= 0.5;
      } else {
        a = b;
        fa = fb;
      }
      b = v;
      fb = fv;
    }
    c.found = true;
    c.speed = b;
    c.at = at;
    return c;
  }
  return c;
}

}  // namespace wrc
