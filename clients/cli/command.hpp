// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Subcommands of the `wrc` front end. Each subcommand lives in its own cmd_<name>.cpp and
/// registers itself with a static CommandRegistrar, so adding a command touches one file.

#include <string>
#include <vector>

namespace wrc::cli {

/// One subcommand: its name as typed, a one-line summary for `wrc --help`, and its entry point.
/// run() gets the arguments after the subcommand name and returns the process exit code.
struct Command {
  std::string name;
  std::string summary;
  int (*run)(const std::vector<std::string>& args);
};

/// All registered subcommands, in registration order.
std::vector<Command>& command_registry();

/// Registers a command at static-initialisation time: `static CommandRegistrar reg{{...}};`.
struct CommandRegistrar {
  explicit CommandRegistrar(Command command) { command_registry().push_back(std::move(command)); }
};

}  // namespace wrc::cli
