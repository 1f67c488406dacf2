// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The one command-line option parser of wrc: every `wrc <command>` of the front end and every
/// service process (wrc-contactd, wrc-geometryd, ...) declare their options in an OptionSpec table
/// and parse with Options: `--name value`, `--name=value` and `--flag`, numbers checked (finite, in
/// range), clear one-line errors (UsageError), --help generated from the table. No LCM here.

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace wrc {

/// The valid values of a number option: [min, max].
struct NumberRange {
  double min = -1e300;
  double max = 1e300;
};

/// The valid values of a whole-number option: [min, max].
struct IntegerRange {
  int min = 1;
  int max = 1000000;
};

/// Declaration of one option: its name (with the leading --), whether it takes a value,
/// the help text (state the unit in brackets) and its default: shown in --help and, when it is a
/// value (a number, a word of a choice), the value number(), integer() and choice() give for an
/// absent option, so a default is written once. A default that is a description ("from the
/// file", "none") leaves the absent case to the caller (has()).
struct OptionSpec {
  std::string name;
  bool takes_value = true;
  std::string help;
  std::string default_text;
  /// The valid values of a number option, the one place its range is stated: number(),
  /// required_number() and integer() check a typed value against it, and the parser the default.
  std::optional<NumberRange> range = std::nullopt;
};

/// Thrown for bad command-line input; the message is one line naming the bad value.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Whether a command takes arguments that are not options (`wrc launch [services...]`).
enum class Positional { kRejected, kAllowed };

/// What becomes of options the table does not name: refused (UsageError), or passed on verbatim,
/// in order, to a later parser (passed_on(); the options every service shares are parsed first,
/// the service's own options from what is left: bus/service/service_options.hpp).
enum class Unknown { kRejected, kPassedOn };

/// What an option given twice does: refused (UsageError), or the last one wins (a service's
/// command line: `wrc launch --lcm-url U` appends to the profile's line, which may name it).
enum class Repeated { kRejected, kLastWins };

/// How Options::for_program treats arguments its table does not describe plainly.
struct ParseRules {
  Positional positional = Positional::kRejected;
  Unknown unknown = Unknown::kRejected;
  Repeated repeated = Repeated::kRejected;
};

/// Parsed options of one command or program. Every lookup (has, text, number, ...) must name a
/// declared option: an undeclared name is a programming error (a misspelled "--yaww" would
/// otherwise read as absent), std::logic_error naming it.
class Options {
 public:
  /// Parses the arguments of `wrc <command>` against specs. Unknown options, missing values and
  /// repeated options throw UsageError, and so does any argument not starting with -- (a stray
  /// word, a mistyped `-yaw`) unless positional is kAllowed; a dash and a letter (`-yaw`) is
  /// refused even then (a negative number is not). `--help` is always accepted (see
  /// help_requested()).
  Options(std::string command, std::string synopsis, std::vector<OptionSpec> specs,
          const std::vector<std::string>& args, Positional positional = Positional::kRejected);

  /// Parses the arguments of a program of its own (a service, "wrc-contactd"): as above, with
  /// the program named in the messages and the help, under rules. With Unknown::kPassedOn,
  /// unknown options and every argument not starting with -- are kept for passed_on() instead of
  /// being refused (rules.positional is then ignored).
  static Options for_program(std::string program, std::string synopsis, std::vector<OptionSpec> specs,
                             const std::vector<std::string>& args, ParseRules rules = {});

  /// True when --help was given; print help() and exit 0 then.
  bool help_requested() const { return help_; }
  /// The --help text: synopsis and one line per option.
  std::string help() const;
  /// One line per option of specs (what help() lists after "options:").
  static std::string option_lines(const std::vector<OptionSpec>& specs);

  bool has(const std::string& name) const;
  /// The raw text of an option, or fallback when absent.
  std::string text(const std::string& name, const std::string& fallback = "") const;
  /// A required text option; throws UsageError naming it when absent.
  std::string required_text(const std::string& name) const;
  /// A finite number in its declared range, the declared default when absent; throws UsageError
  /// naming the option and the text when not a finite number or outside the range,
  /// std::logic_error when absent and the declared default is no number.
  double number(const std::string& name) const;
  /// As number(), within range instead: only for a range that depends on another option's value
  /// (--backoff-max at least --backoff-min); a fixed range belongs to the declaration.
  double number_within(const std::string& name, NumberRange range) const;
  /// A required finite number in its declared range.
  double required_number(const std::string& name) const;
  /// A whole number in its declared range (without one, IntegerRange{}), the declared default
  /// when absent (as number()).
  int integer(const std::string& name) const;
  /// One of the given words, the declared default when absent; throws UsageError listing them
  /// otherwise.
  std::string choice(const std::string& name, const std::vector<std::string>& words) const;
  /// Positional arguments (those not starting with --).
  const std::vector<std::string>& positional() const { return positional_; }
  /// With Unknown::kPassedOn: the arguments not consumed here, verbatim and in order.
  const std::vector<std::string>& passed_on() const { return passed_on_; }

 private:
  /// program: as typed ("wrc geometry", "wrc-contactd"); label: the prefix of the stray-argument
  /// message ("geometry: "; empty for a program, whose main() names it already).
  Options(std::string program, std::string label, std::string synopsis, std::vector<OptionSpec> specs,
          const std::vector<std::string>& args, ParseRules rules);
  /// The declaration of name. @throws std::logic_error when name is not declared.
  const OptionSpec& declared(const std::string& name) const;
  /// The declared default of name as a number. @throws std::logic_error when it is none.
  double default_number(const std::string& name) const;
  std::optional<std::string> find(const std::string& name) const;
  std::string program_;
  std::string label_;
  std::string synopsis_;
  std::vector<OptionSpec> specs_;
  std::vector<std::pair<std::string, std::string>> values_;
  std::vector<std::string> positional_;
  std::vector<std::string> passed_on_;
  bool help_ = false;
};

/// Parses text as a finite double; throws UsageError "<what>: '<text>' is not a finite number".
double parse_finite(const std::string& text, const std::string& what);

}  // namespace wrc
