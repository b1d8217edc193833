#pragma once
// The whole content of a file as bytes (not installed): what the sweep's fingerprint
// hashes (Sha256.cpp), what a sweep reads back of its case folders (SweepRun.cpp) and what
// a result folder's reader parses (ResultFolder.cpp). One reader, so they agree on what
// "readable" means: a regular file that opens and reads to its end without an I/O error
// (a folder opens as a stream too, and would read as an empty file).

#include <optional>
#include <string>

namespace pistondyn::io::detail {

// The file's bytes; nullopt if `path` is not a regular file or cannot be read.
std::optional<std::string> readFileBytes(const std::string& path);

}  // namespace pistondyn::io::detail
