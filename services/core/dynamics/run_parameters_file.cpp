#include "core/dynamics/run_parameters_file.hpp"

#include <sys/stat.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace wrc {
namespace {

constexpr std::size_t kMaxFileBytes = 1u << 20;

}  // namespace

void apply_run_parameters(const std::string& text, const std::string& source, RunSpec& spec) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(source + ": not valid JSON: " + e.what());
  }
  if (!doc.is_object()) throw std::invalid_argument(source + ": the parameter file must hold one JSON object");
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string& key = it.key();
    const RunParameter* entry = find_parameter(run_parameter_table(), key);
    if (!entry) {
      std::string known;
      for (const RunParameter& p : run_parameter_table()) known += std::string(known.empty() ? "" : ", ") + p.key;
      throw std::invalid_argument(source + ": " + key + ": unknown parameter (known: " + known + ")");
    }
    if (entry->kind == RunParameterKind::kBoolean) {
      if (!it->is_boolean()) throw std::invalid_argument(source + ": " + key + ": must be true or false");
      entry->set(spec, it->get<bool>() ? 1.0 : 0.0);
      continue;
    }
    if (!it->is_number()) throw std::invalid_argument(source + ": " + key + ": must be a number");
    const double v = it->get<double>();
    if (entry->kind == RunParameterKind::kInteger && !(std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e12))
      throw std::invalid_argument(source + ": " + key + ": " + std::to_string(v) + " is not a whole number");
    if (const std::optional<std::string> why = entry->violation(v))
      throw std::invalid_argument(source + ": " + parameter_error(*entry, v, *why));
    entry->set(spec, v);
  }
  try {
    spec.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
}

void apply_run_parameter_file(const std::string& path, RunSpec& spec) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw std::runtime_error(path + ": cannot read the parameter file");
  if (!S_ISREG(st.st_mode)) throw std::invalid_argument(path + ": not a regular file");
  if (static_cast<std::size_t>(st.st_size) > kMaxFileBytes)
    throw std::invalid_argument(path + ": " + std::to_string(st.st_size) + " bytes, more than a parameter file has");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw std::runtime_error(path + ": read error");
  apply_run_parameters(text.str(), path, spec);
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
