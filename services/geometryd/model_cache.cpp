// SPDX-License-Identifier: Apache-2.0
#include "geometryd/model_cache.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "protocol/geometry/geometry_table_codec.hpp"
#include "protocol/geometry/spline_model_codec.hpp"
#include "protocol/geometry/spline_model_file.hpp"

namespace wrc::geometryd {

namespace fs = std::filesystem;

ModelCache::ModelCache(std::string dir) : dir_(std::move(dir)) {
  if (dir_.empty()) throw std::runtime_error("model cache: the directory name is empty");
  // Create each missing component ourselves so that every directory made here is 0700.
  fs::path partial;
  for (const fs::path& part : fs::path(dir_)) {
    partial /= part;
    std::error_code ec;
    if (fs::exists(partial, ec)) continue;
    if (!fs::create_directory(partial, ec) && ec)
      throw std::runtime_error("model cache: cannot create " + partial.string() + ": " + ec.message());
    fs::permissions(partial, fs::perms::owner_all, fs::perm_options::replace, ec);
    if (ec) throw std::runtime_error("model cache: cannot set mode 0700 on " + partial.string() + ": " + ec.message());
  }
  std::error_code ec;
  if (!fs::is_directory(dir_, ec)) throw std::runtime_error("model cache: " + dir_ + " is not a directory");
}

std::string ModelCache::path(const std::string& model_key) const {
  return (fs::path(dir_) / (model_key + kModelFileExtension)).string();
}

std::optional<spline_model_t> ModelCache::find(const std::string& model_key, std::string* why) const {
  why->clear();
  const std::string file = path(model_key);
  std::error_code ec;
  if (!fs::exists(file, ec)) return std::nullopt;
  try {
    spline_model_t full = protocol::read_model_file(file);
    if (full.model_key != model_key) {
      *why = file + " holds model_key " + full.model_key;
      return std::nullopt;
    }
    protocol::decode_model(full);
    return full;
  } catch (const std::exception& e) {
    *why = e.what();
    return std::nullopt;
  }
}

spline_model_t ModelCache::store(const spline_model_t& full) const { return protocol::write_model_file(full, path(full.model_key)); }

std::string ModelCache::table_path(const std::string& model_key, int wheel) const {
  return (fs::path(dir_) / (model_key + (wheel == geometry_table_t::LEFT ? ".left" : ".right") + kTableFileExtension))
      .string();
}

geometry_table_t ModelCache::store_table(const geometry_table_t& full) const {
  return protocol::write_table_file(full, table_path(full.model_key, full.wheel));
}

std::vector<geometry_table_t> ModelCache::find_tables(const std::string& model_key) const {
  std::vector<geometry_table_t> out;
  for (int wheel : {static_cast<int>(geometry_table_t::LEFT), static_cast<int>(geometry_table_t::RIGHT)}) {
    const std::string file = table_path(model_key, wheel);
    std::error_code ec;
    if (!fs::exists(file, ec)) continue;
    try {
      geometry_table_t full = protocol::read_table_file(file);
      if (full.model_key == model_key && full.wheel == wheel) out.push_back(protocol::table_reference(full, file));
    } catch (const std::exception&) {
      // an unusable table is not published; the next fit of this model rewrites it
    }
  }
  return out;
}

spline_model_t answer_message(const spline_model_t& full, const std::string& path) {
  if (!protocol::too_large_for_inline(full)) return full;
  return protocol::file_reference(full, path);
}

}  // namespace wrc::geometryd
