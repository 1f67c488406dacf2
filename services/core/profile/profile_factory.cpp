// SPDX-License-Identifier: Apache-2.0
#include "core/profile/profile_factory.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>

#include "core/numerics/number_text.hpp"

#include "core/profile/builtin_profiles.hpp"
#include "core/profile/circle_rail.hpp"
#include "core/profile/conic.hpp"
#include "core/profile/profile_error.hpp"
#include "core/profile/profile_file.hpp"

namespace wrc {
namespace {

const char* side_name(ProfileSide side) { return side == ProfileSide::kWheel ? "wheel" : "rail"; }

void require_side(const std::string& spec, ProfileSide wanted, ProfileSide actual) {
  if (wanted != actual) {
    throw ProfileError(spec, 0,
                       std::string("is a ") + side_name(actual) + " profile, asked for as a " +
                           side_name(wanted) + " profile");
  }
}

// Parses the number after "<prefix>:"; the whole rest must be one finite number.
double parse_parameter(const std::string& spec, std::size_t prefix_length) {
  const std::string text = spec.substr(prefix_length);
  const std::optional<double> value = finite_number(text);
  if (!value) throw ProfileError(spec, 0, "'" + text + "' is not a finite number");
  return *value;
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

ProfilePtr make_profile(const std::string& spec, ProfileSide side,
                        const ProfileFileOptions& options) {
  if (const BuiltinProfile* builtin = find_builtin_profile(spec)) {
    require_side(spec, side, builtin->side);
    return builtin->make();
  }
  if (starts_with(spec, kConicPrefix)) {
    require_side(spec, side, ProfileSide::kWheel);
    return std::make_shared<ConicProfile>(parse_parameter(spec, std::strlen(kConicPrefix)));
  }
  if (starts_with(spec, kCirclePrefix)) {
    require_side(spec, side, ProfileSide::kRail);
    const double radius = parse_parameter(spec, std::strlen(kCirclePrefix));
    if (radius <= 0.0) {
      throw ProfileError(spec, 0, "the circle radius must be positive [m]");
    }
    return std::make_shared<CircleRailProfile>(radius);
  }
  if (spec.empty()) {
    throw ProfileError("(empty profile specification)", 0, "no profile name or file given");
  }
  return read_profile_file(spec, side, options);
}

}  // namespace wrc
