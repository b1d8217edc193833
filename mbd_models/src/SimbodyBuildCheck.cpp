#include "pistondyn/mbd_models/SimbodyBuildCheck.h"

namespace pistondyn::mbd {

bool libraryBuiltWithNDEBUG() {
#ifdef NDEBUG
  return true;
#else
  return false;
#endif
}

}  // namespace pistondyn::mbd
