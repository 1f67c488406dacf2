#include "core/identity/geometry_key.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "core/identity/sha256.hpp"
#include "core/profile/builtin_profiles.hpp"
#include "core/profile/profile_error.hpp"

namespace wrc {
namespace {

std::string exact(double value) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// "<prefix><number>" with the number as %.17g; a malformed number is kept as written
// (make_profile rejects the spec anyway).
std::string canonical_parameter(const std::string& spec, const std::string& prefix) {
  const std::string text = spec.substr(prefix.size());
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) return spec;
  return prefix + exact(value);
}

// One profile as its content: the canonical name of a built-in (the names make_profile knows),
// or the bytes of a file.
std::string profile_content(const char* field, const std::string& spec) {
  const std::string head = std::string(field) + " ";
  if (find_builtin_profile(spec)) return head + "builtin " + spec + "\n";
  for (const char* prefix : {kConicPrefix, kCirclePrefix})
    if (starts_with(spec, prefix)) return head + "builtin " + canonical_parameter(spec, prefix) + "\n";
  std::ifstream in(spec, std::ios::binary);
  if (!in) throw ProfileError(spec, 0, "cannot be read (for the geometry key)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw ProfileError(spec, 0, "reading failed (for the geometry key)");
  return head + "file " + std::to_string(bytes.size()) + "\n" + bytes + "\n";
}

}  // namespace

std::string geometry_key_text(const GeometrySpec& spec) {
  const TrackParameters& t = spec.track;
  std::string text = std::string(kGeometryKeyVersion) + "\n";
  text += profile_content("wheel", spec.wheel);
  text += profile_content("rail", spec.rail);
  text += "rail_cant " + (spec.rail_cant ? exact(*spec.rail_cant) : std::string("profile")) + "\n";
  text += "gauge " + exact(t.gauge) + "\n";
  text += "gauge_depth " + exact(t.gauge_depth) + "\n";
  text += "flange_back_spacing " + exact(t.flange_back_spacing) + "\n";
  text += "taping_line_offset " + exact(t.taping_line_offset) + "\n";
  text += "inclination " + exact(t.inclination) + "\n";
  text += "nominal_radius " + exact(t.nominal_radius) + "\n";
  return text;
}

std::string geometry_key(const GeometrySpec& spec) { return sha256_hex(geometry_key_text(spec)); }

std::string profile_content_hash(const std::string& profile_spec) {
  return sha256_hex(profile_content("profile", profile_spec));
}

std::vector<std::string> geometry_arguments(const GeometrySpec& spec) {
  std::vector<std::string> args{"--wheel", spec.wheel, "--rail", spec.rail};
  if (spec.rail_cant) args.insert(args.end(), {"--rail-cant", exact(*spec.rail_cant)});
  const TrackParameters& t = spec.track;
  args.insert(args.end(), {"--gauge", exact(t.gauge), "--gauge-depth", exact(t.gauge_depth), "--flange-back",
                           exact(t.flange_back_spacing), "--taping-line-offset", exact(t.taping_line_offset),
                           "--inclination", exact(t.inclination), "--r0", exact(t.nominal_radius)});
  return args;
}

}  // namespace wrc
