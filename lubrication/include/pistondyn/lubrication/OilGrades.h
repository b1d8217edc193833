#pragma once
/// \file
/// Engine oils by SAE J300 viscosity grade.
///
/// SAE J300 fixes only ranges (e.g. 9.3 <= nu100 < 12.5 mm^2/s for the "30" grades) and no
/// 40 C value at all, so each grade here is one named commercial oil: kinematic viscosity
/// at 40 C and 100 C (ASTM D445), density (ASTM D4052) and pour point (ASTM D97) as
/// printed in its "typical properties" data sheet. The data sheets are ExxonMobil's
/// product pages as archived in github.com/khwsab/Documentum (commit 4b8395a); each number
/// and its page are listed in src/OilGrades.cpp. "Typical" values vary between batches
/// and markets by a few percent (the Singapore page of the 10W-40 oil prints 92 instead of
/// 96 mm^2/s at 40 C); use a user oil (Oil(OilSpec)) for a measured oil.
///
/// Valid temperature range of every grade: from 10 K above the data sheet's pour point
/// (the oil gels below it) to 200 C.

#include <string>
#include <string_view>

#include "pistondyn/lubrication/Oil.h"

namespace pistondyn::lubrication {

/// The SAE grades with data-sheet values (the oil each stands for).
enum class SaeGrade {
  k0W20,   ///< Mobil Super 3000 0W-20
  k0W30,   ///< Mobil 1 0W-30
  k5W30,   ///< Mobil 1 5W-30
  k5W40,   ///< Mobil Super 3000 X2 5W-40
  k10W40,  ///< Mobil Super 2000 X2 10W-40
  k15W40,  ///< Mobil Super 1000 X2 15W-40
};

/// The data-sheet specification of a grade (name says which oil).
OilSpec makeSaeGradeOilSpec(SaeGrade grade);

/// Oil(makeSaeGradeOilSpec(grade)).
Oil makeSaeGradeOil(SaeGrade grade);

/// "0W-20", "5W-30", ...
std::string toString(SaeGrade grade);

/// Parses "0W-20", "0w20", "SAE 5W-30" (case, spaces, "SAE" prefix and dash optional).
/// Throws std::invalid_argument naming the text when it is not one of the grades above.
SaeGrade parseSaeGrade(std::string_view text);

}  // namespace pistondyn::lubrication
