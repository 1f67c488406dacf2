// SPDX-License-Identifier: Apache-2.0
#include "core/profile/text_profile_reader.hpp"

#include <cctype>
#include <cmath>
#include <memory>

#include "core/profile/profile_error.hpp"
#include "core/profile/profile_plausibility.hpp"
#include "core/profile/profile_points.hpp"
#include "core/profile/profile_text.hpp"
#include "core/profile/spline_profile.hpp"

namespace wrc {
namespace {

bool has_letter(const std::string& text) {
  for (char c : text) {
    if (std::isalpha(static_cast<unsigned char>(c))) return true;
  }
  return false;
}

}  // namespace

ProfilePtr read_text_profile(const std::string& path, ProfileSide side,
                             const ProfileFileOptions& options) {
  using profile_text::lower;
  using profile_text::parse_number;
  using profile_text::trim;
  const std::vector<std::string> lines = profile_text::read_lines(path);
  ProfilePoints points;
  points.source = path;
  double scale = 1e-3;  // mm by default
  double cant = 0.0;
  bool first_data_line = true;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const int line_no = static_cast<int>(k + 1);
    const std::string text = trim(lines[k]);
    if (text.empty()) continue;
    if (text.front() == '#') {
      const std::string body = trim(text.substr(1));
      const auto colon = body.find(':');
      if (colon == std::string::npos) continue;
      const std::string key = lower(trim(body.substr(0, colon)));
      const std::string value = trim(body.substr(colon + 1));
      if (key == "units") {
        const std::string unit = lower(value);
        if (unit == "mm") {
          scale = 1e-3;
        } else if (unit == "m") {
          scale = 1.0;
        } else {
          throw ProfileError(path, line_no, "unknown units '" + value + "' (use mm or m)");
        }
      } else if (key == "side") {
        const std::string s = lower(value);
        if (s != "wheel" && s != "rail") {
          throw ProfileError(path, line_no, "unknown side '" + value + "' (use wheel or rail)");
        }
        const ProfileSide file_side = s == "wheel" ? ProfileSide::kWheel : ProfileSide::kRail;
        if (file_side != side) {
          throw ProfileError(path, line_no,
                             "a " + s + " profile given as a " +
                                 (side == ProfileSide::kWheel ? "wheel" : "rail") + " profile");
        }
      } else if (key == "cant") {
        if (!parse_number(value, cant) || !std::isfinite(cant)) {
          throw ProfileError(path, line_no, "non-numeric cant '" + value + "' [rad]");
        }
      }
      continue;
    }
    const std::vector<std::string> fields = profile_text::split_fields(text);
    double a = 0, b = 0;
    const bool numeric0 = !fields.empty() && parse_number(fields[0], a);
    if (first_data_line && !numeric0 && has_letter(text)) {
      first_data_line = false;  // column-name header
      continue;
    }
    first_data_line = false;
    if (fields.size() < 2) throw ProfileError(path, line_no, "missing value (need 2 columns)");
    if (fields.size() > 2) throw ProfileError(path, line_no, "more than 2 columns");
    if (!numeric0) throw ProfileError(path, line_no, "non-numeric value '" + fields[0] + "'");
    if (!parse_number(fields[1], b)) {
      throw ProfileError(path, line_no, "non-numeric value '" + fields[1] + "'");
    }
    points.lateral.push_back(a * scale);
    points.height.push_back(b * scale);
    points.line.push_back(line_no);
  }
  if (side == ProfileSide::kWheel) cant = 0.0;
  const ProfilePoints checked = validate_profile_points(std::move(points));
  check_profile_plausibility(checked, side);
  return std::make_shared<SplineProfile>(checked, side,
                                         "file " + profile_text::base_name(path),
                                         options.built_in_cant.value_or(cant));
}

}  // namespace wrc
