// SPDX-License-Identifier: Apache-2.0
#pragma once
// A child process started by a multi-process test: it dies with the test (PR_SET_PDEATHSIG),
// can be signalled and waited for with a deadline, and is killed and reaped on destruction.
#include <sys/types.h>

#include <string>
#include <vector>

namespace wrc::bus::test {

class ChildProcess {
 public:
  /// Starts path with args; stderr (and stdout) go to log_path when not empty.
  ChildProcess(const std::string& path, const std::vector<std::string>& args,
               const std::string& log_path = "");
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  /// Sends sig to the child.
  void signal(int sig) const;
  /// Waits up to timeout [s] for the child to end; returns true and sets status when it did.
  bool wait(double timeout, int* status = nullptr);
  /// True while the child has not been reaped.
  bool running() const { return pid_ > 0; }

 private:
  pid_t pid_ = -1;
};

/// True when process pid no longer exists or is a zombie.
bool process_gone(pid_t pid);

/// Reads a whole text file (empty when missing).
std::string read_text(const std::string& path);

/// Runs a shell command and returns its standard output; its exit status (as pclose() gives it)
/// goes to *status.
std::string run_command(const std::string& command, int* status);

}  // namespace wrc::bus::test
