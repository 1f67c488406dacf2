// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `wrc stability` writes of a speed scan, for the lone wheelset and for a vehicle alike: the
// CSV of every eigenvalue at every speed and the eigenvalue plot (root locus, largest real part
// against speed with the critical speed marked).

#include <string>
#include <vector>

#include "core/dynamics/linear_stability.hpp"

namespace wrc::cli {

/// The eigenvalues at one speed, largest real part first.
struct StabilityScanRow {
  double speed = 0;                  ///< [m/s]
  std::vector<StabilityMode> modes;  ///< every eigenvalue with its kind
  /// Per mode, the body with the largest share of its kinetic energy (a vehicle); empty for the
  /// lone wheelset.
  std::vector<std::string> bodies;
};

/// speed, real part, imaginary part, frequency, damping ratio, kind, (body,) least damped; units in
/// the header. @throws std::runtime_error when path cannot be written.
void write_stability_csv(const std::string& path, const std::vector<StabilityScanRow>& scan);

/// The eigenvalue plot (.png or .svg) through gnuplot; the spin modes are left out of the locus.
void draw_stability(const std::string& path, const std::vector<StabilityScanRow>& scan, const CriticalSpeed& critical,
                    const std::string& title);

}  // namespace wrc::cli
