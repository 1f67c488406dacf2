// SPDX-License-Identifier: Apache-2.0
#include "cli/progress_bar.hpp"

#include <unistd.h>

#include <cstdio>

namespace wrc::cli {

ProgressBar::ProgressBar(std::string title)
    : title_(std::move(title)), start_(std::chrono::steady_clock::now()), terminal_(isatty(STDERR_FILENO) != 0) {}

void ProgressBar::update(long done, long total, const std::string& stage) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0.0;
  const double remaining = fraction > 0.02 ? elapsed * (1.0 - fraction) / fraction : -1.0;
  char eta[32] = "?";
  if (remaining >= 0) std::snprintf(eta, sizeof eta, "%.1f s", remaining);
  if (terminal_) {
    const int width = 30, filled = static_cast<int>(fraction * width + 0.5);
    std::string bar(static_cast<size_t>(filled), '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r%s [%s] %3.0f %%  %.1f s, %s left  %-32.32s", title_.c_str(), bar.c_str(), 100 * fraction,
                 elapsed, eta, stage.c_str());
    open_ = true;
  } else {
    const int decile = static_cast<int>(fraction * 10);
    if (decile == last_decile_) return;
    last_decile_ = decile;
    std::fprintf(stderr, "%s: %3.0f %% after %.1f s (%s left): %s\n", title_.c_str(), 100 * fraction, elapsed, eta,
                 stage.c_str());
  }
  std::fflush(stderr);
}

void ProgressBar::finish() {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (open_) std::fputc('\n', stderr);
  std::fprintf(stderr, "%s: done in %.2f s\n", title_.c_str(), elapsed);
  open_ = false;
}

}  // namespace wrc::cli
