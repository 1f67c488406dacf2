// SPDX-License-Identifier: Apache-2.0
#include "core/track/track_irregularity.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/numerics/number_text.hpp"

namespace wrc {

const char* irregularity_channel_name(IrregularityChannel channel) {
  switch (channel) {
    case IrregularityChannel::kAlignment: return "alignment";
    case IrregularityChannel::kVerticalLevel: return "vertical_level";
    case IrregularityChannel::kCrossLevel: return "cross_level";
    case IrregularityChannel::kGauge: return "gauge";
  }
  return "?";
}

double IrregularityPoint::value(IrregularityChannel channel) const {
  switch (channel) {
    case IrregularityChannel::kAlignment: return alignment;
    case IrregularityChannel::kVerticalLevel: return vertical_level;
    case IrregularityChannel::kCrossLevel: return cross_level;
    case IrregularityChannel::kGauge: return gauge;
  }
  return 0.0;
}

TrackIrregularity::TrackIrregularity(std::vector<double> distances,
                                     std::array<std::vector<double>, kIrregularityChannelCount> channels)
    : distances_(std::move(distances)), channels_(std::move(channels)) {
  const std::size_t n = distances_.size();
  if (n < kMinIrregularitySamples || n > kMaxIrregularitySamples)
    throw std::invalid_argument("irregularities: " + std::to_string(n) + " samples, must be " +
                                std::to_string(kMinIrregularitySamples) + " to " +
                                std::to_string(kMaxIrregularitySamples));
  for (std::size_t i = 0; i < n; ++i) {
    const double s = distances_[i];
    if (!std::isfinite(s))
      throw IrregularitySampleError(i, "irregularities: sample " + std::to_string(i) + ": s = " + number_text(s) +
                                  " m is not a finite number");
    if (!(std::fabs(s) <= kMaxIrregularityDistance))
      throw IrregularitySampleError(i, "irregularities: sample " + std::to_string(i) + ": s = " + number_text(s) +
                                           " m is outside [-" + number_text(kMaxIrregularityDistance) + ", " +
                                           number_text(kMaxIrregularityDistance) + "] m");
    if (i > 0 && !(s - distances_[i - 1] >= kMinIrregularitySpacing))
      throw IrregularitySampleError(i, "irregularities: sample " + std::to_string(i) + ": s = " + number_text(s) +
                                  " m does not follow s = " + number_text(distances_[i - 1]) + " m by at least " +
                                  number_text(kMinIrregularitySpacing) + " m");
  }
  for (IrregularityChannel channel : kIrregularityChannels) {
    const std::vector<double>& v = channels_[static_cast<std::size_t>(channel)];
    const std::string name = irregularity_channel_name(channel);
    if (v.size() != n)
      throw std::invalid_argument("irregularities: " + name + " has " + std::to_string(v.size()) + " samples for " +
                                  std::to_string(n) + " distances");
    for (std::size_t i = 0; i < n; ++i)
      if (!(std::fabs(v[i]) <= kMaxIrregularity))
        throw IrregularitySampleError(i, "irregularities: sample " + std::to_string(i) + " (s = " +
                                    number_text(distances_[i]) + " m): " + name + " = " + number_text(v[i]) +
                                    " m is outside [-" + number_text(kMaxIrregularity) + ", " +
                                    number_text(kMaxIrregularity) + "] m");
    splines_.emplace_back(kIrregularitySplineDegree, distances_, v);
  }
}

IrregularityPoint TrackIrregularity::at(double s) const {
  IrregularityPoint p;
  if (empty()) return p;
  // Outside the samples: the end values, no slope (a kink of the rails there, no jump).
  const bool inside = s >= distances_.front() && s <= distances_.back();
  const double at_s = inside ? s : (s < distances_.front() ? distances_.front() : distances_.back());
  std::array<double, kIrregularityChannelCount> value{};
  for (std::size_t k = 0; k < splines_.size(); ++k) {
    const SplineSample sample = splines_[k].evaluate(at_s);
    value[k] = sample.value;
    p.slope[k] = inside ? sample.slope : 0.0;
  }
  p.alignment = value[0];
  p.vertical_level = value[1];
  p.cross_level = value[2];
  p.gauge = value[3];
  return p;
}

double TrackIrregularity::max_abs(IrregularityChannel channel) const {
  double m = 0.0;
  for (double v : samples(channel)) m = std::fmax(m, std::fabs(v));
  return m;
}

double TrackIrregularity::rms(IrregularityChannel channel) const {
  const std::vector<double>& v = samples(channel);
  if (v.empty()) return 0.0;
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return std::sqrt(sum / static_cast<double>(v.size()));
}

}  // namespace wrc
