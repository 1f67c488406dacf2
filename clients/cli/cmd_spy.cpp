// SPDX-License-Identifier: Apache-2.0
// wrc spy: lcm-spy with the project's message types on its class path, so that every wrc message
// is decoded. Debian's /usr/bin/lcm-spy passes -Xincgc, which Java 17 rejects; the
// JDK_JAVA_OPTIONS=-XX:+IgnoreUnrecognizedVMOptions setting lets it start. lcm-spy finds types
// through the CLASSPATH environment variable.

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "bus/process/build_paths.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"

namespace wrc::cli {
namespace {

int run_spy(const std::vector<std::string>& args) {
  Options options("spy", "[options]",
                  {{"--lcm-url", true, "LCM URL to watch", "LCM's default"},
                   {"--jar", true, "types jar", "<build>/lcmtypes/wrc_lcmtypes_java.jar, installed <prefix>/share/java/"},
                   {"--print-command", false, "print the environment and command instead of running it", ""}},
                  args);
  if (options.help_requested()) {
    std::cout << options.help() << "\nNeeds a display (X11); on a headless machine use Xvfb.\n";
    return 0;
  }
  const std::string jar = options.text("--jar", bus::lcm_types_jar());
  if (!std::filesystem::is_regular_file(jar)) {
    throw UsageError("types jar '" + jar + "' does not exist (build the project first: clients/wrc build)");
  }
  std::string classpath = jar;
  if (const char* old = std::getenv("CLASSPATH"); old != nullptr && *old != '\0') classpath += ":" + std::string(old);
  const std::string java_options = "-XX:+IgnoreUnrecognizedVMOptions";
  std::vector<std::string> command{"lcm-spy"};
  if (options.has("--lcm-url")) command.push_back("--lcm-url=" + options.text("--lcm-url"));

  if (options.has("--print-command")) {
    std::cout << "CLASSPATH=" << classpath << " JDK_JAVA_OPTIONS=" << java_options;
    for (const auto& word : command) std::cout << " " << word;
    std::cout << "\n";
    return 0;
  }
  ::setenv("CLASSPATH", classpath.c_str(), 1);
  ::setenv("JDK_JAVA_OPTIONS", java_options.c_str(), 1);
  std::vector<char*> argv;
  for (auto& word : command) argv.push_back(word.data());
  argv.push_back(nullptr);
  ::execvp(argv[0], argv.data());
  std::cerr << "wrc spy: cannot run lcm-spy (install liblcm-bin: clients/wrc setup)\n";
  return 1;
}

const CommandRegistrar registrar{{"spy", "lcm-spy with the project's message types", run_spy}};

}  // namespace
}  // namespace wrc::cli
