#include "FileText.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace pistondyn::app {

std::string readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error(path + ": cannot be read");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace pistondyn::app
