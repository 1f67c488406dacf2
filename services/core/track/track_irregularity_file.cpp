// SPDX-License-Identifier: Apache-2.0
#include "core/track/track_irregularity_file.hpp"

#include <array>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/numerics/number_text.hpp"
#include "core/numerics/regular_file.hpp"
#include "core/numerics/trim.hpp"

namespace wrc {
namespace {

constexpr int kDistanceColumn = -1;  // the s column; channels are 0..3

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// One column of the header: what it holds and the factor to metres.
struct Column {
  int what = kDistanceColumn;
  double to_metres = 1.0;
  std::string name;
};

std::vector<Column> header_columns(const std::string& line, const std::string& where) {
  std::vector<Column> columns;
  std::array<bool, kIrregularityChannelCount> seen_channel{};
  bool seen_s = false;
  for (const std::string& cell : cells_of(line)) {
    const std::size_t open = cell.find('[');
    const std::size_t close = cell.find(']');
    if (open == std::string::npos || close == std::string::npos || close < open || close + 1 != cell.size())
      throw std::invalid_argument(where + "header column '" + cell +
                                  "' has no unit: write it as 'name [unit]', e.g. 'gauge [mm]'");
    Column c;
    c.name = trim(cell.substr(0, open));
    const std::string unit = trim(cell.substr(open + 1, close - open - 1));
    if (c.name == "s") {
      if (seen_s) throw std::invalid_argument(where + "column 's' appears twice");
      seen_s = true;
      if (unit != "m") throw std::invalid_argument(where + "column 's': unit '" + unit + "' is not m");
      columns.push_back(c);
      continue;
    }
    bool known = false;
    for (IrregularityChannel channel : kIrregularityChannels) {
      if (c.name != irregularity_channel_name(channel)) continue;
      const std::size_t k = static_cast<std::size_t>(channel);
      if (seen_channel[k]) throw std::invalid_argument(where + "column '" + c.name + "' appears twice");
      seen_channel[k] = true;
      c.what = static_cast<int>(k);
      known = true;
    }
    if (!known)
      throw std::invalid_argument(where + "unknown column '" + c.name +
                                  "' (the columns are s, alignment, vertical_level, cross_level, gauge)");
    if (unit == "m") {
      c.to_metres = 1.0;
    } else if (unit == "mm") {
      c.to_metres = 1e-3;
    } else {
      throw std::invalid_argument(where + "column '" + c.name + "': unit '" + unit + "' is neither m nor mm");
    }
    columns.push_back(c);
  }
  if (!seen_s) throw std::invalid_argument(where + "no column 's [m]'");
  for (IrregularityChannel channel : kIrregularityChannels)
    if (!seen_channel[static_cast<std::size_t>(channel)])
      throw std::invalid_argument(where + "no column '" + irregularity_channel_name(channel) + " [m]' or '[mm]'");
  return columns;
}

}  // namespace

TrackIrregularity parse_track_irregularity(const std::string& csv_text, const std::string& source) {
  std::istringstream in(csv_text);
  std::string line;
  int line_number = 0;
  std::optional<std::vector<Column>> columns;
  std::vector<double> distances;
  std::array<std::vector<double>, kIrregularityChannelCount> channels;
  std::vector<int> sample_lines;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string text = trim(line);
    if (text.empty() || text[0] == '#') continue;
    const std::string where = source + ":" + std::to_string(line_number) + ": ";
    if (!columns) {
      columns = header_columns(text, where);
      continue;
    }
    const std::vector<std::string> cells = cells_of(text);
    if (cells.size() != columns->size())
      throw std::invalid_argument(where + std::to_string(cells.size()) + " cells, the header has " +
                                  std::to_string(columns->size()));
    if (distances.size() >= kMaxIrregularitySamples)
      throw std::invalid_argument(where + "more than " + std::to_string(kMaxIrregularitySamples) + " samples");
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const Column& c = (*columns)[k];
      const double v = parse_finite_number(cells[k], where + c.name);
      if (c.what == kDistanceColumn) {
        distances.push_back(v);
      } else {
        channels[static_cast<std::size_t>(c.what)].push_back(v * c.to_metres);
      }
    }
    sample_lines.push_back(line_number);
  }
  if (!columns) throw std::invalid_argument(source + ": no header line (s [m],alignment [mm],...)");
  try {
    return TrackIrregularity(std::move(distances), std::move(channels));
  } catch (const IrregularitySampleError& e) {
    // Name the line of the sample the library names.
    if (e.sample() < sample_lines.size())
      throw std::invalid_argument(source + ":" + std::to_string(sample_lines[e.sample()]) + ": " + e.what());
    throw std::invalid_argument(source + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
}

TrackIrregularity read_track_irregularity_file(const std::string& path) {
  return parse_track_irregularity(read_regular_file(path, kMaxIrregularityFileBytes), path);
}

std::string track_irregularity_text(const TrackIrregularity& irregularity, const std::string& comment) {
  std::ostringstream out;
  if (!comment.empty()) {
    std::istringstream lines(comment);
    std::string line;
    while (std::getline(lines, line)) out << "# " << line << "\n";
  }
  out << "s [m]";
  for (IrregularityChannel channel : kIrregularityChannels) out << "," << irregularity_channel_name(channel) << " [m]";
  out << "\n";
  const std::vector<double>& s = irregularity.distances();
  for (std::size_t i = 0; i < s.size(); ++i) {
    out << exact_number_text(s[i]);
    for (IrregularityChannel channel : kIrregularityChannels)
      out << "," << exact_number_text(irregularity.samples(channel)[i]);
    out << "\n";
  }
  return out.str();
}

}  // namespace wrc
