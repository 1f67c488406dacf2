// SPDX-License-Identifier: Apache-2.0
#include "options/options.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

// "-yaw", "-x": a dash and a letter, a mistyped option even where positional words are allowed
// (a negative number "-0.05" or "-.5" is not one).
bool looks_like_short_option(const std::string& arg) {
  return arg.size() > 1 && arg[0] == '-' && std::isalpha(static_cast<unsigned char>(arg[1]));
}

}  // namespace

double parse_finite(const std::string& text, const std::string& what) {
  if (const std::optional<double> value = finite_number(text)) return *value;
  throw UsageError(not_a_finite_number(what, text));
}

Options::Options(std::string command, std::string synopsis, std::vector<OptionSpec> specs,
                 const std::vector<std::string>& args, Positional positional)
    : Options("wrc " + command, command + ": ", std::move(synopsis), std::move(specs), args,
              ParseRules{positional, Unknown::kRejected, Repeated::kRejected}) {}

Options Options::for_program(std::string program, std::string synopsis, std::vector<OptionSpec> specs,
                             const std::vector<std::string>& args, ParseRules rules) {
  return Options(std::move(program), "", std::move(synopsis), std::move(specs), args, rules);
}

Options::Options(std::string program, std::string label, std::string synopsis, std::vector<OptionSpec> specs,
                 const std::vector<std::string>& args, ParseRules rules)
    : program_(std::move(program)), label_(std::move(label)), synopsis_(std::move(synopsis)), specs_(std::move(specs)) {
  // Every declared default of an option with a range lies in it (a programming error otherwise,
  // found by any --help of the command).
  for (const OptionSpec& spec : specs_) {
    if (!spec.range) continue;
    const std::optional<double> value = finite_number(spec.default_text);
    if (value && !(*value >= spec.range->min && *value <= spec.range->max))
      throw std::logic_error(program_ + ": the default " + spec.default_text + " of " + spec.name +
                             " is outside its range [" + number_text(spec.range->min) + ", " +
                             number_text(spec.range->max) + "]");
  }
  const bool pass_on = rules.unknown == Unknown::kPassedOn;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
      continue;
    }
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
      if (!pass_on && looks_like_short_option(arg))
        throw UsageError(label_ + "unexpected argument '" + arg + "' (options start with --; see " + program_ +
                         " --help)");
      (pass_on ? passed_on_ : positional_).push_back(arg);
      continue;
    }
    std::string name = arg;
    std::optional<std::string> inline_value;
    if (auto eq = arg.find('='); eq != std::string::npos) {
      name = arg.substr(0, eq);
      inline_value = arg.substr(eq + 1);
    }
    auto spec = std::find_if(specs_.begin(), specs_.end(), [&](const auto& s) { return s.name == name; });
    if (spec == specs_.end()) {
      if (pass_on) {
        passed_on_.push_back(arg);
        continue;
      }
      throw UsageError("unknown option " + name + " (see " + program_ + " --help)");
    }
    if (find(name)) {
      if (rules.repeated == Repeated::kRejected) throw UsageError("option " + name + " given twice");
      values_.erase(std::remove_if(values_.begin(), values_.end(), [&](const auto& kv) { return kv.first == name; }),
                    values_.end());
    }
    if (!spec->takes_value) {
      if (inline_value) throw UsageError("option " + name + " takes no value");
      values_.emplace_back(name, "1");
      continue;
    }
    if (inline_value) {
      values_.emplace_back(name, *inline_value);
    } else {
      if (i + 1 >= args.size()) throw UsageError("option " + name + " needs a value");
      // "--y --yaw 0.001": the value forgotten, the next option taken for it.
      if (args[i + 1].rfind("--", 0) == 0)
        throw UsageError("option " + name + " needs a value, but the next argument is the option '" + args[i + 1] +
                         "' (give " + name + "=VALUE for a value that starts with --)");
      values_.emplace_back(name, args[++i]);
    }
  }
  if (!pass_on && rules.positional == Positional::kRejected && !positional_.empty() && !help_) {
    const std::string& stray = positional_.front();
    throw UsageError(label_ + "unexpected argument '" + stray + "'" +
                     (stray.size() > 1 && stray[0] == '-' ? " (options start with --)" : "") + " (see " + program_ +
                     " --help)");
  }
}

