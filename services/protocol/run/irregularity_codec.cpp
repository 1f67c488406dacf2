// SPDX-License-Identifier: Apache-2.0
#include "protocol/run/irregularity_codec.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace wrc::protocol {
namespace {

// The message's list of each channel, in the order of kIrregularityChannels.
std::array<std::vector<double>*, kIrregularityChannelCount> channel_lists(run_command_t& m) {
  return {&m.irregularity_alignment, &m.irregularity_vertical_level, &m.irregularity_cross_level,
          &m.irregularity_gauge};
}
std::array<const std::vector<double>*, kIrregularityChannelCount> channel_lists(const run_command_t& m) {
  return {&m.irregularity_alignment, &m.irregularity_vertical_level, &m.irregularity_cross_level,
          &m.irregularity_gauge};
}

}  // namespace

void to_irregularity_fields(const TrackIrregularity& irregularity, run_command_t& m) {
  m.num_irregularity_samples = static_cast<std::int32_t>(irregularity.distances().size());
  m.irregularity_s = irregularity.distances();
  const auto lists = channel_lists(m);
  for (IrregularityChannel c : kIrregularityChannels) *lists[static_cast<std::size_t>(c)] = irregularity.samples(c);
}

TrackIrregularity irregularity_from_fields(const run_command_t& m) {
  const std::string count = "num_irregularity_samples = " + std::to_string(m.num_irregularity_samples);
  if (m.num_irregularity_samples < 0) throw std::invalid_argument(count + " is negative");
  if (static_cast<std::size_t>(m.num_irregularity_samples) > kMaxIrregularitySamples)
    throw std::invalid_argument(count + " is more than the limit of " + std::to_string(kMaxIrregularitySamples));
  const std::size_t n = static_cast<std::size_t>(m.num_irregularity_samples);
  if (m.irregularity_s.size() != n)
    throw std::invalid_argument(count + " does not match the " + std::to_string(m.irregularity_s.size()) +
                                " values of irregularity_s");
  const auto lists = channel_lists(m);
  std::array<std::vector<double>, kIrregularityChannelCount> channels;
  for (IrregularityChannel c : kIrregularityChannels) {
    const std::vector<double>& list = *lists[static_cast<std::size_t>(c)];
    if (list.size() != n)
      throw std::invalid_argument(count + " does not match the " + std::to_string(list.size()) +
                                  " values of irregularity_" + irregularity_channel_name(c));
    channels[static_cast<std::size_t>(c)] = list;
  }
  if (n == 0) return TrackIrregularity();
  return TrackIrregularity(m.irregularity_s, std::move(channels));
}

}  // namespace wrc::protocol
