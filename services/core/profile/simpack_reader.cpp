// SPDX-License-Identifier: Apache-2.0
#include "core/profile/simpack_reader.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <regex>

#include "core/numerics/number_text.hpp"
#include "core/profile/profile_error.hpp"
#include "core/profile/profile_plausibility.hpp"
#include "core/profile/profile_points.hpp"
#include "core/profile/profile_text.hpp"
#include "core/profile/spline_profile.hpp"

namespace wrc {
namespace {

using profile_text::lower;
using profile_text::parse_number;
using profile_text::split_fields;
using profile_text::trim;

const double kStandardCant = std::atan(1.0 / 40.0);  // [rad]

// The line without its '!' comment; '!' inside single quotes does not start a comment.
std::string strip_comment(const std::string& line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\'') quoted = !quoted;
    if (line[i] == '!' && !quoted) return line.substr(0, i);
  }
  return line;
}

struct KeyValue {
  std::string value;
  int line = 0;
};

double numeric_key(const std::string& path, const std::map<std::string, KeyValue>& keys,
                   const std::string& key, double fallback) {
  const auto it = keys.find(key);
  if (it == keys.end()) return fallback;
  double value = 0;
  if (!parse_number(it->second.value, value) || !std::isfinite(value)) {
    throw ProfileError(path, it->second.line,
                       "non-numeric value '" + it->second.value + "' for " + key);
  }
  return value;
}

std::string unquote(const std::string& text) {
  if (text.size() >= 2 && text.front() == '\'' && text.back() == '\'') {
    return text.substr(1, text.size() - 2);
  }
  return text;
}

double length_factor(const std::string& path, const std::map<std::string, KeyValue>& keys) {
  const auto f = keys.find("units.len.f");
  if (f != keys.end()) {
    const double factor = numeric_key(path, keys, "units.len.f", 0.0);
    if (!(factor > 0.0)) {
      throw ProfileError(path, f->second.line,
                         "unknown units: units.len.f = " + f->second.value + " (must be > 0)");
    }
    return factor;
  }
  const auto name = keys.find("units.len");
  if (name == keys.end()) return 1000.0;
  const std::string unit = lower(unquote(name->second.value));
  if (unit == "mm") return 1000.0;
  if (unit == "cm") return 100.0;
  if (unit == "m") return 1.0;
  throw ProfileError(path, name->second.line,
                     "unknown units '" + unquote(name->second.value) + "' (use mm, cm or m)");
}

void require_neutral(const std::string& path, const std::map<std::string, KeyValue>& keys) {
  for (const char* key : {"shift.y", "shift.z", "rotate"}) {
    if (numeric_key(path, keys, key, 0.0) != 0.0) {
      throw ProfileError(path, keys.at(key).line,
                         std::string("unsupported processing option: ") + key + " is not 0");
    }
  }
  for (const char* axis : {"y", "z"}) {
    const std::string lo = std::string("bound.") + axis + ".min";
    const std::string hi = std::string("bound.") + axis + ".max";
    if (keys.count(lo) && keys.count(hi) &&
        numeric_key(path, keys, lo, 0.0) <= numeric_key(path, keys, hi, 0.0)) {
      throw ProfileError(path, keys.at(lo).line,
                         "unsupported processing option: active bound." + std::string(axis));
    }
  }
}

double cant_from_comment(const std::string& comment) {
  const std::string text = lower(comment);
  if (text.find("canted") == std::string::npos) return 0.0;
  std::smatch match;
  static const std::regex ratio("1\\s*:\\s*([0-9]+(\\.[0-9]*)?)");
  if (std::regex_search(text, match, ratio)) {
    return std::atan(1.0 / parse_finite_number(match[1].str(), "cant ratio"));
  }
  return kStandardCant;
}

}  // namespace

