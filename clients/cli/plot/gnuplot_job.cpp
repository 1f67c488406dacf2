// SPDX-License-Identifier: Apache-2.0
#include "cli/plot/gnuplot_job.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "cli/options.hpp"
#include "cli/output_paths.hpp"

namespace wrc::cli::plot {
namespace fs = std::filesystem;

namespace {

std::string lowercase_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The first lines of gnuplot's stderr joined into one line.
std::string one_line(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
    if (out.size() > 400) return out + "...";
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// A POSIX shell word (single-quoted).
std::string quoted_for_shell(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

}  // namespace

ImageRequest image_request(const std::string& path, int width, int height) {
  if (path.empty()) throw UsageError("--out: empty file name");
  if (width < 100 || width > 10000) throw UsageError("--width " + std::to_string(width) + " is outside [100, 10000] px");
  if (height < 100 || height > 10000)
    throw UsageError("--height " + std::to_string(height) + " is outside [100, 10000] px");
  const std::string ext = lowercase_extension(path);
  ImageRequest image;
  image.path = path;
  image.width = width;
  image.height = height;
  if (ext == ".png") image.terminal = "pngcairo noenhanced font 'Sans,11' linewidth 1.5";
  else if (ext == ".svg") image.terminal = "svg noenhanced font 'Sans,11' linewidth 1.5 background '#ffffff'";
  else throw UsageError("--out: '" + path + "' must end in .png or .svg");
  check_output_path(path, "--out");  // before the computation and gnuplot, not after them
  return image;
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\\' || c == '"') out += std::string("\\") + c;
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out + "\"";
}

std::string find_gnuplot() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / "gnuplot";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  throw std::runtime_error("gnuplot is not installed (not on PATH): install Debian's gnuplot-nox "
                           "(clients/lib/setup.sh installs it)");
}

GnuplotJob::GnuplotJob() {
  std::string pattern = (fs::temp_directory_path() / "wrc-plot-XXXXXX").string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (!::mkdtemp(buffer.data())) throw std::runtime_error("cannot create a temporary directory for the plot data");
  directory_ = buffer.data();
}

GnuplotJob::~GnuplotJob() {
  std::error_code ignored;
  fs::remove_all(directory_, ignored);
}

std::string GnuplotJob::data_path(const std::string& name) const { return (fs::path(directory_) / name).string(); }

std::ofstream GnuplotJob::open_data(const std::string& name) const {
  std::ofstream out(data_path(name));
  if (!out) throw std::runtime_error("cannot write the plot data file " + name);
  out.precision(std::numeric_limits<double>::max_digits10);
  return out;
}

void GnuplotJob::render(const std::string& script, const ImageRequest& image) const {
  const std::string gnuplot = find_gnuplot();
  const fs::path picture = fs::path(directory_) / ("picture" + lowercase_extension(image.path));
  const fs::path script_path = fs::path(directory_) / "plot.gp";
  {
    std::ofstream out(script_path);
    out << "set encoding utf8\n"
        << "set terminal " << image.terminal << " size " << image.width << "," << image.height << "\n"
        << "set output " << quoted(picture.string()) << "\n"
        << script << "\nunset output\n";
    if (!out) throw std::runtime_error("cannot write the gnuplot script");
  }
  const fs::path errors = fs::path(directory_) / "gnuplot.stderr";
  const std::string command =
      quoted_for_shell(gnuplot) + " " + quoted_for_shell(script_path.string()) + " 2>" + quoted_for_shell(errors.string());
  const int status = std::system(command.c_str());
  const std::string stderr_text = read_text(errors);
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error("gnuplot failed (exit status " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + "): " + one_line(stderr_text));
  }
  if (!stderr_text.empty()) std::cerr << "gnuplot: " << one_line(stderr_text) << "\n";
  std::error_code error;
  if (!fs::exists(picture, error) || fs::file_size(picture, error) == 0)
    throw std::runtime_error("gnuplot wrote no picture: " + one_line(stderr_text));
  fs::copy_file(picture, image.path, fs::copy_options::overwrite_existing, error);
  if (error) throw std::runtime_error("cannot write '" + image.path + "': " + error.message());
}

}  // namespace wrc::cli::plot
