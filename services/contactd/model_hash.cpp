#include "contactd/model_hash.hpp"

#include <cstdint>
#include <cstring>
#include <vector>

#include "core/identity/sha256.hpp"
#include "core/models/interpolated_model.hpp"
#include "core/models/spline_model.hpp"

namespace wrc::contactd {
namespace {

// Appends value as 8 little-endian bytes.
void put(std::vector<unsigned char>& out, double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<unsigned char>(bits >> (8 * i)));
}

std::string table_hash(const ContactPointTable& table) {
  std::vector<unsigned char> data;
  for (double v : table.data()) put(data, v);
  return sha256_hex(data.data(), data.size());
}

}  // namespace

std::string model_hash(const ContactModel& model) {
  if (const auto* interp = dynamic_cast<const InterpolatedModel*>(&model)) return table_hash(interp->table());
  if (const auto* spline = dynamic_cast<const SplineModel*>(&model)) return spline->splines().data_hash();
  return "";
}

}  // namespace wrc::contactd
