// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The oscillation of a sampled signal (the lateral shift y of a hunting wheelset): its peaks and
/// troughs, the amplitude and period of the last cycles, and whether the amplitude is constant,
/// growing or decaying (docs/bifurcation.md). Pure signal analysis, no simulation.

#include <limits>
#include <vector>

namespace wrc {

/// The last cycles of an oscillation.
struct CycleMeasurement {
  int cycles = 0;          ///< complete cycles (a peak and the trough after it) found [-]
  double amplitude = 0;    ///< half peak-to-peak of the last cycle [signal unit]; 0 without a cycle
  double mean = 0;         ///< (peak + trough) / 2 of the last cycle [signal unit]
  double period = 0;       ///< mean time between the last peaks [s]; 0 with fewer than 2 peaks
  /// Amplitude ratio of successive cycles, the geometric mean over the last up to `periods` + 1
  /// cycles [-]: 1 a converged limit cycle, < 1 decaying, > 1 growing; 0 with fewer than 2 cycles.
  double growth = 0;
  double largest = 0;      ///< largest |x| of the measured samples [signal unit]
  /// The largest half peak-to-peak of the measured cycles [signal unit]: the envelope of an
  /// oscillation whose cycles differ (a drift of the mean does not enter); 0 without a cycle.
  double largest_amplitude = 0;

  /// 1 / period [Hz]; 0 without a period.
  double frequency() const { return period > 0 ? 1.0 / period : 0.0; }
};

/// Measures the oscillation of x(t) over the samples with from <= t < to [s]. Peaks and troughs
/// are the samples larger (smaller) than both neighbours, their value and time refined by the
/// parabola through the three samples, and counted when they differ from the last counted extremum
/// of the other kind by more than 1 % of the range of x over the measured samples; the period is
/// the mean spacing of the last up to `periods` + 1 peaks, the growth the mean ratio of the last up
/// to `periods` + 1 cycles. @throws std::invalid_argument when t and x differ in size, t is not
/// increasing, or periods < 1.
CycleMeasurement measure_cycle(const std::vector<double>& t, const std::vector<double>& x, double from,
                               int periods = 3, double to = std::numeric_limits<double>::infinity());

/// Half the range (largest minus smallest x) over the samples with from <= t < to, both [s]
/// [signal unit]; 0 without samples there. @throws std::invalid_argument when t and x differ in
/// size.
double half_range(const std::vector<double>& t, const std::vector<double>& x, double from, double to);

}  // namespace wrc
