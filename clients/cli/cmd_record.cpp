// SPDX-License-Identifier: Apache-2.0
// wrc record / wrc replay: the bus to an LCM log file and a log back onto the bus with
// lcm-logplayer, so that `wrc spy` and `wrc plot run FILE` see a run as if live. The recorded
// messages keep their authentication trailers; wrc's services drop a replayed copy of a message
// they have seen or one older than their freshness window (docs/bus-security.md), so a replay is
// for watching and plotting, not for driving services.
//
// Recording is done here, not by lcm-logger: lcm-logger keeps LCM's default subscription queue of
// 30 messages and discards what it has not yet written when it is stopped, so on a loaded machine
// a run's burst of states was lost (how many: docs/performance.md). This recorder queues up to kQueueCapacity messages, writes them with LCM's
// own log writer (the file is an ordinary LCM log that lcm-logplayer, lcm-spy and lcm::LogFile
// read), and on Ctrl-C writes every message already received before it closes the file.
#include <unistd.h>

#include <lcm/lcm-cpp.hpp>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "bus/process/shutdown_signal.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/lcm_url.hpp"
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

// [messages] LCM queue of the recorder's subscription: a run's bursts (states, contact batches)
// wait here while the file is written.
constexpr int kQueueCapacity = 100000;

// Writes every message heard on the channels matching `pattern` into `log` until Ctrl-C, then
// what is still queued. Returns the number of messages written.
long record_until_interrupted(lcm::LCM& lcm, lcm::LogFile& log, const std::string& pattern, const std::string& file) {
  struct Writer {
    lcm::LogFile* log;
    const std::string* file;
    long written = 0;
    long long bytes = 0;
    void on_message(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
      lcm::LogEvent event;
      event.eventnum = written;
      event.timestamp = rbuf->recv_utime;
      event.channel = channel;
      event.datalen = static_cast<int32_t>(rbuf->data_size);
      event.data = rbuf->data;
      if (log->writeEvent(&event) != 0) throw std::runtime_error(*file + ": cannot write the log: " + strerror(errno));
      ++written;
      bytes += rbuf->data_size;
    }
  } writer{&log, &file};
  lcm::Subscription* sub = lcm.subscribe(pattern, &Writer::on_message, &writer);
  if (sub == nullptr) throw std::runtime_error("cannot subscribe to '" + pattern + "'");
  sub->setQueueCapacity(kQueueCapacity);
  bus::ShutdownSignal::install();
  std::cerr << "recording " << (pattern == ".*" ? std::string("every channel") : "channels " + pattern) << " into "
            << file << " (Ctrl-C ends)\n";
  while (!bus::ShutdownSignal::requested()) {
    // A signal interrupts the wait (the handler does not restart it): that is the end, not a failure.
    if (lcm.handleTimeout(100) < 0 && !bus::ShutdownSignal::requested())
      throw std::runtime_error("LCM failed while recording into " + file);
  }
  // What already arrived is written before the file closes.
  while (lcm.handleTimeout(0) > 0) {
  }
  lcm.unsubscribe(sub);
  std::cerr << "recorded " << writer.written << " messages (" << writer.bytes << " B) into " << file << "\n";
  return writer.written;
}

int run_record(const std::vector<std::string>& args) {
  const std::vector<OptionSpec> specs{
      {"--channel-prefix", true, "record only the channels of this simulation", "every channel"},
      {"--lcm-url", true, "LCM URL", "LCM's default"},
      {"--force", false, "overwrite an existing FILE", ""}};
  const Options o("record", "FILE [options]", specs, args, Positional::kAllowed);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nRecords every message on the bus into FILE (an LCM log, as lcm-logger writes it) until Ctrl-C.\n"
                 "`wrc plot run FILE` draws a run's time histories from it; `wrc replay FILE` plays it back.\n";
    return 0;
  }
  if (o.positional().size() != 1) throw UsageError("give exactly one FILE");
  const std::string file = o.positional().front();
  struct stat existing {};
  if (!o.has("--force") && ::stat(file.c_str(), &existing) == 0)
    throw UsageError(file + " exists (--force overwrites it)");
  const std::string pattern =
      o.has("--channel-prefix") ? bus::regex_escape(o.text("--channel-prefix") + ".") + ".*" : std::string(".*");
  lcm::LCM lcm(bus::effective_lcm_url(o.has("--lcm-url") ? o.text("--lcm-url") : std::string()));
  if (!lcm.good()) throw std::runtime_error("cannot open LCM (is there a multicast route? see `ip route`)");
  lcm::LogFile log(file, "w");
  if (!log.good()) throw std::runtime_error(file + ": cannot create the log: " + strerror(errno));
  record_until_interrupted(lcm, log, pattern, file);
  return 0;
}

int run_replay(const std::vector<std::string>& args) {
  const std::vector<OptionSpec> specs{{"--speed", true, "playback speed multiplier", "1", NumberRange{1e-3, 1e3}},
                                      {"--channels", true, "play only the channels matching this regular expression",
                                       "every channel"},
                                      {"--lcm-url", true, "LCM URL", "LCM's default"}};
  const Options o("replay", "FILE [options]", specs, args, Positional::kAllowed);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nPlays an LCM log (wrc record) back onto the bus with lcm-logplayer, with the recorded timing\n"
                 "(scaled by --speed), so that `wrc spy` shows it as if live.\n";
    return 0;
  }
  if (o.positional().size() != 1) throw UsageError("give exactly one FILE");
  std::vector<std::string> words{"--speed=" + std::to_string(o.number("--speed"))};
  if (o.has("--channels")) words.push_back("--regexp=" + o.text("--channels"));
  if (o.has("--lcm-url")) words.push_back("--lcm-url=" + o.text("--lcm-url"));
  words.push_back(o.positional().front());
  return exec_tool("lcm-logplayer", words);
}

const CommandRegistrar record_registrar{{"record", "record the bus into an LCM log", run_record}};
const CommandRegistrar replay_registrar{{"replay", "play an LCM log back onto the bus (lcm-logplayer)", run_replay}};

}  // namespace
}  // namespace wrc::cli
