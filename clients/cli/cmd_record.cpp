// wrc record / wrc replay: the bus to a log file with LCM's lcm-logger, and a log back onto the
// bus with lcm-logplayer, so that `wrc spy` and `wrc plot run FILE` see a run as if live. The
// recorded messages keep their authentication trailers; wrc's services drop a replayed copy of a
// message they have seen or one older than their freshness window (docs/bus-security.md), so a
// replay is for watching and plotting, not for driving services.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/options.hpp"

namespace wrc::cli {
namespace {

// Replaces this process with program and its arguments (an error when it cannot start).
int exec_tool(const std::string& program, const std::vector<std::string>& words) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& w : words) argv.push_back(const_cast<char*>(w.c_str()));
  argv.push_back(nullptr);
  ::execvp(program.c_str(), argv.data());
  throw std::runtime_error(program + " could not be started (liblcm-bin installs it): " + std::string(strerror(errno)));
}

int run_record(const std::vector<std::string>& args) {
  const std::vector<OptionSpec> specs{
      {"--channel-prefix", true, "record only the channels of this simulation", "every channel"},
      {"--lcm-url", true, "LCM URL", "LCM's default"},
      {"--force", false, "overwrite an existing FILE", ""}};
  const Options o("record", "FILE [options]", specs, args, Positional::kAllowed);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nRecords every message on the bus into FILE (an LCM log) with lcm-logger until Ctrl-C.\n"
                 "`wrc plot run FILE` draws a run's time histories from it; `wrc replay FILE` plays it back.\n";
    return 0;
  }
  if (o.positional().size() != 1) throw UsageError("record: give exactly one FILE");
  std::vector<std::string> words;
  if (o.has("--channel-prefix")) words.push_back("--channel=" + o.text("--channel-prefix") + "\\..*");
  if (o.has("--lcm-url")) words.push_back("--lcm-url=" + o.text("--lcm-url"));
  if (o.has("--force")) words.push_back("--force");
  words.push_back(o.positional().front());
  return exec_tool("lcm-logger", words);
}

int run_replay(const std::vector<std::string>& args) {
  const std::vector<OptionSpec> specs{{"--speed", true, "playback speed multiplier", "1"},
                                      {"--lcm-url", true, "LCM URL", "LCM's default"}};
  const Options o("replay", "FILE [options]", specs, args, Positional::kAllowed);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nPlays an LCM log (wrc record) back onto the bus with lcm-logplayer, with the recorded timing\n"
                 "(scaled by --speed), so that `wrc spy` shows it as if live.\n";
    return 0;
  }
  if (o.positional().size() != 1) throw UsageError("replay: give exactly one FILE");
  std::vector<std::string> words{"--speed=" + std::to_string(o.number("--speed", 1.0, 1e-3, 1e3))};
  if (o.has("--lcm-url")) words.push_back("--lcm-url=" + o.text("--lcm-url"));
  words.push_back(o.positional().front());
  return exec_tool("lcm-logplayer", words);
}

const CommandRegistrar record_registrar{{"record", "record the bus into an LCM log (lcm-logger)", run_record}};
const CommandRegistrar replay_registrar{{"replay", "play an LCM log back onto the bus (lcm-logplayer)", run_replay}};

}  // namespace
}  // namespace wrc::cli
