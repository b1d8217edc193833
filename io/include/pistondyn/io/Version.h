#pragma once
/// \file
/// The pistondyn version these libraries were built as (CMake project version).

#include <string>

namespace pistondyn::io {

/// "0.1.0"
std::string getVersion();

}  // namespace pistondyn::io
