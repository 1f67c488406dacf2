// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The main() of a service with options of its own: whole-line stderr, the options every service
/// shares (bus/service/service_options.hpp), --help, the service's own options, run(), and a one-line error
/// with exit code 1 for anything that escapes.

#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bus/process/line_atomic_stderr.hpp"
#include "bus/service/service_options.hpp"

namespace wrc::bus {

/// The OwnOptions of a service without options of its own: any other argument is an error.
struct NoOwnOptions {
  static NoOwnOptions parse(const std::vector<std::string>& rest) {
    if (!rest.empty()) throw std::invalid_argument("unknown argument '" + rest.front() + "' (see --help)");
    return {};
  }
  static std::string help_text() { return ""; }
};

/// OwnOptions: a type with static OwnOptions parse(const std::vector<std::string>&) and static
/// std::string help_text(). run(const ServiceOptions&, const OwnOptions&) returns the exit code.
/// @param usage the first lines of --help (what the service does, its channels).
template <class OwnOptions, class Run>
int service_main(int argc, char** argv, const std::string& program, const std::string& usage, Run run) {
  make_stderr_line_atomic();  // one log shared with other processes: whole lines only
  try {
    const auto service = ServiceOptions::parse(argc, argv);
    if (service.help) {
      std::cout << usage << "\n" << OwnOptions::help_text() << ServiceOptions::help_text();
      return 0;
    }
    const auto options = OwnOptions::parse(service.rest);
    return run(service, options);
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace wrc::bus
