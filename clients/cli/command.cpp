// SPDX-License-Identifier: Apache-2.0
#include "cli/command.hpp"

namespace wrc::cli {

std::vector<Command>& command_registry() {
  static std::vector<Command> registry;  // filled by the commands' registrars before main()
  return registry;
}

}  // namespace wrc::cli
