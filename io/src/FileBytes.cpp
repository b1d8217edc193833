#include "FileBytes.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace pistondyn::io::detail {

std::optional<std::string> readFileBytes(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return std::nullopt;
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad())
    return std::nullopt;
  return ss.str();
}

}  // namespace pistondyn::io::detail