std::string Options::option_lines(const std::vector<OptionSpec>& specs) {
  std::ostringstream out;
  for (const auto& s : specs) {
    std::string left = "  " + s.name + (s.takes_value ? " V" : "");
    out << left << std::string(left.size() < 26 ? 26 - left.size() : 1, ' ') << s.help;
    if (!s.default_text.empty()) out << " (default " << s.default_text << ")";
    out << "\n";
  }
  return out.str();
}

std::string Options::help() const {
  std::ostringstream out;
  out << "usage: " << program_ << " " << synopsis_ << "\n";
  if (!specs_.empty()) out << "\noptions:\n" << option_lines(specs_);
  return out.str();
}

const OptionSpec& Options::declared(const std::string& name) const {
  for (const OptionSpec& s : specs_)
    if (s.name == name) return s;
  throw std::logic_error(program_ + ": lookup of the undeclared option " + name);
}

double Options::default_number(const std::string& name) const {
  const OptionSpec& spec = declared(name);
  if (const std::optional<double> value = finite_number(spec.default_text)) return *value;
  throw std::logic_error(program_ + ": option " + name + " has no number as its default ('" + spec.default_text +
                         "'); its absence is the caller's to handle");
}

std::optional<std::string> Options::find(const std::string& name) const {
  declared(name);
  for (const auto& [k, v] : values_)
    if (k == name) return v;
  return std::nullopt;
}

bool Options::has(const std::string& name) const { return find(name).has_value(); }

std::string Options::text(const std::string& name, const std::string& fallback) const {
  return find(name).value_or(fallback);
}

std::string Options::required_text(const std::string& name) const {
  auto v = find(name);
  if (!v) throw UsageError("missing required option " + name);
  return *v;
}

// value (typed as text, or the declared default) within [min, max]; the refusal names the option,
// the text and the range, then hint.
static double check_range(double value, const std::string& name, const std::string& text, double min, double max,
                          const std::string& hint = "") {
  if (!(value >= min && value <= max)) {
    std::ostringstream msg;
    msg << name << ": " << text << " is outside [" << min << ", " << max << "]" << hint;
    throw UsageError(msg.str());
  }
  return value;
}

double Options::number(const std::string& name) const {
  return number_within(name, declared(name).range.value_or(NumberRange{}));
}

double Options::number_within(const std::string& name, NumberRange range) const {
  auto v = find(name);
  if (!v) {
    // The declared default obeys the same range as a value typed: a table and a call site that
    // disagree, or a range that another option moved (--backoff-max below --backoff-min), are
    // refused naming the option instead of running with an out-of-range value.
    return check_range(default_number(name), name, "its default " + declared(name).default_text, range.min, range.max,
                       "; give " + name + " a value");
  }
  return check_range(parse_finite(*v, name), name, *v, range.min, range.max);
}

double Options::required_number(const std::string& name) const {
  const NumberRange range = declared(name).range.value_or(NumberRange{});
  auto v = find(name);
  if (!v) throw UsageError("missing required option " + name);
  return check_range(parse_finite(*v, name), name, *v, range.min, range.max);
}

int Options::integer(const std::string& name) const {
  const IntegerRange whole;
  const NumberRange range = declared(name).range.value_or(NumberRange{double(whole.min), double(whole.max)});
  auto v = find(name);
  if (!v) {
    const double d = default_number(name);
    if (d != std::floor(d)) throw std::logic_error(program_ + ": option " + name + " has no whole number as its default");
    return static_cast<int>(check_range(d, name, "its default " + declared(name).default_text, range.min, range.max,
                                        "; give " + name + " a value"));
  }
  const double d = parse_finite(*v, name);
  if (d != std::floor(d)) throw UsageError(name + ": '" + *v + "' is not a whole number");
  return static_cast<int>(check_range(d, name, *v, range.min, range.max));
}

std::string Options::choice(const std::string& name, const std::vector<std::string>& words) const {
  auto v = find(name);
  if (!v) return declared(name).default_text;
  if (std::find(words.begin(), words.end(), *v) != words.end()) return *v;
  std::string list;
  for (const auto& w : words) list += (list.empty() ? "" : ", ") + w;
  throw UsageError(name + ": '" + *v + "' is not one of " + list);
}

}  // namespace wrc
