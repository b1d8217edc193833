// Engine oils by SAE grade: one named commercial oil per grade, numbers from its
// "typical properties" data sheet.
//
// Source of every number: ExxonMobil product pages ("Properties" tab) as archived in the
// public repository github.com/khwsab/Documentum, commit 4b8395a (files named below,
// relative to the repository root). Kinematic viscosities are ASTM D445, densities
// ASTM D4052, pour points ASTM D97. The printed viscosity index (ASTM D2270) and HTHS
// (ASTM D4683) are not used here; the tests use them as independent checks of these
// numbers.

#include "pistondyn/lubrication/OilGrades.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

#include "OilUnits.h"

namespace pistondyn::lubrication {

namespace {

using detail::kM2psPerCSt;
// Density of water at 60 F (15.56 C), to turn a 60/60 F specific gravity into a density.
constexpr double kWaterDensityAt60F_kgpm3 = 999.01;
// Walther data points of all data sheets.
constexpr double kT40_degC = 40.0;
constexpr double kT100_degC = 100.0;
// The valid range starts this far above the pour point: below the pour point the oil
// gels and has no Newtonian viscosity; near it, wax structure already dominates.
constexpr double kMarginAbovePourPoint_K = 10.0;
constexpr double kMaxTemperature_degC = 200.0;

OilSpec sheet(const char* name, double nu40_cSt, double nu100_cSt, double density_kgpm3,
              double densityReference_degC, double pourPoint_degC) {
  OilSpec s;
  s.name = name;
  s.temperature1_degC = kT40_degC;
  s.kinematicViscosity1_m2ps = nu40_cSt * kM2psPerCSt;
  s.temperature2_degC = kT100_degC;
  s.kinematicViscosity2_m2ps = nu100_cSt * kM2psPerCSt;
  s.density_kgpm3 = density_kgpm3;
  s.densityReferenceTemperature_degC = densityReference_degC;
  s.minTemperature_degC = pourPoint_degC + kMarginAbovePourPoint_K;
  s.maxTemperature_degC = kMaxTemperature_degC;
  return s;
}

}  // namespace

OilSpec makeSaeGradeOilSpec(SaeGrade grade) {
  switch (grade) {
    case SaeGrade::k0W20:
      // Mobil Super 3000 0W-20: AP-English-LCW/carengineoils_au_products_mobil-super-3000-
      // 0W-20.aspx (identical on UK-English-LCW/carengineoils_products_mobil-super-0w-20
      // .aspx and Canada-English-LCW/carengineoils_products_mobil-super_3000-0w20.aspx):
      // nu40 = 44.9, nu100 = 8.6 mm^2/s, specific gravity 0.848 (API gravity 35.4, which
      // gives 141.5 / (131.5 + 35.4) = 0.848), pour point -42 C.
      return sheet("SAE 0W-20 (Mobil Super 3000 0W-20 data sheet)", 44.9, 8.6,
                   0.848 * kWaterDensityAt60F_kgpm3, 15.56, -42.0);
    case SaeGrade::k0W30:
      // Mobil 1 0W-30: AP-English-LCW/carengineoils_au_products_mobil-1-0W-30.aspx:
      // nu40 = 62.9, nu100 = 10.9 mm^2/s, density 0.842 g/ml at 15.6 C, pour point -50 C.
      return sheet("SAE 0W-30 (Mobil 1 0W-30 data sheet)", 62.9, 10.9, 842.0, 15.6, -50.0);
    case SaeGrade::k5W30:
      // Mobil 1 5W-30: AP-English-LCW/carengineoils_sg_mobil-1-5w30.aspx (identical on
      // Canada-English-LCW/carengineoils_products_mobil-1_5w30.aspx): nu40 = 61.7,
      // nu100 = 11.0 mm^2/s, density 0.855 g/ml at 15.6 C, pour point -42 C.
      return sheet("SAE 5W-30 (Mobil 1 5W-30 data sheet)", 61.7, 11.0, 855.0, 15.6, -42.0);
    case SaeGrade::k5W40:
      // Mobil Super 3000 X2 5W-40: AP-English-LCW/carengineoils_au_products_mobil-super-
      // 3000-x2-5w40.aspx (identical on the _sg_ and _in_ pages): nu40 = 83,
      // nu100 = 14.0 mm^2/s, density 0.860 kg/l at 15 C, pour point -42 C.
      return sheet("SAE 5W-40 (Mobil Super 3000 X2 5W-40 data sheet)", 83.0, 14.0, 860.0, 15.0,
                   -42.0);
    case SaeGrade::k10W40:
      // Mobil Super 2000 X2 10W-40: AP-English-LCW/carengineoils_au_products_mobil-super-
      // 2000-x2-10w40.aspx: nu40 = 96, nu100 = 14.4 mm^2/s, density 0.877 kg/l at 15 C,
      // pour point -33 C. (The Singapore/Malaysia pages of the same product print
      // 92 / 14.4 mm^2/s and 0.869 kg/l: another formulation year.)
      return sheet("SAE 10W-40 (Mobil Super 2000 X2 10W-40 data sheet)", 96.0, 14.4, 877.0, 15.0,
                   -33.0);
    case SaeGrade::k15W40:
      // Mobil Super 1000 X2 15W-40: AP-English-LCW/carengineoils_au_products_mobil-super-
      // 1000-x2-15w-40.aspx (same viscosities on the _sg_ page): nu40 = 109,
      // nu100 = 14.5 mm^2/s, density 0.880 kg/l at 15 C, pour point -30 C.
      return sheet("SAE 15W-40 (Mobil Super 1000 X2 15W-40 data sheet)", 109.0, 14.5, 880.0, 15.0,
                   -30.0);
  }
  throw std::invalid_argument("makeSaeGradeOilSpec: unknown SaeGrade value " +
                              std::to_string(static_cast<int>(grade)));
}

Oil makeSaeGradeOil(SaeGrade grade) {
  return Oil(makeSaeGradeOilSpec(grade));
}

std::string toString(SaeGrade grade) {
  switch (grade) {
    case SaeGrade::k0W20:
      return "0W-20";
    case SaeGrade::k0W30:
      return "0W-30";
    case SaeGrade::k5W30:
      return "5W-30";
    case SaeGrade::k5W40:
      return "5W-40";
    case SaeGrade::k10W40:
      return "10W-40";
    case SaeGrade::k15W40:
      return "15W-40";
  }
  throw std::invalid_argument("toString: unknown SaeGrade value " +
                              std::to_string(static_cast<int>(grade)));
}

SaeGrade parseSaeGrade(std::string_view text) {
  // Normalise: upper case, drop blanks and dashes, drop a leading "SAE".
  std::string key;
  for (const char c : text) {
    if (c == ' ' || c == '-' || c == '\t') {
      continue;
    }
    key.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  if (key.rfind("SAE", 0) == 0) {
    key.erase(0, 3);
  }
  constexpr SaeGrade kAll[] = {SaeGrade::k0W20, SaeGrade::k0W30,  SaeGrade::k5W30,
                               SaeGrade::k5W40, SaeGrade::k10W40, SaeGrade::k15W40};
  for (const SaeGrade g : kAll) {
    std::string name = toString(g);
    name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
    if (key == name) {
      return g;
    }
  }
  throw std::invalid_argument("parseSaeGrade: text '" + std::string(text) +
                              "' is not one of the grades 0W-20, 0W-30, 5W-30, 5W-40, "
                              "10W-40, 15W-40");
}

}  // namespace pistondyn::lubrication
