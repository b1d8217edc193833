#pragma once
/// @file
/// `pistondyn fit FIT.yaml --out DIR`: named uncertain inputs of the base deck calibrated to
/// measured traces by bounded least squares. README.md, "Calibration", documents the deck:
///
/// ~~~
///   parameters:                            # DesignStudy's variables, each with a start
///     piston.com_above_pin_mm: {bounds: [2, 10], start: 4}
///     liner.cold_radial_clearance_um: [35, 75]        # start: mid-range
///   measured:
///     - file: measured_tilt.csv            # CSV crank_angle_deg, <column>
///       column: tilt_mrad                  # a cycle.csv column of the run
///       weight: 1                          # optional (residuals times sqrt(weight))
///       windows_deg: [[0, 120], [600, 720]]   # optional crank-angle windows
///     - file: measured_lateral.csv
///       column: u_lat_um
///       height_above_pin_mm: 10            # lateral displacement there: u_lat + h tilt
///   method:
///     max_iterations: 30                   # Levenberg-Marquardt iterations
///     tolerance: 1e-6                      # relative decrease of the sum of squares
///     jacobian_step: 1e-3                  # central differences, relative to the ranges
///     rank_tolerance: 1e-6                 # singular-value ratio of an identifiable set
///     correlation_limit: 0.99
/// ~~~
///
/// The model's trace is the run's last cycle interpolated linearly (periodically) at the
/// measured crank angles. Levenberg-Marquardt in parameters scaled to [0, 1], steps
/// projected onto the bounds; each iteration's Jacobian is one batch of 2 n evaluations
/// (central differences; one-sided at a bound) run side by side. At the optimum: s^2 = SSR
/// / (m - n), covariance s^2 (J'J)^-1 from the Jacobian there; a parameter whose column is
/// zero, or that takes part in a direction of J with a singular value below rank_tolerance
/// times the largest (columns scaled to unit length), is reported as not identifiable, with
/// no value of its standard error; the others' errors come from the identifiable subset.
/// A parameter whose standard error exceeds its range, or whose correlation with another
/// exceeds correlation_limit, is reported as not identifiable too.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pistondyn/design/DesignStudy.h"
#include "pistondyn/design/Evaluations.h"

