// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// One gnuplot run of `wrc plot`: a private temporary directory for the data files and the script,
/// the cairo terminal chosen by the output file's extension (.png: pngcairo, .svg: svg), gnuplot's
/// exit status checked and its stderr reported, the temporaries removed afterwards.

#include <fstream>
#include <string>

namespace wrc::cli::plot {

/// The picture asked for: output path, terminal and size in pixels.
struct ImageRequest {
  std::string path;      ///< output file (.png or .svg)
  std::string terminal;  ///< gnuplot terminal line without the size ("pngcairo ...", "svg ...")
  int width = 1200;      ///< [px]
  int height = 900;      ///< [px]
};

/// The image request for path; throws UsageError naming the file for an extension other than
/// .png or .svg, a path that cannot be written (cli/output_paths.hpp), or a size outside
/// [100, 10000] px.
ImageRequest image_request(const std::string& path, int width, int height);

/// A gnuplot string literal (double-quoted, backslashes and quotes escaped, newlines as \n).
std::string quoted(const std::string& text);

/// The full path of gnuplot found on PATH; throws std::runtime_error (one line, naming the
/// package) when it is not installed.
std::string find_gnuplot();

/// Temporary directory, data files and the run of one script.
class GnuplotJob {
 public:
  /// Creates the temporary directory; throws std::runtime_error when it cannot.
  GnuplotJob();
  ~GnuplotJob();
  GnuplotJob(const GnuplotJob&) = delete;
  GnuplotJob& operator=(const GnuplotJob&) = delete;

  /// Path of a data file named name in the temporary directory.
  std::string data_path(const std::string& name) const;
  /// Opens that file for writing (full precision); throws std::runtime_error when it cannot.
  std::ofstream open_data(const std::string& name) const;

  /// Runs script (the plotting commands) after the terminal and output lines of image, then moves
  /// the picture to image.path. Throws std::runtime_error with gnuplot's stderr when gnuplot fails
  /// or writes no picture.
  void render(const std::string& script, const ImageRequest& image) const;

 private:
  std::string directory_;
};

}  // namespace wrc::cli::plot
