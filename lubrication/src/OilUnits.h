#pragma once
// Internal: unit conversions shared by Oil.cpp and OilGrades.cpp. Not installed.

namespace pistondyn::lubrication::detail {

constexpr double kM2psPerCSt = 1e-6;  // 1 cSt = 1 mm^2/s = 1e-6 m^2/s

}  // namespace pistondyn::lubrication::detail
