// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A sweep on this machine: each pending grid point run as a process of its own
/// (`wrc sweep --run-point I --work-dir DIR`, what a Slurm task runs too), at most `jobs` at once,
/// each in its own process group with its output in the work directory's logs; a row reported as
/// each ends, a progress bar of runs done and failed with the time left. Ctrl-C (SIGINT) or
/// SIGTERM stops the running ones and returns: the rows so far are kept, a rerun resumes.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cli/sweep/sweep_work.hpp"

namespace wrc::cli {

/// This program's own path (/proc/self/exe), what runs the points.
std::string own_executable();

/// The `wrc sweep` arguments that run a point of work in a process of its own; point: its number,
/// or a shell variable's expansion in a job script.
std::vector<std::string> run_point_arguments(const SweepWork& work, const std::string& point);

/// Runs points, at most jobs at once, calling on_row with each row as its process ends (a process
/// that ends without writing its row is a failed row naming its exit and its log). Returns false
/// when interrupted (the running points are stopped and give no row).
bool run_points_locally(const SweepWork& work, const sweep::SweepLayout& layout, const std::vector<std::size_t>& points,
                        int jobs, const std::function<void(const sweep::SweepRow&)>& on_row);

}  // namespace wrc::cli
