// SPDX-License-Identifier: Apache-2.0
// wrc-cli: dispatches `wrc-cli <command> [options]` to the registered subcommands.
// The shell front end clients/wrc sets up and builds the project, then execs this program.

#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "bus/process/line_atomic_stderr.hpp"
#include "cli/command.hpp"

namespace {
void print_usage(std::ostream& out) {
  auto commands = wrc::cli::command_registry();
  std::sort(commands.begin(), commands.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  out << "usage: wrc <command> [options]   (all numbers in SI units)\n\ncommands:\n";
  for (const auto& c : commands) out << "  " << c.name << std::string(12 - std::min<size_t>(11, c.name.size()), ' ') << c.summary << "\n";
  out << "\n`wrc <command> --help` describes one command.\n";
}
}  // namespace

int main(int argc, char** argv) {
  wrc::bus::make_stderr_line_atomic();  // one log shared with other processes: whole lines only
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_usage(std::cout);
    return args.empty() ? 2 : 0;
  }
  const auto& commands = wrc::cli::command_registry();
  auto it = std::find_if(commands.begin(), commands.end(),
                         [&](const auto& c) { return c.name == args[0]; });
  if (it == commands.end()) {
    std::cerr << "wrc: unknown command '" << args[0] << "' (see wrc --help)\n";
    return 2;
  }
  try {
    return it->run(std::vector<std::string>(args.begin() + 1, args.end()));
  } catch (const std::exception& e) {
    std::cerr << "wrc " << args[0] << ": " << e.what() << "\n";
    return 1;
  }
}
