#include "pistondyn/io/Version.h"

#ifndef PISTONDYN_VERSION
#error "PISTONDYN_VERSION must be defined by the build"
#endif

namespace pistondyn::io {

std::string getVersion() {
  return PISTONDYN_VERSION;
}

}  // namespace pistondyn::io
