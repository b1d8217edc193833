#pragma once
/// \file
/// Lubricating oil: kinematic viscosity from the Walther relation of ASTM D341, density
/// from a constant volumetric thermal expansion coefficient, and the dynamic viscosity
/// eta(T) = rho(T) nu(T) the film solvers need. Low-shear (Newtonian) viscosity: no
/// pressure-viscosity and no shear-thinning of polymer-thickened multigrades.
///
/// Walther / ASTM D341 (simple form, valid for nu >= 2 mm^2/s):
///   log10(log10(nu + 0.7)) = A - B log10(T),  nu in mm^2/s (cSt), T in K.
/// A and B are fitted exactly through the two given (T, nu) points.
///
/// Density (our model; the data sheets give one density at 15 or 15.6 C):
///   rho(T) = rho_ref / (1 + alpha (T - T_ref)),
/// i.e. the specific volume grows linearly with T; alpha defaults to 6.5e-4 1/K, a typical
/// value for mineral and synthetic engine oils (6..7.5e-4 1/K). An error of 1e-4 1/K in
/// alpha changes eta at 100 C by about 0.85 %.
///
/// Valid temperature range: [minTemperature_degC, maxTemperature_degC] of the spec, with
/// the upper end lowered, if needed, to where nu falls to 2 mm^2/s (the lower limit of the
/// simple D341 form). Outside, every evaluation throws std::invalid_argument. The Walther
/// line through 40 C and 100 C data is an extrapolation below 40 C: for polymer-thickened
/// multigrades it is an estimate there (SAE J300's CCS/MRV data are the real low-
/// temperature properties), and below the pour point there is no Newtonian viscosity at
/// all.
///
/// Immutable after construction; safe to share between threads.

#include <string>

#include <Eigen/Core>

namespace pistondyn::lubrication {

/// Bounds in brackets are checked by Oil(OilSpec); the plausibility bounds (data viscosity
/// <= 1e-2 m^2/s, density in (500, 2000) kg/m^3, data temperatures in (-60, 250) degC)
/// catch unit mistakes (mm^2/s, g/ml, kelvin).
struct OilSpec {
  std::string name;                       ///< free text, e.g. grade and data source
  double temperature1_degC = 40.0;        ///< first data temperature [degC], default 40
  double kinematicViscosity1_m2ps = 0.0;  ///< nu at temperature1 [m^2/s], <= 1e-2 (no default)
  double temperature2_degC = 100.0;       ///< second data temperature [degC], default 100
  double kinematicViscosity2_m2ps = 0.0;  ///< nu at temperature2 [m^2/s], [2e-6, nu1) (no default)
  double density_kgpm3 = 0.0;             ///< density at densityReference [kg/m^3] (no default)
  double densityReferenceTemperature_degC = 15.0;  ///< [degC], default 15
  double thermalExpansion_perK = 6.5e-4;           ///< volumetric expansion alpha [1/K], [0, 2e-3)
  double minTemperature_degC = -20.0;              ///< lowest valid temperature [degC], default -20
  double maxTemperature_degC = 200.0;  ///< highest valid temperature [degC], default 200
};

/// A Newtonian oil: kinematic viscosity by the Walther relation (ASTM D341) through two data
/// points, density with a constant expansion coefficient, and its valid temperature range.
class Oil {
 public:
  /// Fits the Walther line through (temperature1, nu1) and (temperature2, nu2).
  /// Inputs:
  ///   spec  see OilSpec
  /// Throws std::invalid_argument naming the member when: a value is not finite;
  /// temperature2 <= temperature1 (the points must be ordered by increasing T);
  /// nu2 >= nu1 (viscosity must fall with temperature); a viscosity is <= 0 or below the
  /// 2 mm^2/s limit of ASTM D341's simple form; density <= 0; alpha outside [0, 2e-3);
  /// a temperature is at or below absolute zero; or the valid range is empty.
  /// Plausibility (unit mistakes; the message suggests the likely one): a data viscosity
  /// above 1e-2 m^2/s (given in mm^2/s?), a density outside (500, 2000) kg/m^3 (g/ml?), a
  /// data or density-reference temperature outside (-60, 250) degC (kelvin?).
  explicit Oil(const OilSpec& spec);

  /// Kinematic viscosity nu(T) [m^2/s] at temperature_degC inside the valid range.
  double calcKinematicViscosity_m2ps(double temperature_degC) const;
  /// Density rho(T) [kg/m^3] at temperature_degC inside the valid range.
  double calcDensity_kgpm3(double temperature_degC) const;
  /// Dynamic viscosity eta(T) = rho(T) nu(T) [Pa s] at temperature_degC inside the range.
  double calcDynamicViscosity_Pas(double temperature_degC) const;
  /// eta(T) for every entry of a temperature field (e.g. per film node, for
  /// FilmProblem::viscosityPerNode_Pas).
  /// Inputs:  temperature_degC  temperatures [degC], each inside the valid range
  /// Outputs: viscosity_Pas     eta [Pa s], same size (not resized; no allocation)
  /// Throws std::invalid_argument naming the index of the first temperature outside the
  /// range (output untouched), or on a size mismatch.
  void calcDynamicViscosity_Pas(const Eigen::Ref<const Eigen::ArrayXd>& temperature_degC,
                                Eigen::Ref<Eigen::ArrayXd> viscosity_Pas) const;
  /// Same as calcDynamicViscosity_Pas, temperature given in kelvin.
  double calcDynamicViscosityAtKelvin_Pas(double temperature_K) const;

  /// Valid range [degC]; the maximum may be lower than the spec's (nu >= 2 mm^2/s).
  double getMinTemperature_degC() const { return minTemperature_degC_; }
  double getMaxTemperature_degC() const { return maxTemperature_degC_; }  ///< see above
  /// Walther constants A, B [-] of log10(log10(nu_cSt + 0.7)) = A - B log10(T_K).
  double getWaltherA() const { return waltherA_; }
  double getWaltherB() const { return waltherB_; }  ///< see getWaltherA
  const OilSpec& getSpec() const { return spec_; }  ///< the specification as checked

 private:
  /// Throws std::invalid_argument naming function (and, for index >= 0, the array entry
  /// temperature_degC[index]) if the temperature is outside the valid range.
  void checkTemperature(const char* function, double temperature_degC,
                        Eigen::Index index = -1) const;
  double kinematicViscosity_cSt(double temperature_K) const;   ///< unchecked
  double density_kgpm3(double temperature_degC) const;         ///< unchecked
  double dynamicViscosity_Pas(double temperature_degC) const;  ///< unchecked

  OilSpec spec_;
  double waltherA_ = 0.0;
  double waltherB_ = 0.0;
  double minTemperature_degC_ = 0.0;
  double maxTemperature_degC_ = 0.0;
};

}  // namespace pistondyn::lubrication
