// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The shared bus key: 32 random bytes under which every wrc message is authenticated
/// (bus/auth/message_auth.hpp). It lives in a file only its owner may read or write (mode 0600), as
/// 64 hex digits on one line, so that it can be copied to other machines of the same bus.
///
/// Where the file is, first match wins: the `--bus-key FILE` option of a service or command,
/// `$WRC_BUS_KEY`, `$XDG_CONFIG_HOME/wrc/bus.key`, `~/.config/wrc/bus.key`.

#include <array>
#include <cstdint>
#include <string>

namespace wrc::bus {

/// The key's bytes.
struct BusKey {
  static constexpr std::size_t kBytes = 32;  ///< [B] 256 bits, the HMAC-SHA-256 block of security
  std::array<std::uint8_t, kBytes> bytes{};
};

/// The file to use: `option` when not empty, else $WRC_BUS_KEY, else the per-user default above.
/// Throws std::runtime_error when none can be named (no HOME and no XDG_CONFIG_HOME).
std::string bus_key_path(const std::string& option = "");

/// Reads the key at path. Throws std::runtime_error naming the file and what is wrong: missing
/// (with how to get one), not a regular file, owned by another user, readable or writable by
/// group or others (with the chmod to fix it), or not exactly 64 hex digits.
BusKey read_bus_key(const std::string& path);

/// Reads the key at path, or creates it (fresh random bytes from OpenSSL's generator, the parent
/// directory made 0700 if missing, the file 0600, created exclusively so that two launchers
/// starting at once agree on one key). *created tells which happened.
BusKey read_or_create_bus_key(const std::string& path, bool* created = nullptr);

}  // namespace wrc::bus
