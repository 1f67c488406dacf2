#pragma once
/// @file
/// A small command-line option parser shared by all subcommands: `--name value` pairs and
/// `--flag` switches, with numbers checked (finite, in range) and clear one-line errors.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace wrc::cli {

/// Declaration of one option: its name (with the leading --), whether it takes a value,
/// the help text (state the unit in brackets) and the default shown in --help.
struct OptionSpec {
  std::string name;
  bool takes_value = true;
  std::string help;
  std::string default_text;
};

/// Thrown for bad command-line input; the message is one line naming the bad value.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Whether a command takes arguments that are not options (`wrc launch [services...]`).
enum class Positional { kRejected, kAllowed };

/// Parsed options of one subcommand.
class Options {
 public:
  /// Parses args against specs. Unknown options, missing values and repeated options throw
  /// UsageError, and so does any argument not starting with -- (a stray word, a mistyped
  /// `-yaw`) unless positional is kAllowed. `--help` is always accepted (see help_requested()).
  Options(std::string command, std::string synopsis, std::vector<OptionSpec> specs,
          const std::vector<std::string>& args, Positional positional = Positional::kRejected);

  /// True when --help was given; print help() and exit 0 then.
  bool help_requested() const { return help_; }
  /// The --help text: synopsis and one line per option.
  std::string help() const;

  bool has(const std::string& name) const;
  /// The raw text of an option, or fallback when absent.
  std::string text(const std::string& name, const std::string& fallback = "") const;
  /// A required text option; throws UsageError naming it when absent.
  std::string required_text(const std::string& name) const;
  /// A finite number; throws UsageError naming the option and the text when not a finite number
  /// or outside [min, max].
  double number(const std::string& name, double fallback, double min = -1e300, double max = 1e300) const;
  /// A required finite number in [min, max].
  double required_number(const std::string& name, double min = -1e300, double max = 1e300) const;
  /// A positive whole number.
  int integer(const std::string& name, int fallback, int min = 1, int max = 1000000) const;
  /// One of the given words; throws UsageError listing them otherwise.
  std::string choice(const std::string& name, const std::vector<std::string>& words,
                     const std::string& fallback) const;
  /// Positional arguments (those not starting with --).
  const std::vector<std::string>& positional() const { return positional_; }

 private:
  std::optional<std::string> find(const std::string& name) const;
  std::string command_;
  std::string synopsis_;
  std::vector<OptionSpec> specs_;
  std::vector<std::pair<std::string, std::string>> values_;
  std::vector<std::string> positional_;
  bool help_ = false;
};

/// Parses text as a finite double; throws UsageError "<what>: '<text>' is not a finite number".
double parse_finite(const std::string& text, const std::string& what);

}  // namespace wrc::cli
