// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A progress bar on stderr for long work (precomputation, runs): fraction done, elapsed and
/// remaining time. On a terminal it redraws one line; otherwise it prints a line per 10 %.

#include <chrono>
#include <string>

namespace wrc::cli {

class ProgressBar {
 public:
  explicit ProgressBar(std::string title);
  /// Shows done of total units (total 0: unknown) with the current stage.
  void update(long done, long total, const std::string& stage);
  /// Ends the bar's line (prints the elapsed time).
  void finish();

 private:
  std::string title_;
  std::chrono::steady_clock::time_point start_;
  bool terminal_;
  int last_decile_ = -1;
  bool open_ = false;
};

}  // namespace wrc::cli
