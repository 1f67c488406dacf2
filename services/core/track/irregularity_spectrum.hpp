// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Track irregularities generated from a published power spectral density (docs/track.md):
/// the ERRI (ORE B176) low and high levels and the FRA track classes 1 to 6, as a sum of cosines
/// with random phases over a wavelength band, sampled for TrackIrregularity.

#include <cstdint>
#include <string>
#include <vector>

#include "core/track/track_irregularity.hpp"

namespace wrc {

/// A published spectrum.
enum class IrregularitySpectrum { kErriLow, kErriHigh, kFra1, kFra2, kFra3, kFra4, kFra5, kFra6 };
/// "erri-low", "erri-high", "fra-1" ... "fra-6".
const char* irregularity_spectrum_name(IrregularitySpectrum spectrum);
/// Every spectrum, in the order above.
std::vector<IrregularitySpectrum> irregularity_spectra();
/// The spectrum named name. @throws std::invalid_argument listing the names.
IrregularitySpectrum parse_irregularity_spectrum(const std::string& name);

/// One-sided power spectral density of a channel at the spatial angular frequency omega [rad/m]
/// [m^2 / (rad/m)]: the variance of the channel is the integral over omega from 0 to infinity.
/// The ERRI spectra define no gauge: 0 there.
/// @throws std::invalid_argument for omega not positive and finite.
double irregularity_density(IrregularitySpectrum spectrum, IrregularityChannel channel, double omega);

/// What to generate.
struct IrregularityGeneration {
  IrregularitySpectrum spectrum = IrregularitySpectrum::kErriLow;
  double length = 1000.0;          ///< from s = 0 to s = length [m], > 0
  double spacing = 0.25;           ///< distance of the samples [m], at least kMinIrregularitySpacing
  double min_wavelength = 3.0;     ///< shortest wavelength generated [m] (> 4 spacings)
  double max_wavelength = 150.0;   ///< longest [m], > min_wavelength
  std::uint64_t seed = 1;          ///< of the random phases: the same seed, the same track
  /// Over this distance from s = 0 the channels are faded in from 0 (a raised cosine) so that a run
  /// starts on the nominal track [m] (0: none).
  double fade_in = 20.0;

  /// @throws std::invalid_argument naming the first value out of its range.
  void validate() const;
};

/// The irregularities: channel k is sum_j sqrt(2 S_k(omega_j) d_omega) cos(omega_j s + phase_kj)
/// over omega_j evenly spaced across the band (spacing d_omega at most 2 pi / length, so that the
/// signal does not repeat within the length), the phases uniform in [0, 2 pi) from the seed,
/// independent per channel; sampled every spacing.
/// @throws std::invalid_argument when a channel leaves kMaxIrregularity (a worse class over a wide
///         band), naming it, or as validate().
TrackIrregularity generate_irregularity(const IrregularityGeneration& generation);

/// The variance the spectrum puts into the band of generation for a channel [m^2] (the integral of
/// the density over the band): what the generated channel's mean square approaches.
double band_variance(const IrregularityGeneration& generation, IrregularityChannel channel);

}  // namespace wrc
