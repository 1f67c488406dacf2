// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// SHA-256 (FIPS 180-4) by OpenSSL's EVP interface: the one digest wrc uses for geometry keys and
/// hashes of model data (tables, spline coefficients), so that every process and every tool
/// (`sha256sum`) computes the same digest of the same bytes.

#include <cstddef>
#include <string>
#include <vector>

namespace wrc {

/// SHA-256 of size bytes at data: 64 lowercase hex digits.
/// @throws std::runtime_error when OpenSSL fails (the message says which call).
std::string sha256_hex(const void* data, std::size_t size);

/// SHA-256 of the bytes of text: 64 lowercase hex digits.
/// @throws std::runtime_error when OpenSSL fails.
std::string sha256_hex(const std::string& text);

/// SHA-256 of values, each as the 8 bytes of its IEEE 754 binary64 bits, least significant byte
/// first (little-endian) on every host: the hash of model data (tables, spline coefficients) that
/// two machines compare. 64 lowercase hex digits. @throws std::runtime_error when OpenSSL fails.
std::string sha256_hex_of_doubles(const std::vector<double>& values);

}  // namespace wrc
