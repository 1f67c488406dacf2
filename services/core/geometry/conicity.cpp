// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/conicity.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wrc {

double equivalent_conicity(const RigidWheelsetSolver& solver, double amplitude, int samples, double yaw) {
  if (!(amplitude > 0 && amplitude <= 0.02) || samples < 8 || !std::isfinite(yaw)) {
    std::ostringstream msg;
    msg << "equivalent conicity: amplitude " << amplitude << " m must lie in (0, 0.02], samples " << samples
        << " must be >= 8";
    throw std::invalid_argument(msg.str());
  }
  double sum = 0;
  RigidContact previous;
  for (int k = 0; k < samples; ++k) {
    const double t = 2 * M_PI * (k + 0.5) / samples;
    const double y = amplitude * std::sin(t);
    const RigidContact c = k == 0 ? solver.solve(y, yaw) : solver.solve(y, yaw, previous);
    sum += c.delta_r() * std::sin(t);
    previous = c;
  }
  // (1/(2 pi A)) * (2 pi / N) * sum
  return sum / (samples * amplitude);
}

}  // namespace wrc
