// SPDX-License-Identifier: Apache-2.0
#include "core/profile/miniprof_reader.hpp"

#include <memory>

#include "core/profile/profile_error.hpp"
#include "core/profile/profile_plausibility.hpp"
#include "core/profile/profile_points.hpp"
#include "core/profile/profile_text.hpp"
#include "core/profile/spline_profile.hpp"

namespace wrc {

ProfilePtr read_miniprof_profile(const std::string& path, ProfileSide side,
                                 const ProfileFileOptions& options) {
  using profile_text::parse_number;
  using profile_text::trim;
  if (side != ProfileSide::kRail) {
    throw ProfileError(path, 0, "MiniProf .ban files are rail profiles, asked for as a wheel");
  }
  const std::vector<std::string> lines = profile_text::read_lines(path);
  ProfilePoints points;
  points.source = path;
  bool in_data = false;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const int line_no = static_cast<int>(k + 1);
    std::string text = trim(lines[k]);
    if (text.empty()) continue;
    const auto eq = text.find('=');
    if (!in_data && eq != std::string::npos) {
      const std::string key = trim(text.substr(0, eq));
      std::string value;
      for (char c : text.substr(eq + 1)) {
        if (c != ' ' && c != '\t' && c != '\r') value += c;
      }
      if (profile_text::lower(key) == "columndef" && profile_text::lower(value) != "x,y") {
        throw ProfileError(path, line_no, "unsupported ColumnDef '" + value + "' (need X,Y)");
      }
      continue;
    }
    in_data = true;
    if (text.front() == '"') text = trim(text.substr(1));
    const std::vector<std::string> fields = profile_text::split_fields(text);
    if (fields.size() < 2) throw ProfileError(path, line_no, "missing Y value");
    if (fields.size() > 2) throw ProfileError(path, line_no, "more than 2 values in a point");
    double x = 0, y = 0;
    if (!parse_number(fields[0], x)) {
      throw ProfileError(path, line_no, "non-numeric value '" + fields[0] + "'");
    }
    if (!parse_number(fields[1], y)) {
      throw ProfileError(path, line_no, "non-numeric value '" + fields[1] + "'");
    }
    points.lateral.push_back(-x * 1e-3);
    points.height.push_back(-y * 1e-3);
    points.line.push_back(line_no);
  }
  const ProfilePoints checked = validate_profile_points(std::move(points));
  check_profile_plausibility(checked, side);
  return std::make_shared<SplineProfile>(checked, side,
                                         "file " + profile_text::base_name(path),
                                         options.built_in_cant.value_or(0.0));
}

}  // namespace wrc
