#pragma once
// Reading a whole file, for the commands and the pages they write.

#include <string>

namespace pistondyn::app {

// A whole file's bytes; throws std::runtime_error "<path>: cannot be read".
std::string readWholeFile(const std::string& path);

}  // namespace pistondyn::app
