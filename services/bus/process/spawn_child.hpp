// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Starting a child process that cannot outlive its parent (services started by `wrc query`, by
/// multi-process tests and by benchmarks).

#include <string>
#include <sys/types.h>
#include <vector>

namespace wrc::bus {

/// Forks and executes words[0] with arguments words[1..]. The child gets death_signal when the
/// parent dies (PR_SET_PDEATHSIG; it exits at once if the parent is already gone), and with a
/// non-empty log_path its standard output and error go to that file (truncated). Returns the
/// child's pid, or -1 when fork fails (errno set). A failed exec ends the child with status 127.
pid_t spawn_tied_child(const std::vector<std::string>& words, int death_signal, const std::string& log_path = "");

}  // namespace wrc::bus
