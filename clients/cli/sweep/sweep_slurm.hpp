// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A sweep on an existing Slurm cluster (`wrc sweep --slurm`): one job array whose task k runs the
/// k-th pending grid point with the same program (`wrc sweep --run-point I --work-dir DIR`, from
/// the same checkout or install, which every node must reach at the same path, as the work
/// directory), each task writing its row into the work directory; the sweep follows the rows as
/// they come and gathers them into the same CSV as a local sweep. Not a scheduler: sbatch, squeue
/// and the cluster's accounts, partitions and limits do the rest.

#include <cstddef>
#include <string>
#include <vector>

#include "cli/sweep/sweep_work.hpp"

namespace wrc::cli {

struct SlurmSubmission {
  std::string partition;                 ///< --partition, "" for the cluster's default
  std::string time;                      ///< --time per task, "" for the partition's default
  std::vector<std::string> sbatch_args;  ///< further sbatch options, passed as given
  int array_limit = 0;                   ///< most tasks running at once (%N), 0 for no limit
};

/// Writes the job script and the list of points into work's slurm/ and submits it with sbatch.
/// Returns the job id. @throws std::runtime_error with sbatch's output when it fails.
std::string submit_to_slurm(const SweepWork& work, const std::vector<std::size_t>& points,
                            const SlurmSubmission& submission);

/// Whether job still has tasks pending or running (squeue); false once Slurm no longer knows it.
/// @throws std::runtime_error when squeue fails otherwise.
bool slurm_job_active(const std::string& job);

}  // namespace wrc::cli
