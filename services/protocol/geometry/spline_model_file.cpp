// SPDX-License-Identifier: Apache-2.0
#include "protocol/geometry/spline_model_file.hpp"

#include <stdexcept>
#include <vector>

#include "protocol/geometry/message_file.hpp"

namespace wrc::protocol {
namespace {

constexpr const char* kModelFile = "spline model file";

// The reference to the file holding bytes (full without its coefficients, with the file fields).
spline_model_t model_reference(const spline_model_t& full, const std::string& path, const std::vector<char>& bytes) {
  spline_model_t reference = full;
  for (spline_wheel_t& w : reference.wheels) {
    w.num_coefficients = 0;
    w.coefficients.assign(static_cast<size_t>(w.num_functions), std::vector<double>());
  }
  set_file_fields(reference, path, bytes);
  return reference;
}

}  // namespace

spline_model_t write_model_file(const spline_model_t& message, const std::string& path) {
  return model_reference(message, path, write_message_file(message, path, kModelFile));
}

spline_model_t file_reference(const spline_model_t& full, const std::string& path) {
  return model_reference(full, path, read_message_file_bytes(path, kModelFile));
}

spline_model_t read_model_file(const std::string& path) {
  return decode_bytes<spline_model_t>(read_message_file_bytes(path, kModelFile), path, kModelFile);
}

spline_model_t resolve_model(const spline_model_t& reference) {
  if (reference.file_path.empty()) return reference;
  return model_from_file_bytes(reference, checked_file(reference, kModelFile), reference.file_path);
}

spline_model_t model_from_file_bytes(const spline_model_t& reference, const std::vector<char>& bytes,
                                     const std::string& where) {
  spline_model_t full = decode_bytes<spline_model_t>(bytes, where, kModelFile);
  if (full.model_key != reference.model_key || full.model_hash != reference.model_hash)
    throw std::runtime_error(std::string(kModelFile) + " " + where +
                             " holds another model (model_key or model_hash differ)");
  full.header = reference.header;
  full.request_id = reference.request_id;
  return full;
}
}  // namespace wrc::protocol
