// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle/vehicle_file.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

#include "core/numerics/regular_file.hpp"

namespace wrc {
namespace {

using nlohmann::json;

constexpr std::size_t kMaxFileBytes = 1u << 20;

// One object of the file (the vehicle, a body, an element): its keys taken one by one, each
// checked for its type, the rest refused by name at the end.
class Entry {
 public:
  Entry(const json& object, std::string where) : object_(object), where_(std::move(where)) {
    if (!object_.is_object()) fail("", "must be a JSON object");
  }
  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    throw std::invalid_argument(where_ + (key.empty() ? "" : key + ": ") + why);
  }
  bool has(const std::string& key) const { return object_.contains(key); }
  const json& at(const std::string& key) {
    if (!object_.contains(key)) fail(key, "missing");
    used_.insert(key);
    return object_.at(key);
  }
  std::string text(const std::string& key) {
    const json& v = at(key);
    if (!v.is_string()) fail(key, "must be a string, not " + v.dump().substr(0, 40));
    return v.get<std::string>();
  }
  double number(const std::string& key) { return as_number(at(key), key); }
  double number_or(const std::string& key, double fallback) { return has(key) ? number(key) : fallback; }
  std::array<double, 3> vector3(const std::string& key) { return as_vector3(at(key), key); }
  std::array<double, 3> vector3_or(const std::string& key) {
    return has(key) ? vector3(key) : std::array<double, 3>{0, 0, 0};
  }
  double as_number(const json& v, const std::string& key) const {
    if (!v.is_number()) fail(key, "must be a number, not " + v.dump().substr(0, 40));
    return v.get<double>();
  }
  std::array<double, 3> as_vector3(const json& v, const std::string& key) const {
    if (!v.is_array() || v.size() != 3) fail(key, "must be an array of three numbers [x, y, z]");
    return {as_number(v[0], key), as_number(v[1], key), as_number(v[2], key)};
  }
  /// Refuses every key not taken, naming the keys allowed.
  void check_all_used(const std::vector<std::string>& allowed) const {
    for (auto it = object_.begin(); it != object_.end(); ++it) {
      if (used_.count(it.key())) continue;
      std::string list;
      for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
      fail(it.key(), "unknown key (keys here: " + list + ")");
    }
  }

