// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Track irregularities along the distance travelled: the four channels of a track's geometric
/// quality (EN 13848-1's alignment, longitudinal level, cross-level and gauge), sampled (from a
/// measured-track file or a generated spectrum) and interpolated by the natural spline of degree 7,
/// so that the rails under a travelling wheelset move smoothly (docs/track.md).

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/numerics/natural_spline.hpp"

namespace wrc {

/// The channels, in the order of the file's columns and of TrackIrregularity's arrays.
enum class IrregularityChannel { kAlignment, kVerticalLevel, kCrossLevel, kGauge };
inline constexpr int kIrregularityChannelCount = 4;
inline constexpr std::array<IrregularityChannel, kIrregularityChannelCount> kIrregularityChannels{
    IrregularityChannel::kAlignment, IrregularityChannel::kVerticalLevel, IrregularityChannel::kCrossLevel,
    IrregularityChannel::kGauge};
/// "alignment", "vertical_level", "cross_level", "gauge": the channel's name in files, messages
/// and the command line.
const char* irregularity_channel_name(IrregularityChannel channel);

/// Largest |value| of a channel sample [m]: 30 mm, beyond EN 13848-5's immediate-action limits of
/// every channel at every speed class, so that a rail's offset (alignment +- gauge / 2) stays well
/// inside what a contact query accepts (kMaxRailOffset, 50 mm).
inline constexpr double kMaxIrregularity = 0.03;
/// Most samples a layout of irregularities may have [-]: 20 km at 1 m, 5 km at 0.25 m; the run
/// command carries them on the bus (five doubles each) within its 1 MiB.
inline constexpr std::size_t kMaxIrregularitySamples = 20000;
/// Largest |s| of a sample [m]: 10 000 km, ten times the longest layout segment; at this distance
/// a double still resolves the smallest spacing to 2e-9 m (farther out the spline's system loses
/// its samples' differences and turns singular).
inline constexpr double kMaxIrregularityDistance = 1e7;
/// Smallest spacing of two samples [m] (a measuring trolley samples every 0.25 m or more).
inline constexpr double kMinIrregularitySpacing = 1e-3;
/// Degree of the spline between samples [-]: 7, C6 across the samples. The rails' rates enter the
/// constraints, so a wheelset's velocities follow the channels' first derivative; IDA's BDF of
/// order up to 5 estimates its error from the sixth time derivative of the velocities, which a
/// cubic spline's jumping third derivative (every 8 ms at 0.25 m and 30 m/s) made a train of
/// spikes: three quarters of the steps of a 1 km run went to them (docs/track.md).
inline constexpr int kIrregularitySplineDegree = 7;
/// Fewest samples [-]: what the natural spline of degree 7 needs to be unique.
inline constexpr std::size_t kMinIrregularitySamples = (kIrregularitySplineDegree + 1) / 2;

/// A sample that breaks a rule of TrackIrregularity; what() names it ("irregularities: sample 12
/// (s = 3 m): ...").
class IrregularitySampleError : public std::invalid_argument {
 public:
  IrregularitySampleError(std::size_t sample, const std::string& message)
      : std::invalid_argument(message), sample_(sample) {}
  /// Index of the sample [-].
  std::size_t sample() const { return sample_; }

 private:
  std::size_t sample_;
};

/// The channels at one distance s, with their slopes along the track. Rails: left at y > 0.
struct IrregularityPoint {
  /// Lateral position of the track centre line, the mean of the two rails' lateral positions,
  /// > 0 to the left [m].
  double alignment = 0;
  /// Height of the track, the mean of the two rails' heights, > 0 up [m].
  double vertical_level = 0;
  /// Height of the left rail minus that of the right one [m] (a cant error).
  double cross_level = 0;
  /// Gauge deviation, the left rail's lateral position minus the right one's (> 0: wider) [m].
  double gauge = 0;
  /// d/ds of each channel, in the same order [-].
  std::array<double, kIrregularityChannelCount> slope{0, 0, 0, 0};
  /// The value of a channel [m].
  double value(IrregularityChannel channel) const;
};

/// The irregularities along a track: samples at strictly increasing distances, each channel the
/// natural spline of degree kIrregularitySplineDegree through its samples. Before the first and after the last sample the channels keep
/// their end values (slope 0 there: the rails run on parallel to the nominal track).
class TrackIrregularity {
 public:
  /// No irregularities: every channel 0 everywhere.
  TrackIrregularity() = default;
  /// @param distances s of the samples [m], strictly increasing by at least
  ///        kMinIrregularitySpacing, kMinIrregularitySamples to kMaxIrregularitySamples, each
  ///        |s| <= kMaxIrregularityDistance.
  /// @param channels each channel's samples [m], as many as distances, |value| <= kMaxIrregularity.
  /// @throws IrregularitySampleError naming the sample, channel and value that break a rule;
  ///         std::invalid_argument for a count out of range or channels of another length.
  TrackIrregularity(std::vector<double> distances,
                    std::array<std::vector<double>, kIrregularityChannelCount> channels);

  /// True without samples (the nominal track).
  bool empty() const { return distances_.empty(); }
  /// The channels at s [m] (all 0 when empty()).
  IrregularityPoint at(double s) const;

  const std::vector<double>& distances() const { return distances_; }
  const std::vector<double>& samples(IrregularityChannel channel) const {
    return channels_[static_cast<std::size_t>(channel)];
  }
  /// Largest |sample| of a channel [m] (0 when empty()).
  double max_abs(IrregularityChannel channel) const;
  /// Root mean square of a channel's samples [m] (0 when empty()).
  double rms(IrregularityChannel channel) const;

 private:
  std::vector<double> distances_;
  std::array<std::vector<double>, kIrregularityChannelCount> channels_;
  std::vector<NaturalSpline> splines_;  // one per channel, when not empty
};

}  // namespace wrc
