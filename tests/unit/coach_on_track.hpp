// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The Manchester coach (parameters/vehicles/manchester-coach.json) on the R600 layout
/// (parameters/track-curve-R600-1km.json) with ERRI low-level irregularities, as the vehicle
/// benchmark runs it (tests/bench/vehicle_benchmark.sh), for unit tests.

#include <cstdint>
#include <string>

#include "core/track/irregularity_spectrum.hpp"
#include "core/track/track_layout_file.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"

namespace wrc::test {

/// ERRI low-level irregularities (3 to 70 m, 1050 m) of the given seed, as `wrc irregularities
/// --spectrum erri-low --length 1050 --wavelengths 3:70 --seed N` writes them.
inline TrackIrregularity erri_low(std::uint64_t seed) {
  IrregularityGeneration g;
  g.length = 1050.0;
  g.min_wavelength = 3.0;
  g.max_wavelength = 70.0;
  g.seed = seed;
  return generate_irregularity(g);
}

/// The coach on the R600 layout with the irregularities of seed at 30 m/s, no lateral load.
inline VehicleRunSpec coach_on_irregular_track(std::uint64_t seed) {
  VehicleRunSpec spec;
  spec.vehicle = read_vehicle_file(std::string(WRC_PARAMETERS_DIR) + "/vehicles/manchester-coach.json");
  spec.run.wheelset.speed = 30.0;
  spec.run.wheelset.lateral_force = 0.0;
  spec.run.track = read_track_layout_file(std::string(WRC_PARAMETERS_DIR) + "/track-curve-R600-1km.json");
  spec.run.irregularity = erri_low(seed);
  return spec;
}

}  // namespace wrc::test
