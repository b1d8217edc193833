#include "pistondyn/contact_forces/LubricationRegime.h"

#include <cmath>
#include <stdexcept>

namespace pistondyn::contact_forces {

LubricationRegime classifyRegime(double filmRatio) {
  if (std::isnan(filmRatio)) {
    throw std::invalid_argument("classifyRegime: filmRatio = nan must be a number");
  }
  if (filmRatio > kMixedRegimeUpperFilmRatio) {
    return LubricationRegime::Hydrodynamic;
  }
  if (filmRatio > kBoundaryRegimeUpperFilmRatio) {
    return LubricationRegime::Mixed;
  }
  return LubricationRegime::Boundary;
}

const char* toString(LubricationRegime regime) {
  switch (regime) {
    case LubricationRegime::Hydrodynamic:
      return "hydrodynamic";
    case LubricationRegime::Mixed:
      return "mixed";
    case LubricationRegime::Boundary:
      return "boundary";
  }
  return "unknown";
}

}  // namespace pistondyn::contact_forces