 private:
  const json& object_;
  std::string where_;
  std::set<std::string> used_;
};

std::string name_of(const json& object, const char* what, std::size_t index) {
  if (object.is_object() && object.contains("name") && object["name"].is_string()) return object["name"];
  throw std::invalid_argument(std::string(what) + " " + std::to_string(index + 1) + ": name: missing or not a string");
}

BodyKind body_kind(Entry& e) {
  const std::string kind = e.text("kind");
  for (BodyKind k : {BodyKind::kCarBody, BodyKind::kBogieFrame, BodyKind::kWheelset})
    if (kind == body_kind_name(k)) return k;
  e.fail("kind", "'" + kind + "' is none of car_body, bogie_frame, wheelset");
}

ElementKind element_kind(Entry& e) {
  const std::string kind = e.text("kind");
  for (ElementKind k : {ElementKind::kSpringDamper, ElementKind::kTorsionalSpring, ElementKind::kBumpStop,
                        ElementKind::kNonlinearDamper})
    if (kind == element_kind_name(k)) return k;
  e.fail("kind", "'" + kind + "' is none of spring_damper, torsional_spring, bump_stop, nonlinear_damper");
}

VehicleBody read_body(const json& object, std::size_t index) {
  VehicleBody b;
  b.name = name_of(object, "body", index);
  Entry e(object, "body '" + b.name + "': ");
  e.text("name");
  b.kind = body_kind(e);
  b.mass = e.number("mass");
  b.inertia = e.vector3("inertia");
  b.products_of_inertia = e.vector3_or("products_of_inertia");
  b.position = e.vector3("position");
  b.external_force = e.vector3_or("external_force");
  e.check_all_used({"name", "kind", "mass", "inertia", "products_of_inertia", "position", "external_force"});
  return b;
}

int direction(Entry& e) {
  const std::string d = e.text("direction");
  if (d == "x") return 0;
  if (d == "y") return 1;
  if (d == "z") return 2;
  e.fail("direction", "'" + d + "' is none of x, y, z");
}

void read_kind_keys(Entry& e, VehicleElement& el) {
  switch (el.kind) {
    case ElementKind::kSpringDamper:
      el.stiffness = e.vector3_or("stiffness");
      el.damping = e.vector3_or("damping");
      e.check_all_used({"name", "kind", "bodies", "attachments", "stiffness", "damping"});
      return;
    case ElementKind::kTorsionalSpring:
      el.yaw_stiffness = e.number_or("yaw_stiffness", 0);
      el.roll_stiffness = e.number_or("roll_stiffness", 0);
      el.yaw_damping = e.number_or("yaw_damping", 0);
      el.roll_damping = e.number_or("roll_damping", 0);
      e.check_all_used({"name", "kind", "bodies", "attachments", "yaw_stiffness", "roll_stiffness", "yaw_damping",
                        "roll_damping"});
      return;
    case ElementKind::kBumpStop:
      el.direction = direction(e);
      el.clearance = e.number("clearance");
      el.stop_stiffness = e.number("stiffness");
      e.check_all_used({"name", "kind", "bodies", "attachments", "direction", "clearance", "stiffness"});
      return;
    case ElementKind::kNonlinearDamper: {
      el.direction = direction(e);
      const json& curve = e.at("curve");
      if (!curve.is_array()) e.fail("curve", "must be an array of [velocity, force] pairs");
      for (const json& point : curve) {
        if (!point.is_array() || point.size() != 2) e.fail("curve", "must be an array of [velocity, force] pairs");
        el.curve.emplace_back(e.as_number(point[0], "curve"), e.as_number(point[1], "curve"));
      }
      e.check_all_used({"name", "kind", "bodies", "attachments", "direction", "curve"});
      return;
    }
  }
}

VehicleElement read_element(const json& object, std::size_t index) {
  VehicleElement el;
  el.name = name_of(object, "element", index);
  Entry e(object, "element '" + el.name + "': ");
  e.text("name");
  el.kind = element_kind(e);
  const json& bodies = e.at("bodies");
  if (!bodies.is_array() || bodies.size() != 2 || !bodies[0].is_string() || !bodies[1].is_string())
    e.fail("bodies", "must be two body names (or \"track\")");
  el.bodies = {bodies[0].get<std::string>(), bodies[1].get<std::string>()};
  const json& points = e.at("attachments");
  if (!points.is_array() || points.size() != 2) e.fail("attachments", "must be two points [[x, y, z], [x, y, z]]");
  el.attachments = {e.as_vector3(points[0], "attachments"), e.as_vector3(points[1], "attachments")};
  read_kind_keys(e, el);
  return el;
}

// The file's JSON with every key given twice in any object refused (the parser would keep the last).
json parse_strict(const std::string& text, const std::string& source) {
  std::vector<std::set<std::string>> keys;
  const json::parser_callback_t check = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    if (event == json::parse_event_t::object_end) keys.pop_back();
    if (event == json::parse_event_t::key && !keys.back().insert(parsed.get<std::string>()).second)
      throw std::invalid_argument(source + ": " + parsed.get<std::string>() + ": key given twice in one object");
    return true;
  };
  try {
    return json::parse(text, check, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::exception& e) {
    throw std::invalid_argument(source + ": not valid JSON: " + e.what());
  }
}

}  // namespace

VehicleDescription parse_vehicle(const std::string& json_text, const std::string& source) {
  const json file = parse_strict(json_text, source);
  VehicleDescription v;
  try {
    Entry top(file, "");
    v.name = top.text("name");
    const json& bodies = top.at("bodies");
    const json& elements = top.at("elements");
    if (!bodies.is_array()) top.fail("bodies", "must be an array of bodies");
    if (!elements.is_array()) top.fail("elements", "must be an array of elements");
    top.check_all_used({"name", "bodies", "elements"});
    for (std::size_t k = 0; k < bodies.size(); ++k) v.bodies.push_back(read_body(bodies[k], k));
    for (std::size_t k = 0; k < elements.size(); ++k) v.elements.push_back(read_element(elements[k], k));
    validate(v);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
  return v;
}

VehicleDescription read_vehicle_file(const std::string& path) {
  return parse_vehicle(read_regular_file(path, kMaxFileBytes), path);
}

}  // namespace wrc
