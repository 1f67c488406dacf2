// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Output files of the front end checked before any work starts: a command that writes FILE at
/// its end (`wrc run --summary/--history`, `wrc fit --report`, `wrc plot --out`) first makes sure
/// FILE can be written, so that a mistyped folder fails at once with one line, not after a run,
/// a fit or a plot.

#include <string>

namespace wrc::cli {

/// Checks that path can be written: an existing file is opened for writing (not truncated, not
/// changed), a new one is created and removed again (no file is left behind), so the folder must
/// exist and be writable. what names the path in the error, e.g. "--summary".
/// @throws UsageError "<what> <path>: <reason>" (e.g. "the folder /x does not exist",
/// "is a directory", "cannot be written: Permission denied").
void check_output_path(const std::string& path, const std::string& what);

}  // namespace wrc::cli
