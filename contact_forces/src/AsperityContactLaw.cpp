#include "pistondyn/contact_forces/AsperityContactLaw.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "pistondyn/common/Validation.h"

namespace pistondyn::contact_forces {
namespace {

// A gap is usable unless it is NaN or −inf (+inf means "far apart").
inline bool isUsableGap(double gap_m) {
  return !std::isnan(gap_m) && gap_m != -std::numeric_limits<double>::infinity();
}

[[noreturn]] void throwBadGap(const AsperityContactLaw& law, const char* function,
                              const std::string& argument, double gap_m) {
  common::throwInvalidValue(std::string(law.name()) + "::" + function, argument, gap_m, "m",
                            "a number and not -inf");
}

// A finite gap whose pressure or slope is not finite: an overlap far beyond anything
// physical (the power of the penetration overflowed). Reported, never returned.
[[noreturn]] void throwOverflow(const AsperityContactLaw& law, const char* function,
                                const std::string& argument, double gap_m) {
  common::throwInvalidValue(std::string(law.name()) + "::" + function, argument, gap_m, "m",
                            "an overlap whose contact pressure and slope are finite (they overflow "
                            "the double range here; h/sigma = " +
                                common::formatNumber(gap_m / law.compositeSigma_m()) + ")");
}

inline bool isFinite(const PressureAndSlope& ps) {
  return std::isfinite(ps.pressure_Pa) && std::isfinite(ps.dPressure_dGap_PaPerM);
}

}  // namespace

void ContactField::resize(Eigen::Index rows, Eigen::Index cols) {
  pressure_Pa.resize(rows, cols);
  dPressure_dGap_PaPerM.resize(rows, cols);
  realAreaFraction.resize(rows, cols);
  filmRatio.resize(rows, cols);
  regime.resize(rows, cols);
}

double AsperityContactLaw::calcPressure(double gap_m) const {
  if (!isUsableGap(gap_m)) {
    throwBadGap(*this, "calcPressure", "gap_m", gap_m);
  }
  const double p = evalPressure(gap_m);
  if (!std::isfinite(p)) {
    throwOverflow(*this, "calcPressure", "gap_m", gap_m);
  }
  return p;
}

PressureAndSlope AsperityContactLaw::calcPressureAndSlope(double gap_m) const {
  if (!isUsableGap(gap_m)) {
    throwBadGap(*this, "calcPressureAndSlope", "gap_m", gap_m);
  }
  const PressureAndSlope ps = evalPressureAndSlope(gap_m);
  if (!isFinite(ps)) {
    throwOverflow(*this, "calcPressureAndSlope", "gap_m", gap_m);
  }
  return ps;
}

ContactNodeState AsperityContactLaw::calcNode(double gap_m) const {
  if (!isUsableGap(gap_m)) {
    throwBadGap(*this, "calcNode", "gap_m", gap_m);
  }
  const ContactNodeState node = evalNode(gap_m);
  if (!isFinite({node.pressure_Pa, node.dPressure_dGap_PaPerM})) {
    throwOverflow(*this, "calcNode", "gap_m", gap_m);
  }
  return node;
}

LubricationRegime AsperityContactLaw::classify(double gap_m) const {
  // Same domain as the pressure calls: −inf is as unusable here as there.
  if (!isUsableGap(gap_m)) {
    throwBadGap(*this, "classify", "gap_m", gap_m);
  }
  return classifyRegime(gap_m / compositeSigma_m());
}

void AsperityContactLaw::calcField(const Eigen::Ref<const Eigen::ArrayXXd>& gap_m,
                                   ContactField& out) const {
  // Check the whole field first so that a bad node leaves `out` untouched.
  const Eigen::Index rows = gap_m.rows();
  const Eigen::Index cols = gap_m.cols();
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      if (!isUsableGap(gap_m(i, j))) {
        throwBadGap(*this, "calcField",
                    "gap_m(" + std::to_string(i) + ", " + std::to_string(j) + ")", gap_m(i, j));
      }
    }
  }
  out.resize(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i) {
      const ContactNodeState node = evalNode(gap_m(i, j));
      if (!isFinite({node.pressure_Pa, node.dPressure_dGap_PaPerM})) {
        throwOverflow(*this, "calcField",
                      "gap_m(" + std::to_string(i) + ", " + std::to_string(j) + ")", gap_m(i, j));
      }
      out.pressure_Pa(i, j) = node.pressure_Pa;
      out.dPressure_dGap_PaPerM(i, j) = node.dPressure_dGap_PaPerM;
      out.realAreaFraction(i, j) = node.realAreaFraction;
      out.filmRatio(i, j) = node.filmRatio;
      out.regime(i, j) = node.regime;
    }
  }
}

ContactNodeState AsperityContactLaw::evalNode(double gap_m) const {
  ContactNodeState node;
  const PressureAndSlope ps = evalPressureAndSlope(gap_m);
  node.pressure_Pa = ps.pressure_Pa;
  node.dPressure_dGap_PaPerM = ps.dPressure_dGap_PaPerM;
  node.realAreaFraction = evalAreaFraction(gap_m);
  node.filmRatio = gap_m / compositeSigma_m();
  node.regime = classifyRegime(node.filmRatio);
  return node;
}

}  // namespace pistondyn::contact_forces