namespace pistondyn::design {

/// One measured trace of FIT.yaml's `measured` list, read and checked: a cycle.csv column
/// against crank angle, inside optional crank-angle windows.
struct MeasuredTrace {
  std::string file;                 ///< as resolved
  std::string column;               ///< of cycle.csv
  std::optional<double> height_mm;  ///< lateral displacement at this height above the pin
  double weight = 1.0;  ///< > 0; the trace's residuals are multiplied by sqrt(weight)
  std::vector<std::pair<double, double>> windows_deg;  ///< empty: the whole trace
  ///@{
  /// The measured points inside the windows: crank angle [deg] and value (the column's unit).
  std::vector<double> angle_deg, value;
  ///@}
  std::string origin;                                  ///< "fit.yaml:9: measured[1]"
  /// The column's name as the residuals name it ("tilt_mrad", "u_lat_um at 10 mm").
  std::string getLabel() const;
};

/// The deck's `method` section (this file's comment has the keys).
struct FitMethod {
  int maxIterations = 30;  ///< Levenberg-Marquardt iterations (accepted or not)
  /// Stop when an accepted step lowers the sum of squares by less than this fraction.
  double tolerance = 1e-6;
  /// Central-difference step of the Jacobian, relative to each parameter's range.
  double jacobianStep = 1e-3;
  /// Singular-value ratio below which a direction of J is not identifiable.
  double rankTolerance = 1e-6;
  /// |correlation| beyond which two parameters are not identifiable separately.
  double correlationLimit = 0.99;
};

/// FIT.yaml read and checked (loadFitDeck).
struct FitSpec {
  DesignStudy study;  ///< its variables are the parameters, each with a start
  std::vector<MeasuredTrace> traces;  ///< at least one
  FitMethod method;  ///< the iteration's settings
  ///@{
  /// The study's normalised content (design.json) and the SHA-256 hex of what decides its
  /// results (openDesignFolder()).
  std::string description, fingerprint;
  ///@}
  /// Measured points over all traces (the residuals' count m).
  int getPointCount() const;
};

/// Reads and checks FIT.yaml: the parameters, the traces (columns, crank angles strictly
/// increasing and within the run's 0 .. 720 deg cycle, finite numbers, each trace's column
/// one the run writes), at least one point more than parameters. Throws io::DeckError.
FitSpec loadFitDeck(const std::string& path,
                    const std::vector<std::string>& commandLineOverrides = {},
                    const io::LinerRegistry& registry = io::LinerRegistry::getGlobal());

/// One fitted parameter (in its key's unit).
struct FitParameterResult {
  std::string key;  ///< the deck key, as DesignVariable::key
  ///@{
  /// The starting and the fitted value.
  double start = 0.0, value = 0.0;
  ///@}
  bool atBound = false;  ///< the fitted value lies on a bound
  bool identifiable = true;  ///< false: no standard error (see note)
  std::optional<double> standardError;  ///< sqrt of the covariance's diagonal; nullopt: none
  std::string note;  ///< why not identifiable, or strong correlations
};

/// One trial point of the Levenberg-Marquardt iteration (the start is number 0).
struct FitIteration {
  int number = 0;  ///< 0 for the start, then one per trial step
  std::vector<double> x;  ///< the parameters, in their units
  double sumOfSquares = 0.0;  ///< weighted; +inf when its run failed
  double lambda = 0.0;  ///< the damping the step was computed with
  bool accepted = false;  ///< it lowered the sum of squares and became the current point
  std::string evaluation;  ///< its run folder id
};

/// What runFit() found.
struct FitOutcome {
  bool ok = false;      ///< the fit reached a result (the start ran)
  std::string message;  ///< why not
  /// Why the iteration stopped: converged, iteration limit, no step left within the bounds,
  /// or no further decrease.
  std::string stopReason;
  std::vector<FitParameterResult> parameters;  ///< in the study's variable order
  std::vector<std::vector<double>> correlation;  ///< NaN for unidentifiable parameters
  double sumOfSquares = 0.0;  ///< weighted sum of squared residuals at the optimum (SSR)
  int points = 0;  ///< measured points m
  double residualStd = 0.0;  ///< sqrt(SSR / (m - n)), in the weighted traces' units
  int rank = 0;              ///< of the Jacobian at the optimum
  std::vector<FitIteration> iterations;  ///< every trial point, the start first
  EvaluationResult best;  ///< the run at the fitted values
  std::vector<double> bestX;  ///< the fitted values, in the parameters' units
  std::vector<std::vector<double>> model;  ///< per trace, the fitted model at its angles
};

/// Receives one line of progress text per event (may be empty: no progress).
using FitProgress = std::function<void(const std::string& line)>;

/// Runs the fit of this file's comment on `executor`. A failed run at the start gives ok =
/// false with a message; a failed trial point is rejected, not thrown.
FitOutcome runFit(const FitSpec& spec, Executor& executor, const FitProgress& progress = {});

/// The model's values of a trace from a run folder's cycle.csv (its last cycle, linear and
/// periodic interpolation at the trace's angles). Throws std::runtime_error.
std::vector<double> readModelTrace(const MeasuredTrace& trace, const std::string& runFolder);

/// Covariance analysis of a Jacobian J (m x n, row-major: J[i][j] = d r_i / d x_j) with the
/// residual variance s2: standard errors (nullopt: not identifiable, with the reason in
/// `notes`), correlations (NaN where undefined) and the rank.
struct CovarianceAnalysis {
  std::vector<std::optional<double>> standardError;  ///< per parameter, in its unit
  std::vector<std::string> notes;  ///< per parameter: why not identifiable, or ""
  std::vector<std::vector<double>> correlation;  ///< n x n
  /// Rank of J with its columns scaled to unit length: the singular values >= rankTolerance
  /// times the largest.
  int rank = 0;
};
/// The analysis above; `names` label the parameters in the notes.
CovarianceAnalysis analyseCovariance(const std::vector<std::vector<double>>& J, double s2,
                                     const std::vector<std::string>& names, double rankTolerance,
                                     double correlationLimit);

/// The residuals' table: trace, crank_angle_deg, measured, fitted, residual (fitted -
/// measured), weight.
std::string makeResidualsCsv(const FitSpec& spec, const FitOutcome& outcome);
/// The iterations' table.
std::string makeFitHistoryCsv(const FitSpec& spec, const FitOutcome& outcome);

}  // namespace pistondyn::design
