// Compiled by CTest with -DNDEBUG on purpose: the build must stop at the guard in
// SimbodyBuildCheck.h (see tests/mbd_models/CMakeLists.txt).
#include "pistondyn/mbd_models/CrankTrain.h"
int main() {
  return 0;
}
