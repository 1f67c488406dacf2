// SPDX-License-Identifier: Apache-2.0
#include "core/identity/geometry_key.hpp"

#include <optional>

#include "core/geometry/track_table.hpp"
#include "core/identity/sha256.hpp"
#include "core/numerics/number_text.hpp"
#include "core/profile/builtin_profiles.hpp"
#include "core/profile/profile_file_bytes.hpp"

namespace wrc {
namespace {

std::string exact(double value) { return exact_number_text(value); }

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// "<prefix><number>" with the number as %.17g; a malformed number is kept as written
// (make_profile rejects the spec anyway).
std::string canonical_parameter(const std::string& spec, const std::string& prefix) {
  const std::string text = spec.substr(prefix.size());
  const std::optional<double> value = finite_number(text);
  return value ? prefix + exact(*value) : spec;
}

// One profile as its content: the canonical name of a built-in (the names make_profile knows),
// or the bytes of a file.
std::string profile_content(const char* field, const std::string& spec) {
  const std::string head = std::string(field) + " ";
  if (find_builtin_profile(spec)) return head + "builtin " + spec + "\n";
  for (const char* prefix : {kConicPrefix, kCirclePrefix})
    if (starts_with(spec, prefix)) return head + "builtin " + canonical_parameter(spec, prefix) + "\n";
  const std::string bytes = read_profile_file_bytes(spec);
  return head + "file " + std::to_string(bytes.size()) + "\n" + bytes + "\n";
}

}  // namespace

std::string geometry_key_text(const GeometrySpec& spec) {
  std::string text = std::string(kGeometryKeyVersion) + "\n";
  text += profile_content("wheel", spec.wheel);
  text += profile_content("rail", spec.rail);
  text += "rail_cant " + (spec.rail_cant ? exact(*spec.rail_cant) : std::string("profile")) + "\n";
  for (const auto& p : track_parameter_table()) text += std::string(p.key) + " " + exact(p.get(spec.track)) + "\n";
  return text;
}

std::string geometry_key(const GeometrySpec& spec) { return sha256_hex(geometry_key_text(spec)); }

std::string profile_content_hash(const std::string& profile_spec) {
  return sha256_hex(profile_content("profile", profile_spec));
}

std::vector<std::string> geometry_arguments(const GeometrySpec& spec) {
  std::vector<std::string> args{"--wheel", spec.wheel, "--rail", spec.rail};
  if (spec.rail_cant) args.insert(args.end(), {"--rail-cant", exact(*spec.rail_cant)});
  for (const auto& p : track_parameter_table()) args.insert(args.end(), {p.option_name(), exact(p.get(spec.track))});
  return args;
}

}  // namespace wrc
