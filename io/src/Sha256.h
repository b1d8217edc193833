#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as lower-case hex: the fingerprint of a sweep and
// of the files its cases read. A plain implementation, so the project needs no crypto
// library; the hex of a file's content equals what `sha256sum FILE` prints. Not installed.

#include <optional>
#include <string>

namespace pistondyn::io::detail {

// 64 hex digits.
std::string sha256Hex(const std::string& bytes);
// Of a file's content; nullopt if it cannot be read.
std::optional<std::string> sha256HexOfFile(const std::string& path);

}  // namespace pistondyn::io::detail
