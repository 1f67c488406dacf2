// SPDX-License-Identifier: Apache-2.0
#include "core/track/track_layout_file.hpp"

#include <algorithm>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/numerics/number_text.hpp"
#include "core/numerics/regular_file.hpp"

namespace wrc {
namespace {

using nlohmann::json;

constexpr std::size_t kMaxFileBytes = 1u << 20;  // [B] a layout of thousands of segments fits

// The JSON of text with every object's keys checked to be unique.
json parse_unique_keys(const std::string& text, const std::string& source) {
  std::vector<std::set<std::string>> keys;  // per open object
  const json::parser_callback_t check = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    if (event == json::parse_event_t::object_end) keys.pop_back();
    if (event == json::parse_event_t::key && !keys.back().insert(parsed.get<std::string>()).second)
      throw std::invalid_argument(source + ": " + parsed.get<std::string>() + ": duplicate key (each key may appear once)");
    return true;
  };
  try {
    return json::parse(text, check, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::exception& e) {
    throw std::invalid_argument(source + ": not valid JSON: " + e.what());
  }
}

double number(const json& object, const char* key, const std::string& where, bool required = true,
              double fallback = 0.0) {
  if (!object.contains(key)) {
    if (required) throw std::invalid_argument(where + ": " + key + ": missing");
    return fallback;
  }
  const json& v = object.at(key);
  if (!v.is_number()) throw std::invalid_argument(where + ": " + key + ": must be a number [m]");
  return v.get<double>();
}

}  // namespace

TrackLayout parse_track_layout(const std::string& json_text, const std::string& source) {
  const json root = parse_unique_keys(json_text, source);
  if (!root.is_object()) throw std::invalid_argument(source + ": the track layout must be one JSON object");
  for (const auto& [key, value] : root.items()) {
    (void)value;
    if (key != "cant_base" && key != "segments")
      throw std::invalid_argument(source + ": " + key + ": unknown key (known: cant_base, segments)");
  }
  if (!root.contains("segments") || !root.at("segments").is_array() || root.at("segments").empty())
    throw std::invalid_argument(source + ": segments: must be a non-empty list of segments");
  std::vector<TrackSegment> segments;
  for (std::size_t k = 0; k < root.at("segments").size(); ++k) {
    const json& item = root.at("segments")[k];
    const std::string where = source + ": segments[" + std::to_string(k) + "]";
    if (!item.is_object()) throw std::invalid_argument(where + ": must be an object");
    if (!item.contains("type") || !item.at("type").is_string())
      throw std::invalid_argument(where + ": type: missing (straight, transition or curve)");
    const std::string type = item.at("type").get<std::string>();
    TrackSegment s;
    const auto* kind = std::find_if(std::begin(kTrackSegmentKinds), std::end(kTrackSegmentKinds),
                                    [&](TrackSegmentKind candidate) { return type == track_segment_kind_name(candidate); });
    if (kind == std::end(kTrackSegmentKinds))
      throw std::invalid_argument(where + ": type: '" + type + "' is not straight, transition or curve");
    s.kind = *kind;
    std::set<std::string> known{"type", "length"};
    if (s.kind == TrackSegmentKind::kCurve) {
      known.insert({"radius", "direction", "cant"});
      s.radius = number(item, "radius", where);
      s.cant = number(item, "cant", where, false, 0.0);
      if (!item.contains("direction") || !item.at("direction").is_string() ||
          (item.at("direction") != "left" && item.at("direction") != "right"))
        throw std::invalid_argument(where + ": direction: must be \"left\" or \"right\"");
      s.left = item.at("direction") == "left";
    }
    for (const auto& [key, value] : item.items()) {
      (void)value;
      if (known.count(key)) continue;
      // A key of a curve on a straight or a transition (whose curvature and cant come from its
      // neighbours) is named as such.
      const bool curve_key = key == "radius" || key == "direction" || key == "cant";
      throw std::invalid_argument(where + ": " + key + ": " + (curve_key ? "a key of a curve, " : "") + "not a key of a " +
                                  type);
    }
    s.length = number(item, "length", where);
    segments.push_back(s);
  }
  try {
    return TrackLayout(std::move(segments), number(root, "cant_base", source, false, 1.5));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
}

TrackLayout read_track_layout_file(const std::string& path) {
  return parse_track_layout(read_regular_file(path, kMaxFileBytes), path);
}

std::string track_layout_text(const TrackLayout& layout) {
  std::ostringstream out;
  out << "{\"cant_base\": " << exact_number_text(layout.cant_base()) << ", \"segments\": [";
  for (std::size_t k = 0; k < layout.segments().size(); ++k) {
    const TrackSegment& s = layout.segments()[k];
    out << (k ? ", " : "") << "{\"type\": \""
        << track_segment_kind_name(s.kind)
        << "\", \"length\": " << exact_number_text(s.length);
    if (s.kind == TrackSegmentKind::kCurve)
      out << ", \"radius\": " << exact_number_text(s.radius) << ", \"direction\": \"" << (s.left ? "left" : "right")
          << "\", \"cant\": " << exact_number_text(s.cant);
    out << "}";
  }
  out << "]}";
  return out.str();
}

}  // namespace wrc
