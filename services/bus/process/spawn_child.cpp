// SPDX-License-Identifier: Apache-2.0
#include "bus/process/spawn_child.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <unistd.h>

namespace wrc::bus {

pid_t spawn_tied_child(const std::vector<std::string>& words, int death_signal, const std::string& log_path) {
  std::vector<std::string> copy = words;
  std::vector<char*> argv;
  for (auto& w : copy) argv.push_back(w.data());
  argv.push_back(nullptr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  ::prctl(PR_SET_PDEATHSIG, death_signal);
  if (::getppid() != parent) ::_exit(1);  // the parent is already gone
  if (!log_path.empty()) {
    const int fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
  }
  ::execv(argv[0], argv.data());
  ::_exit(127);
}

}  // namespace wrc::bus
