// SPDX-License-Identifier: Apache-2.0
#include "core/profile/profile_file.hpp"

#include "core/profile/miniprof_reader.hpp"
#include "core/profile/profile_text.hpp"
#include "core/profile/simpack_reader.hpp"
#include "core/profile/text_profile_reader.hpp"

namespace wrc {

ProfilePtr read_profile_file(const std::string& path, ProfileSide side,
                             const ProfileFileOptions& options) {
  const std::string name = profile_text::lower(profile_text::base_name(path));
  const auto dot = name.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : name.substr(dot);
  if (ext == ".prw" || ext == ".prr") return read_simpack_profile(path, side, options);
  if (ext == ".ban") return read_miniprof_profile(path, side, options);
  return read_text_profile(path, side, options);
}

}  // namespace wrc
