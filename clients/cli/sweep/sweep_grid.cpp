// SPDX-License-Identifier: Apache-2.0
#include "cli/sweep/sweep_grid.hpp"

#include <cctype>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/numerics/inclusive_range.hpp"
#include "core/numerics/number_text.hpp"

namespace wrc::sweep {
namespace {

// value rounded to 12 significant digits (a range's steps add rounding errors of about 1e-16).
double rounded(double value) {
  const double out = *finite_number(number_text(value, 12));
  return out == 0.0 ? 0.0 : out;  // no "-0"
}

// "a:b:c" with three numbers, split; false for anything else (a single value of its own).
bool split_range(const std::string& item, double& from, double& to, double& step) {
  const auto first = item.find(':');
  if (first == std::string::npos) return false;
  const auto second = item.find(':', first + 1);
  if (second == std::string::npos || item.find(':', second + 1) != std::string::npos) return false;
  const std::optional<double> a = finite_number(item.substr(0, first));
  const std::optional<double> b = finite_number(item.substr(first + 1, second - first - 1));
  const std::optional<double> c = finite_number(item.substr(second + 1));
  if (!a || !b || !c) return false;
  from = *a;
  to = *b;
  step = *c;
  return true;
}

}  // namespace

std::vector<std::string> range_values(double from, double to, double step) {
  const long count = inclusive_range_count(from, to, step);
  if (static_cast<std::size_t>(count) > kMaxAxisValues)
    throw std::invalid_argument("range " + shortest_number_text(from) + ":" + shortest_number_text(to) + ":" + shortest_number_text(step) +
                                ": more than " + std::to_string(kMaxAxisValues) + " values");
  std::vector<std::string> values;
  for (const double v : inclusive_range(from, to, step)) values.push_back(shortest_number_text(rounded(v)));
  return values;
}

GridAxis parse_grid_axis(const std::string& text) {
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0)
    throw std::invalid_argument("grid '" + text + "' is not KEY=VALUES (e.g. speed=10:40:10 or friction=0.2,0.3)");
  GridAxis axis;
  for (char c : text.substr(0, equals)) {
    if (c == '-') c = '_';
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
      throw std::invalid_argument("grid '" + text + "': the key may have letters, digits, '_' and '-' only");
    axis.key += c;
  }
  const std::string list = text.substr(equals + 1);
  if (list.empty()) throw std::invalid_argument("grid '" + text + "': no values after '='");
  std::stringstream items(list);
  std::string item;
  std::set<std::string> seen;
  auto add = [&](const std::string& value) {
    if (!seen.insert(value).second)
      throw std::invalid_argument("grid '" + text + "': the value " + value + " is given twice");
    axis.values.push_back(value);
    if (axis.values.size() > kMaxAxisValues)
      throw std::invalid_argument("grid '" + text + "': more than " + std::to_string(kMaxAxisValues) + " values");
  };
  while (std::getline(items, item, ',')) {
    if (item.empty()) throw std::invalid_argument("grid '" + text + "': an empty value (two commas, or one at an end)");
    double from = 0, to = 0, step = 0;
    if (split_range(item, from, to, step)) {
      try {
        for (const std::string& v : range_values(from, to, step)) add(v);
      } catch (const std::invalid_argument& e) {
        if (std::string(e.what()).rfind("grid ", 0) == 0) throw;
        throw std::invalid_argument("grid '" + text + "': " + e.what());
      }
    } else {
      add(item);
    }
  }
  if (list.back() == ',') throw std::invalid_argument("grid '" + text + "': an empty value (two commas, or one at an end)");
  return axis;
}

Grid::Grid(std::vector<GridAxis> axes) : axes_(std::move(axes)) {
  if (axes_.empty()) throw std::invalid_argument("a sweep needs at least one --grid KEY=VALUES");
  std::set<std::string> keys;
  double count = 1.0;
  for (const GridAxis& a : axes_) {
    if (!keys.insert(a.key).second) throw std::invalid_argument("grid key " + a.key + " is given twice");
    if (a.values.empty()) throw std::invalid_argument("grid key " + a.key + " has no values");
    count *= static_cast<double>(a.values.size());
  }
  if (count > static_cast<double>(kMaxGridPoints)) {
    throw std::invalid_argument("the grid has " + number_text(count, 15) + " runs, more than the limit of " +
                                std::to_string(kMaxGridPoints));
  }
  size_ = static_cast<std::size_t>(count);
}

std::vector<std::string> Grid::point(std::size_t index) const {
  if (index >= size_)
    throw std::out_of_range("grid point " + std::to_string(index) + " of a grid of " + std::to_string(size_) + " runs");
  std::vector<std::string> values(axes_.size());
  for (std::size_t k = axes_.size(); k-- > 0;) {
    const std::size_t n = axes_[k].values.size();
    values[k] = axes_[k].values[index % n];
    index /= n;
  }
  return values;
}

std::size_t Grid::index_of(const std::vector<std::string>& values) const {
  if (values.size() != axes_.size()) return size_;
  std::size_t index = 0;
  for (std::size_t k = 0; k < axes_.size(); ++k) {
    const auto& v = axes_[k].values;
    std::size_t i = 0;
    while (i < v.size() && v[i] != values[k]) ++i;
    if (i == v.size()) return size_;
    index = index * v.size() + i;
  }
  return index;
}

}  // namespace wrc::sweep
