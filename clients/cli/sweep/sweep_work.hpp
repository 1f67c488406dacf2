// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A sweep's work directory (default: the CSV's path with ".work"), on a filesystem every run can
/// reach (a cluster's shared one for --slurm): sweep.json (the definition, sweep_definition.hpp),
/// rows/<point>.json (one file per finished or failed run, written by the run's own process and
/// gathered into the CSV by the sweep), logs/ (a run's output when it failed; Slurm's task logs)
/// and slurm/ (job scripts and their lists of points).

#include <cstddef>
#include <map>
#include <optional>
#include <string>

#include "cli/sweep/sweep_definition.hpp"
#include "cli/sweep/sweep_table.hpp"

namespace wrc::cli {

class SweepWork {
 public:
  explicit SweepWork(std::string directory);

  const std::string& directory() const { return directory_; }
  std::string definition_path() const { return directory_ + "/sweep.json"; }
  std::string row_path(std::size_t point) const;
  std::string log_path(std::size_t point) const;
  std::string slurm_directory() const { return directory_ + "/slurm"; }
  std::string logs_directory() const { return directory_ + "/logs"; }

  /// Creates the directory with the definition, or checks that the definition it holds is this one.
  /// @throws UsageError when it holds another sweep's, naming the directory.
  void prepare(const SweepDefinition& definition) const;
  /// The definition it holds. @throws UsageError when there is none.
  SweepDefinition definition() const;

  /// Writes a run's row (to a temporary file renamed into place: a reader never sees half of it).
  void write_row(const sweep::SweepRow& row, const sweep::Grid& grid) const;
  /// The row of point, when its file is there. @throws std::invalid_argument when the file is not
  /// a row of this grid's point (values or number of results differ).
  std::optional<sweep::SweepRow> read_row(std::size_t point, const sweep::SweepLayout& layout) const;
  /// Adds the rows of every point not in rows whose file is there; returns how many.
  std::size_t gather(const sweep::SweepLayout& layout, std::map<std::size_t, sweep::SweepRow>& rows) const;
  /// Removes the row file of point (a failed run to be run again).
  void forget(std::size_t point) const;

 private:
  std::string directory_;
};

}  // namespace wrc::cli
