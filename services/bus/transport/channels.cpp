// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/channels.hpp"

#include <cctype>
#include <stdexcept>

namespace wrc::bus {

ChannelNames::ChannelNames(std::string prefix) : prefix_(std::move(prefix)) {
  for (char c : prefix_) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') {
      throw std::invalid_argument("channel prefix '" + prefix_ +
                                  "' may only contain letters, digits, '_' and '-'");
    }
  }
}

std::string ChannelNames::name(const std::string& base) const {
  std::string full = prefix_.empty() ? base : prefix_ + "." + base;
  if (full.size() > kMaxChannelLength) {
    throw std::invalid_argument("channel name '" + full + "' is longer than 63 characters");
  }
  return full;
}

std::string ChannelNames::name(const std::string& base, const std::string& suffix) const {
  return name(base + "." + suffix);
}

std::string regex_escape(const std::string& channel) {
  static const std::string special = R"(\^$.|?*+()[]{})";
  std::string out;
  out.reserve(channel.size() + 4);
  for (char c : channel) {
    if (special.find(c) != std::string::npos) out += '\\';
    out += c;
  }
  return out;
}

}  // namespace wrc::bus
