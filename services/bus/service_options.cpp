#include "bus/service_options.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace wrc::bus {

namespace {
double parse_period(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || value <= 0.0 ||
      value > 60.0) {
    throw std::invalid_argument("--heartbeat-period: '" + text + "' is not a number in (0, 60] s");
  }
  return value;
}

void check_instance(const std::string& name) {
  bool ok = !name.empty() && name.size() <= 24;
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-');
  if (!ok) {
    throw std::invalid_argument("--instance: '" + name +
                                "' must be 1-24 letters, digits, '_' or '-'");
  }
}
}  // namespace

ServiceOptions ServiceOptions::parse(int argc, const char* const* argv) {
  ServiceOptions options;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    std::string value;
    bool has_inline = false;
    if (auto eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      has_inline = true;
    }
    const bool ours = arg == "--lcm-url" || arg == "--channel-prefix" || arg == "--instance" ||
                      arg == "--heartbeat-period";
    if (arg == "--help" || arg == "-h") {
      options.help = true;
      continue;
    }
    if (!ours) {
      options.rest.push_back(argv[i]);
      continue;
    }
    if (!has_inline) {
      if (i + 1 >= argc) throw std::invalid_argument("option " + arg + " needs a value");
      value = argv[++i];
    }
    if (arg == "--lcm-url") {
      options.lcm_url = value;
    } else if (arg == "--channel-prefix") {
      options.channel_prefix = value;
    } else if (arg == "--instance") {
      check_instance(value);
      options.instance = value;
    } else {
      options.heartbeat_period = parse_period(value);
    }
  }
  return options;
}

std::string ServiceOptions::help_text() {
  return "  --lcm-url URL           LCM URL (default: LCM's own, udpm ttl=0, or $LCM_DEFAULT_URL)\n"
         "  --channel-prefix P      prefix of every channel, P.HEARTBEAT etc. (default none)\n"
         "  --instance NAME         instance name, unique per model on the bus (default 0)\n"
         "  --heartbeat-period S    heartbeat period [s] (default 0.5)\n";
}

}  // namespace wrc::bus
