// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/run_parameters_file.hpp"

#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/numerics/regular_file.hpp"

namespace wrc {
namespace {

constexpr std::size_t kMaxFileBytes = 1u << 20;

using nlohmann::json;

// "<source>: <key>: unknown parameter (known: ...)".
std::invalid_argument unknown_parameter(const std::string& source, const std::string& key) {
  std::string known;
  for (const RunParameter& p : run_parameter_table()) known += std::string(known.empty() ? "" : ", ") + p.key;
  return std::invalid_argument(source + ": " + key + ": unknown parameter (known: " + known + ")");
}

// nlohmann-json's SAX interface over a parameter file: the members of its one top-level object in
// file order (a nested object or array as an empty one of its kind: it is no parameter value),
// a key given twice in any object refused, and a number beyond the range of a double (1e999,
// which the DOM parser reports without the file or the key) refused naming the key and its range.
class ParameterFileReader {
 public:
  explicit ParameterFileReader(const std::string& source) : source_(source) {}

  std::vector<std::pair<std::string, json>> members;

  bool null() { return value(nullptr); }
  bool boolean(bool v) { return value(v); }
  bool number_integer(json::number_integer_t v) { return value(v); }
  bool number_unsigned(json::number_unsigned_t v) { return value(v); }
  bool number_float(json::number_float_t v, const json::string_t&) { return value(v); }
  bool string(json::string_t& v) { return value(v); }
  bool binary(json::binary_t&) { return value(json::binary_t{}); }
  bool start_object(std::size_t) { return open(true); }
  bool start_array(std::size_t) { return open(false); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(json::string_t& k) {
    Level& level = levels_.back();
    if (!level.keys.insert(k).second)
      throw std::invalid_argument(source_ + ": " + path(k) + ": duplicate key (each key may appear once)");
    level.key = k;
    return true;
  }

  bool parse_error(std::size_t, const std::string& last_token, const json::exception& e) {
    constexpr int kNumberOverflow = 406;  // nlohmann-json: a number beyond the range of a double
    if (e.id == kNumberOverflow && levels_.size() == 1) {
      const std::string& key = levels_.front().key;
      const RunParameter* entry = find_parameter(run_parameter_table(), key);
      if (!entry) throw unknown_parameter(source_, key);
      if (entry->kind == RunParameterKind::kBoolean)
        throw std::invalid_argument(source_ + ": " + key + ": must be true or false");
      const ParameterRange& range = entry->range;
      const bool bounded = std::isfinite(range.min) || std::isfinite(range.max);
      throw std::invalid_argument(source_ + ": " + key + " = " + last_token + " is not a finite number" +
                                  (bounded ? " (valid: " + range.text() + " [" + entry->unit + "])" : ""));
    }
    // Elsewhere: the top-level key it is under, if any.
    const std::string under = levels_.empty() || levels_.front().key.empty() ? "" : levels_.front().key;
    if (e.id == kNumberOverflow)
      throw std::invalid_argument(source_ + ": " + (under.empty() ? "" : under + ": ") + last_token +
                                  " is not a finite number");
    throw std::invalid_argument(source_ + ": not valid JSON" + (under.empty() ? "" : " after the key " + under) + ": " +
                                e.what());
  }

 private:
  struct Level {
    bool object = false;
    std::set<std::string> keys;
    std::string key;  ///< the last key read in this object
  };

  // The keys from the top-level object down to key: "a.b.key" ("[]" for an array on the way).
  std::string path(const std::string& key) const {
    std::string p;
    for (std::size_t k = 0; k + 1 < levels_.size(); ++k)
      p += levels_[k].object ? levels_[k].key + "." : std::string("[].");
    return p + key;
  }

  bool value(json v) {
    if (levels_.empty()) throw std::invalid_argument(source_ + ": the parameter file must hold one JSON object");
    if (levels_.size() == 1) members.emplace_back(levels_.front().key, std::move(v));
    return true;
  }

  bool open(bool object) {
    if (levels_.empty() && !object)
      throw std::invalid_argument(source_ + ": the parameter file must hold one JSON object");
    if (!levels_.empty()) value(object ? json::object() : json::array());
    levels_.push_back({object, {}, {}});
    return true;
  }

  bool close() {
    levels_.pop_back();
    return true;
  }

  const std::string& source_;
  std::vector<Level> levels_;
};

}  // namespace

void apply_run_parameters(const std::string& text, const std::string& source, RunSpec& spec) {
  ParameterFileReader reader(source);
  json::sax_parse(text, &reader, json::input_format_t::json, /*strict=*/true, /*ignore_comments=*/true);
  for (const auto& [key, v] : reader.members) {
    const RunParameter* entry = find_parameter(run_parameter_table(), key);
    if (!entry) throw unknown_parameter(source, key);
    if (entry->kind == RunParameterKind::kBoolean) {
      if (!v.is_boolean()) throw std::invalid_argument(source + ": " + key + ": must be true or false");
      entry->set(spec, v.get<bool>() ? 1.0 : 0.0);
      continue;
    }
    if (!v.is_number()) throw std::invalid_argument(source + ": " + key + ": must be a number");
    // The table's rule: a whole number for a count, within the range (max_steps = 1e30 is outside
    // it, not "not a whole number").
    const double value = v.get<double>();
    if (const std::optional<std::string> why = entry->violation(value))
      throw std::invalid_argument(source + ": " + parameter_error(*entry, value, *why));
    entry->set(spec, value);
  }
  try {
    spec.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
}

void apply_run_parameter_file(const std::string& path, RunSpec& spec) {
  apply_run_parameters(read_regular_file(path, kMaxFileBytes), path, spec);
}

std::string run_parameter_text(const RunSpec& spec) {
  std::ostringstream out;
  out << "{\n";
  const auto& table = run_parameter_table();
  for (std::size_t k = 0; k < table.size(); ++k) {
    const RunParameter& p = table[k];
    out << "  \"" << p.key << "\": " << p.value_text(p.get(spec));
    out << (k + 1 < table.size() ? "," : "") << "  // [" << p.unit << "] " << p.description << "\n";
  }
  out << "}\n";
  return out.str();
}

}  // namespace wrc