ProfilePtr read_simpack_profile(const std::string& path, ProfileSide side,
                                const ProfileFileOptions& options) {
  const std::vector<std::string> lines = profile_text::read_lines(path);
  std::map<std::string, KeyValue> keys;
  ProfilePoints raw;
  raw.source = path;
  bool in_points = false;
  bool saw_begin = false;
  bool saw_end = false;
  bool in_header = false;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const int line_no = static_cast<int>(k + 1);
    const std::string text = trim(strip_comment(lines[k]));
    if (text.empty()) continue;
    if (text == "header.begin" || text == "header.end") {
      in_header = text == "header.begin";
      continue;
    }
    if (text == "point.begin") {
      in_points = saw_begin = true;
      continue;
    }
    if (text == "point.end") {
      if (!in_points) throw ProfileError(path, line_no, "point.end without point.begin");
      in_points = false;
      saw_end = true;
      continue;
    }
    if (in_points) {
      const std::vector<std::string> fields = split_fields(text);
      if (fields.size() < 2) throw ProfileError(path, line_no, "missing z value");
      if (fields.size() > 3) throw ProfileError(path, line_no, "more than 3 values in a point");
      double y = 0, z = 0, w = 0;
      if (!parse_number(fields[0], y)) {
        throw ProfileError(path, line_no, "non-numeric value '" + fields[0] + "'");
      }
      if (!parse_number(fields[1], z)) {
        throw ProfileError(path, line_no, "non-numeric value '" + fields[1] + "'");
      }
      if (fields.size() == 3 && !parse_number(fields[2], w)) {
        throw ProfileError(path, line_no, "non-numeric value '" + fields[2] + "'");
      }
      raw.lateral.push_back(y);
      raw.height.push_back(z);
      raw.line.push_back(line_no);
      continue;
    }
    const auto eq = text.find('=');
    if (eq != std::string::npos) {
      // Header keys get a "header." prefix: "type" also appears in the spline section.
      const std::string key = (in_header ? "header." : "") + trim(text.substr(0, eq));
      keys[key] = KeyValue{trim(text.substr(eq + 1)), line_no};
    }
  }
  if (!saw_begin) throw ProfileError(path, 0, "no point.begin section");
  if (!saw_end) throw ProfileError(path, static_cast<int>(lines.size()), "missing point.end");

  const auto type = keys.find("header.type");
  if (type == keys.end()) throw ProfileError(path, 0, "missing header type (0 rail, 1 wheel)");
  double type_value = -1;
  if (!parse_number(type->second.value, type_value) || (type_value != 0 && type_value != 1)) {
    throw ProfileError(path, type->second.line,
                       "header type must be 0 (rail) or 1 (wheel), not '" + type->second.value + "'");
  }
  const ProfileSide file_side = type_value == 1 ? ProfileSide::kWheel : ProfileSide::kRail;
  if (file_side != side) {
    throw ProfileError(path, type->second.line,
                       file_side == ProfileSide::kWheel
                           ? "SIMPACK type 1 (wheel profile) given as a rail profile"
                           : "SIMPACK type 0 (rail profile) given as a wheel profile");
  }
  const double factor = length_factor(path, keys);
  require_neutral(path, keys);
  const double sign_y = numeric_key(path, keys, "mirror.y", 0.0) == 1.0 ? -1.0 : 1.0;
  const double sign_z = numeric_key(path, keys, "mirror.z", 0.0) == 1.0 ? -1.0 : 1.0;
  // Wheel: F = z (z down); rail: v = -z.
  const double height_sign = side == ProfileSide::kWheel ? sign_z : -sign_z;
  for (std::size_t i = 0; i < raw.lateral.size(); ++i) {
    raw.lateral[i] = sign_y * raw.lateral[i] / factor;
    raw.height[i] = height_sign * raw.height[i] / factor;
  }
  const ProfilePoints points = validate_profile_points(std::move(raw));
  check_profile_plausibility(points, side);

  double cant = 0.0;
  if (side == ProfileSide::kRail) {
    const auto comment = keys.find("comment");
    cant = options.built_in_cant
               ? *options.built_in_cant
               : (comment == keys.end() ? 0.0 : cant_from_comment(comment->second.value));
  }
  return std::make_shared<SplineProfile>(points, side, "file " + profile_text::base_name(path),
                                         cant);
}

}  // namespace wrc
