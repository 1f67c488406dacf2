#pragma once
/// @file
/// The geometry a contact service computes with (wheel and rail profile, track), its
/// command-line form and a key that identifies it on the bus. wrc-contactd publishes the key as
/// `table_hash` in its heartbeats and replies and rejects a query whose non-empty `table_hash`
/// differs; `wrc query` computes the key of the geometry it asks for and so only uses (or starts)
/// a service that computes with that geometry. Header-only: the `wrc` front end uses it too.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/geometry/track.hpp"

namespace wrc::contactd {

/// Profiles and track of one service (the defaults of architecture.md section 3).
struct GeometrySpec {
  std::string wheel = "S1002";  ///< profile spec of core/profile/profile_factory.hpp
  std::string rail = "UIC60";   ///< profile spec of core/profile/profile_factory.hpp
  TrackParameters track;        ///< gauge, flange-back spacing, inclination, r0 [SI]
};

namespace detail {
inline std::string exact(double value) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}
/// A built-in profile name stands for itself; a file for its bytes (so that two paths of the
/// same file give the same key and an edited file a new one).
inline std::string profile_identity(const std::string& spec) {
  std::error_code ec;
  if (spec.find(':') == std::string::npos && std::filesystem::is_regular_file(spec, ec)) {
    std::ifstream in(spec, std::ios::binary);
    return "file:" + std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return "name:" + spec;
}
}  // namespace detail

/// Command-line arguments that make wrc-contactd build exactly this geometry (numbers with 17
/// significant digits, the inclination in radians).
inline std::vector<std::string> geometry_arguments(const GeometrySpec& spec) {
  using detail::exact;
  return {"--wheel",       spec.wheel,
          "--rail",        spec.rail,
          "--gauge",       exact(spec.track.gauge),
          "--gauge-depth", exact(spec.track.gauge_depth),
          "--flange-back", exact(spec.track.flange_back_spacing),
          "--inclination", exact(spec.track.inclination),
          "--r0",          exact(spec.track.nominal_radius)};
}

/// 16 hex digits (FNV-1a, 64 bit) of the canonical text of spec: equal keys, same geometry.
inline std::string geometry_key(const GeometrySpec& spec) {
  using detail::exact;
  const std::string text = detail::profile_identity(spec.wheel) + "|" + detail::profile_identity(spec.rail) +
                           "|" + exact(spec.track.gauge) + "|" + exact(spec.track.gauge_depth) + "|" +
                           exact(spec.track.flange_back_spacing) + "|" +
                           exact(spec.track.taping_line_offset) + "|" + exact(spec.track.inclination) +
                           "|" + exact(spec.track.nominal_radius);
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace wrc::contactd
