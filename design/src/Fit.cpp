#include "pistondyn/design/Fit.h"

#include <yaml-cpp/yaml.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "StudyDeckReader.h"
#include "pistondyn/common/Validation.h"
#include "pistondyn/io/CsvTable.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/ResultFolder.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace pistondyn::design {
namespace {

using Json = nlohmann::ordered_json;
using common::formatNumber;

// ---- the deck ----------------------------------------------------------------------------

std::optional<std::vector<std::pair<double, double>>> readWindows(detail::StudyDeckReader& r,
                                                                  const YAML::Node& node,
                                                                  const std::string& where) {
  if (!node.IsSequence() || node.size() == 0) {
    r.problem(node, where,
              "expected a list of [from, to] crank-angle windows in degrees, e.g. "
              "[[0, 120], [600, 720]]");
    return std::nullopt;
  }
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const auto w = r.range(node[i], where + "[" + std::to_string(i + 1) + "]");
    if (!w)
      return std::nullopt;
    if (w->first < 0.0 || w->second > 720.0) {
      r.problem(node[i], where + "[" + std::to_string(i + 1) + "]",
                "a window lies within the run's cycle, 0 .. 720 deg");
      return std::nullopt;
    }
    out.push_back(*w);
  }
  return out;
}

// The trace's file: crank angles strictly increasing within 0 .. 720 deg, the named column.
void readTraceFile(detail::StudyDeckReader& r, const YAML::Node& at, const std::string& where,
                   MeasuredTrace& t) {
  io::CsvTable table;
  try {
    table = io::readCsvTable(t.file, {"crank_angle_deg", t.column});
  } catch (const io::DeckError& e) {
    r.problem(at, where, std::string("the measured trace is rejected: ") + e.what());
    return;
  }
  if (table.columns.size() != 2) {
    r.problem(at, where,
              t.file + ": expected exactly the columns crank_angle_deg, " + t.column +
                  " (the file has " + std::to_string(table.columns.size()) + ")");
    return;
  }
  const std::size_t a = table.columnIndex("crank_angle_deg"), v = table.columnIndex(t.column);
  double previous = -1.0;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const double angle = table.rows[i][a];
    if (angle < 0.0 || angle > 720.0) {
      r.problem(table.where(i) + ": crank_angle_deg " + formatNumber(angle) +
                " lies outside the run's cycle, 0 .. 720 deg (0 = firing TDC; give the "
                "measured cycle on that axis)");
      return;
    }
    if (i > 0 && !(angle > previous)) {
      r.problem(table.where(i) + ": crank_angle_deg " + formatNumber(angle) +
                " does not increase (the previous row has " + formatNumber(previous) +
                "): the crank angles must increase strictly");
      return;
    }
    previous = angle;
    bool inside = t.windows_deg.empty();
    for (const auto& [from, to] : t.windows_deg)
      inside = inside || (angle >= from && angle <= to);
    if (inside) {
      t.angle_deg.push_back(angle);
      t.value.push_back(table.rows[i][v]);
    }
  }
  if (table.rows.empty())
    r.problem(at, where, t.file + ": no rows");
}

void readMeasured(detail::StudyDeckReader& r, const YAML::Node& node, FitSpec& spec) {
  if (!node.IsSequence() || node.size() == 0) {
    r.problem(node, "measured",
              "expected a list of traces, each {file: measured.csv, column: tilt_mrad, weight: "
              "1, windows_deg: [[0, 120]]}");
    return;
  }
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string where = "measured[" + std::to_string(i + 1) + "]";
    const YAML::Node item = node[i];
    if (!item.IsMap()) {
      r.problem(item, where,
                "expected a section (file, column, weight, windows_deg, "
                "height_above_pin_mm)");
      continue;
    }
    MeasuredTrace t;
    t.origin = r.at(item, where);
    YAML::Node fileNode;
    bool ok = true;
    for (const auto& [key, value] : r.entries(item, where)) {
      const std::string w = where + "." + key;
      if (key == "file") {
        fileNode.reset(value);
        if (const auto f = r.text(value, w))
          t.file = r.resolve(*f);
        else
          ok = false;
      } else if (key == "column") {
        if (const auto c = r.text(value, w))
          t.column = *c;
        else
          ok = false;
      } else if (key == "weight") {
        const auto x = r.number(value, w);
        if (x && !(*x > 0.0)) {
          r.problem(value, w, "a weight must be positive");
          ok = false;
        } else if (x) {
          t.weight = *x;
        } else {
          ok = false;
        }
      } else if (key == "windows_deg") {
        if (const auto win = readWindows(r, value, w))
          t.windows_deg = *win;
        else
          ok = false;
      } else if (key == "height_above_pin_mm") {
        t.height_mm = r.number(value, w);
        ok = ok && t.height_mm.has_value();
      } else {
        r.problem(value, w,
                  "unknown key (expected file, column, weight, windows_deg, height_above_pin_mm)");
        ok = false;
      }
    }
    if (t.file.empty() || t.column.empty()) {
      r.problem(item, where, std::string("missing key ") + (t.file.empty() ? "file" : "column"));
      continue;
    }
    if (t.height_mm && t.column != "u_lat_um") {
      r.problem(item, where + ".height_above_pin_mm",
                "a lateral displacement at a height is the column u_lat_um (at the pin) carried "
                "up by the tilt; the trace's column is " +
                    t.column);
      ok = false;
    }
    if (!ok)
      continue;
    readTraceFile(r, fileNode, where + ".file", t);
    spec.traces.push_back(std::move(t));
  }
}

void readFitMethod(detail::StudyDeckReader& r, const YAML::Node& node, FitMethod& m) {
  if (!node.IsMap()) {
    r.problem(node, "method",
              "expected a section (max_iterations, tolerance, jacobian_step, "
              "rank_tolerance, correlation_limit)");
    return;
  }
  for (const auto& [key, v] : r.entries(node, "method")) {
    const std::string where = "method." + key;
    if (key == "max_iterations") {
      if (const auto n = r.wholeNumber(v, where, 1, 10000))
        m.maxIterations = static_cast<int>(*n);
      continue;
    }
    double* target = key == "tolerance"           ? &m.tolerance
                     : key == "jacobian_step"     ? &m.jacobianStep
                     : key == "rank_tolerance"    ? &m.rankTolerance
                     : key == "correlation_limit" ? &m.correlationLimit
                                                  : nullptr;
    if (target == nullptr) {
      r.problem(v, where,
                "unknown key (expected max_iterations, tolerance, jacobian_step, rank_tolerance, "
                "correlation_limit)");
      continue;
    }
    const auto x = r.number(v, where);
    const double hi = key == "correlation_limit" ? 1.0 : 0.5;
    if (x && !(*x > 0.0 && *x <= hi))
      r.problem(v, where, "expected a number in (0, " + formatNumber(hi) + "]");
    else if (x)
      *target = *x;
  }
}

Json describe(const FitSpec& spec, bool forFingerprint) {
  const DesignStudy& s = spec.study;
  Json j;
  if (!forFingerprint) {
    j["deck"] = s.deckPath;
    j["name"] = s.name;
    j["base_deck"] = s.baseDeckPath;
  }
  j["context_sha256"] = s.contextSha256;
  j["fixed_overrides"] = s.fixedOverrides;
  Json vars = Json::array();
  for (const auto& v : s.variables)
    vars.push_back({{"key", v.key}, {"lower", v.lower}, {"upper", v.upper}, {"start", *v.start}});
  j["parameters"] = vars;
  Json traces = Json::array();
  for (const auto& t : spec.traces) {
    Json one = {{"column", t.column}, {"weight", t.weight}};
    if (!forFingerprint)
      one["file"] = t.file;
    one["height_above_pin_mm"] = t.height_mm ? Json(*t.height_mm) : Json(nullptr);
    Json windows = Json::array();
    for (const auto& w : t.windows_deg)
      windows.push_back({w.first, w.second});
    one["windows_deg"] = windows;
    one["angle_deg"] = t.angle_deg;
    one["value"] = t.value;
    traces.push_back(one);
  }
  j["measured"] = traces;
  j["method"] = {{"max_iterations", spec.method.maxIterations},
                 {"tolerance", spec.method.tolerance},
                 {"jacobian_step", spec.method.jacobianStep},
                 {"rank_tolerance", spec.method.rankTolerance},
                 {"correlation_limit", spec.method.correlationLimit}};
  return j;
}

// ---- the least-squares loop --------------------------------------------------------------

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

struct Residuals {
  bool ok = false;
  std::string message;
  Vector r;
  EvaluationResult run;
  std::vector<std::vector<double>> model;
};

class Problem {
 public:
  Problem(const FitSpec& spec, Executor& executor) : spec_(spec), executor_(executor) {
    for (const auto& v : spec.study.variables) {
      lo_.push_back(v.lower);
      hi_.push_back(v.upper);
    }
  }
  std::size_t size() const { return lo_.size(); }
  std::vector<double> toX(const Vector& u) const {
    std::vector<double> x(u.size());
    for (Eigen::Index i = 0; i < u.size(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      x[k] = std::clamp(lo_[k] + u[i] * (hi_[k] - lo_[k]), lo_[k], hi_[k]);
    }
    return x;
  }
  double range(std::size_t i) const { return hi_[i] - lo_[i]; }

  std::vector<Residuals> evaluate(const std::vector<Vector>& points) {
    std::vector<EvaluationRequest> requests;
    std::vector<std::optional<std::string>> unbuildable;
    for (const auto& u : points) {
      try {
        requests.push_back(spec_.study.makeRequest(toX(u)));
        unbuildable.emplace_back();
      } catch (const std::exception& e) {
        unbuildable.emplace_back(e.what());
      }
    }
    const auto results = executor_.evaluate(requests);
    std::vector<Residuals> out;
    std::size_t next = 0;
    for (const auto& why : unbuildable) {
      Residuals res;
      if (why) {
        res.message = *why;
        out.push_back(res);
        continue;
      }
      res.run = results[next++];
      if (!res.run.ok) {
        res.message = res.run.message;
        out.push_back(res);
        continue;
      }
      try {
        std::vector<double> all;
        for (const auto& t : spec_.traces) {
          res.model.push_back(readModelTrace(t, res.run.folder));
          const double w = std::sqrt(t.weight);
          for (std::size_t i = 0; i < t.value.size(); ++i)
            all.push_back(w * (res.model.back()[i] - t.value[i]));
        }
        res.r = Eigen::Map<const Vector>(all.data(), static_cast<Eigen::Index>(all.size()));
        res.ok = true;
      } catch (const std::exception& e) {
        res.message = e.what();
      }
      out.push_back(res);
    }
    return out;
  }

  // The residuals at u and the Jacobian in scaled coordinates (central differences, one
  // sided at a bound), in one batch. J's columns of parameters whose neighbours failed are 0.
  Residuals withJacobian(const Vector& u, Matrix& J, std::vector<std::string>& notes) {
    const double h = spec_.method.jacobianStep;
    const auto n = static_cast<Eigen::Index>(size());
    std::vector<Vector> points = {u};
    std::vector<std::pair<double, double>> steps;
    for (Eigen::Index j = 0; j < n; ++j) {
      Vector up = u, down = u;
      up[j] = std::min(1.0, u[j] + h);
      down[j] = std::max(0.0, u[j] - h);
      points.push_back(up);
      points.push_back(down);
      steps.emplace_back(up[j], down[j]);
    }
    auto res = evaluate(points);
    if (!res[0].ok)
      return res[0];
    J.setZero(res[0].r.size(), n);
    notes.assign(static_cast<std::size_t>(n), "");
    for (Eigen::Index j = 0; j < n; ++j) {
      const auto k = static_cast<std::size_t>(j);
      const Residuals& a = res[1 + 2 * k];
      const Residuals& b = res[2 + 2 * k];
      if (a.ok && b.ok && steps[k].first > steps[k].second) {
        J.col(j) = (a.r - b.r) / (steps[k].first - steps[k].second);
      } else if (a.ok && steps[k].first > u[j]) {
        J.col(j) = (a.r - res[0].r) / (steps[k].first - u[j]);
      } else if (b.ok && steps[k].second < u[j]) {
        J.col(j) = (res[0].r - b.r) / (u[j] - steps[k].second);
      } else {
        notes[k] = "the runs beside it failed (" + (a.ok ? b.message : a.message) + ")";
      }
    }
    return res[0];
  }

 private:
  const FitSpec& spec_;
  Executor& executor_;
  std::vector<double> lo_, hi_;
};

double periodicInterpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  // x strictly increasing within [0, 720); the curve repeats every 720 deg.
  const std::size_t n = x.size();
  if (n == 1)
    return y[0];
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  std::size_t hi = static_cast<std::size_t>(it - x.begin());
  std::size_t lo = hi == 0 ? n - 1 : hi - 1;
  double xl = x[lo], xh = hi == n ? x[0] + 720.0 : x[hi];
  if (hi == n)
    hi = 0;
  if (at < x[0])
    xl -= 720.0;
  const double t = (at - xl) / (xh - xl);
  return y[lo] + t * (y[hi] - y[lo]);
}

}  // namespace

std::string MeasuredTrace::getLabel() const {
  return height_mm ? column + " at " + formatNumber(*height_mm) + " mm" : column;
}

int FitSpec::getPointCount() const {
  int m = 0;
  for (const auto& t : traces)
    m += static_cast<int>(t.value.size());
  return m;
}

FitSpec loadFitDeck(const std::string& path, const std::vector<std::string>& commandLineOverrides,
                    const io::LinerRegistry& registry) {
  detail::StudyDeckReader r(path, "fit");
  FitSpec spec;
  bool sawMeasured = false;
  for (const auto& [key, value] : r.open()) {
    if (r.readCommon(key, value, "parameters", true))
      continue;
    if (key == "measured") {
      sawMeasured = true;
      readMeasured(r, value, spec);
    } else if (key == "method") {
      readFitMethod(r, value, spec.method);
    } else {
      r.problem(value, key,
                "unknown key (a fit deck has name, base_deck, set, parameters, profile, "
                "measured, method)");
    }
  }
  if (!sawMeasured)
    r.problem(r.getPath() + ": measured: missing key (the traces to fit)");
  r.throwIfProblems();
  const auto base = r.finishCommon(spec.study, commandLineOverrides, registry);
  for (auto& v : spec.study.variables) {
    if (!v.start)
      v.start = 0.5 * (v.lower + v.upper);
  }
  // Each trace's column is one the run writes.
  std::vector<std::string> columns;
  try {
    auto model = io::buildModel(*base);
    columns = plugin::CycleSimulation(*model, base->simulation).getColumns();
  } catch (const std::exception& e) {
    r.problem(r.getPath() + ": base_deck: the model cannot be built: " + e.what());
  }
  for (const auto& t : spec.traces) {
    for (const std::string& c : {t.column, std::string(t.height_mm ? "tilt_mrad" : "")}) {
      if (!c.empty() && std::find(columns.begin(), columns.end(), c) == columns.end()) {
        std::string list;
        for (const auto& x : columns)
          list += (list.empty() ? "" : ", ") + x;
        r.problem(t.origin + ".column: the run writes no column " + c + " (its columns: " + list +
                  ")");
      }
    }
  }
  const int m = spec.getPointCount();
  const auto n = static_cast<int>(spec.study.variables.size());
  if (m <= n) {
    r.problem(r.getPath() + ": measured: " + std::to_string(m) +
              " measured points inside the windows for " + std::to_string(n) +
              " parameters: a fit needs more data points than parameters (widen the windows, "
              "add traces, or fit fewer parameters)");
  }
  r.throwIfProblems();
  spec.description = describe(spec, false).dump();
  spec.fingerprint = hashText("fit\n" + describe(spec, true).dump());
  return spec;
}

std::vector<double> readModelTrace(const MeasuredTrace& trace, const std::string& runFolder) {
  const io::ResultFolder f = io::readResultFolder(runFolder);
  const io::CycleWindow w = io::selectLastCycle(f.cycle);
  const std::size_t c = f.cycle.columnIndex(trace.column);
  const std::size_t tilt = trace.height_mm ? f.cycle.columnIndex("tilt_mrad") : 0;
  std::vector<double> x, y;
  for (std::size_t i = 0; i < w.rows.size(); ++i) {
    const double angle = w.angle_deg[i];
    if (angle >= 720.0)
      continue;  // the row closing the cycle: the same point as 0 deg
    const auto& row = f.cycle.rows[w.rows[i]];
    // mm x mrad = um: the lateral displacement at the height, small tilt.
    y.push_back(row[c] + (trace.height_mm ? *trace.height_mm * row[tilt] : 0.0));
    x.push_back(angle);
  }
  if (x.empty())
    throw std::runtime_error(runFolder + ": the run has no rows in its last cycle");
  std::vector<double> out;
  for (const double a : trace.angle_deg)
    out.push_back(periodicInterpolate(x, y, std::fmod(a, 720.0)));
  return out;
}

CovarianceAnalysis analyseCovariance(const std::vector<std::vector<double>>& Jrows, double s2,
                                     const std::vector<std::string>& names, double rankTolerance,
                                     double correlationLimit) {
  const std::size_t n = names.size();
  const std::size_t m = Jrows.size();
  Matrix J(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < n; ++j)
      J(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = Jrows[i][j];
  CovarianceAnalysis a;
  a.standardError.assign(n, std::nullopt);
  a.notes.assign(n, "");
  a.correlation.assign(n, std::vector<double>(n, std::nan("")));
  std::vector<bool> identifiable(n, true);
  Vector norms = J.colwise().norm();
  const double largest = norms.size() > 0 ? norms.maxCoeff() : 0.0;
  std::vector<Eigen::Index> nonzero;
  for (std::size_t j = 0; j < n; ++j) {
    const double v = norms[static_cast<Eigen::Index>(j)];
    if (!(v > 1e-12 * largest) || !(v > 0.0)) {
      identifiable[j] = false;
      a.notes[j] = "not identifiable: the traces do not depend on it (zero sensitivity)";
    } else {
      nonzero.push_back(static_cast<Eigen::Index>(j));
    }
  }
  if (!nonzero.empty()) {
    Matrix Js(J.rows(), static_cast<Eigen::Index>(nonzero.size()));
    for (std::size_t k = 0; k < nonzero.size(); ++k)
      Js.col(static_cast<Eigen::Index>(k)) = J.col(nonzero[k]) / norms[nonzero[k]];
    Eigen::JacobiSVD<Matrix> svd(Js, Eigen::ComputeThinV);
    const Vector sigma = svd.singularValues();
    const Matrix V = svd.matrixV();
    // Directions the traces cannot see, and every parameter that takes part in one.
    std::vector<std::pair<std::vector<std::size_t>, double>> blind;
    for (Eigen::Index k = 0; k < sigma.size(); ++k) {
      if (sigma[k] >= rankTolerance * sigma[0]) {
        ++a.rank;
        continue;
      }
      std::vector<std::size_t> involved;
      for (Eigen::Index r = 0; r < V.rows(); ++r) {
        if (std::fabs(V(r, k)) >= 0.1)
          involved.push_back(static_cast<std::size_t>(nonzero[static_cast<std::size_t>(r)]));
      }
      blind.emplace_back(involved, sigma[k] / sigma[0]);
    }
    for (const auto& [involved, ratio] : blind) {
      for (const std::size_t j : involved) {
        identifiable[j] = false;
        std::string others;
        for (const std::size_t o : involved) {
          if (o != j)
            others += (others.empty() ? "" : ", ") + names[o];
        }
        a.notes[j] = "not identifiable: the Jacobian has rank " + std::to_string(a.rank) + " for " +
                     std::to_string(n) + " parameters; only a combination" +
                     (others.empty() ? std::string() : " with " + others) +
                     " is determined (singular value ratio " + formatNumber(ratio) + " < " +
                     formatNumber(rankTolerance) + ")";
      }
    }
  }
  // Covariance of the identifiable set.
  std::vector<std::size_t> set;
  for (std::size_t j = 0; j < n; ++j) {
    if (identifiable[j])
      set.push_back(j);
  }
  if (!set.empty()) {
    Matrix JI(J.rows(), static_cast<Eigen::Index>(set.size()));
    for (std::size_t k = 0; k < set.size(); ++k)
      JI.col(static_cast<Eigen::Index>(k)) = J.col(static_cast<Eigen::Index>(set[k]));
    const Matrix C = s2 * (JI.transpose() * JI).inverse();
    for (std::size_t p = 0; p < set.size(); ++p) {
      const double cp = C(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p));
      a.standardError[set[p]] = std::sqrt(cp);
      for (std::size_t q = 0; q < set.size(); ++q) {
        const double cq = C(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(q));
        a.correlation[set[p]][set[q]] =
            C(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(q)) / std::sqrt(cp * cq);
      }
    }
    for (std::size_t p = 0; p < set.size(); ++p) {
      for (std::size_t q = 0; q < set.size(); ++q) {
        const double rho = a.correlation[set[p]][set[q]];
        if (p != q && std::fabs(rho) > correlationLimit) {
          a.notes[set[p]] = "not identifiable separately: correlation " + formatNumber(rho) +
                            " with " + names[set[q]] + " (beyond " +
                            formatNumber(correlationLimit) + ")";
        }
      }
    }
    for (const std::size_t j : set) {
      if (!a.notes[j].empty())
        a.standardError[j].reset();
    }
  }
  return a;
}

FitOutcome runFit(const FitSpec& spec, Executor& executor, const FitProgress& progress) {
  FitOutcome out;
  Problem problem(spec, executor);
  const auto n = static_cast<Eigen::Index>(problem.size());
  const int m = spec.getPointCount();
  out.points = m;
  Vector u(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& v = spec.study.variables[static_cast<std::size_t>(j)];
    u[j] = (*v.start - v.lower) / (v.upper - v.lower);
  }
  Matrix J;
  std::vector<std::string> failures;
  Residuals current = problem.withJacobian(u, J, failures);
  if (!current.ok) {
    out.message = "the run at the start failed: " + current.message;
    return out;
  }
  double ssr = current.r.squaredNorm();
  double lambda = 1e-3;
  int number = 0;
  out.iterations.push_back({number, problem.toX(u), ssr, lambda, true, current.run.id});
  if (progress)
    progress("start: sum of squares " + formatNumber(ssr));
  out.stopReason = "iteration limit reached";
  for (int it = 0; it < spec.method.maxIterations; ++it) {
    const Matrix A = J.transpose() * J;
    const Vector g = J.transpose() * current.r;
    const double scale = A.diagonal().maxCoeff();
    Vector D = A.diagonal();
    for (Eigen::Index j = 0; j < n; ++j)
      D[j] = std::max(D[j], 1e-12 * std::max(scale, 1e-300));
    bool accepted = false;
    while (!accepted) {
      Matrix M = A;
      M.diagonal() += lambda * D;
      const Vector step = M.ldlt().solve(-g);
      Vector trial = (u + step).cwiseMax(0.0).cwiseMin(1.0);
      if ((trial - u).cwiseAbs().maxCoeff() < 1e-12) {
        out.stopReason = "no step left within the bounds";
        break;
      }
      const Residuals next = problem.evaluate({trial}).front();
      const double nextSsr =
          next.ok ? next.r.squaredNorm() : std::numeric_limits<double>::infinity();
      ++number;
      out.iterations.push_back(
          {number, problem.toX(trial), nextSsr, lambda, next.ok && nextSsr < ssr, next.run.id});
      if (next.ok && nextSsr < ssr) {
        const double relative = (ssr - nextSsr) / ssr;
        u = trial;
        lambda = std::max(lambda / 10.0, 1e-12);
        current = problem.withJacobian(u, J, failures);
        ssr = current.r.squaredNorm();
        accepted = true;
        if (progress)
          progress("iteration " + std::to_string(number) + ": sum of squares " + formatNumber(ssr));
        if (relative < spec.method.tolerance) {
          out.stopReason =
              "sum of squares converged (relative decrease " + formatNumber(relative) + ")";
          it = spec.method.maxIterations;
        }
      } else {
        lambda *= 10.0;
        if (lambda > 1e12) {
          out.stopReason = "no further decrease of the sum of squares";
          break;
        }
      }
    }
    if (!accepted)
      break;
  }
  out.ok = true;
  out.best = current.run;
  out.bestX = problem.toX(u);
  out.model = current.model;
  out.sumOfSquares = ssr;
  out.residualStd = std::sqrt(ssr / std::max(1, m - static_cast<int>(n)));
  // The Jacobian in the parameters' own units.
  std::vector<std::vector<double>> Jx(static_cast<std::size_t>(J.rows()),
                                      std::vector<double>(static_cast<std::size_t>(n)));
  for (Eigen::Index i = 0; i < J.rows(); ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      Jx[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          J(i, j) / problem.range(static_cast<std::size_t>(j));
  std::vector<std::string> names;
  for (const auto& v : spec.study.variables)
    names.push_back(v.key);
  const CovarianceAnalysis cov =
      analyseCovariance(Jx, out.residualStd * out.residualStd, names, spec.method.rankTolerance,
                        spec.method.correlationLimit);
  out.rank = cov.rank;
  out.correlation = cov.correlation;
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const auto& v = spec.study.variables[k];
    FitParameterResult p;
    p.key = v.key;
    p.start = *v.start;
    p.value = out.bestX[k];
    p.atBound = u[j] <= 0.0 || u[j] >= 1.0;
    p.standardError = cov.standardError[k];
    p.identifiable = cov.standardError[k].has_value();
    p.note = !failures[k].empty() ? failures[k] : cov.notes[k];
    // Determined no better than by its bounds: the traces barely depend on it.
    if (p.standardError && *p.standardError > v.upper - v.lower) {
      p.note = "not identifiable: its standard error " + formatNumber(*p.standardError) +
               " exceeds its range " + formatNumber(v.upper - v.lower) +
               " (the traces barely depend on it)";
      p.standardError.reset();
      p.identifiable = false;
    }
    if (!failures[k].empty()) {
      p.identifiable = false;
      p.standardError.reset();
    }
    out.parameters.push_back(p);
  }
  return out;
}

std::string makeResidualsCsv(const FitSpec& spec, const FitOutcome& o) {
  std::ostringstream out;
  out << "# pistondyn fit: measured and fitted traces at the measured crank angles inside the "
         "windows; residual = fitted - measured; crank angle 0 deg = firing TDC\n";
  out << "trace,column,crank_angle_deg,measured,fitted,residual,weight\n";
  for (std::size_t t = 0; t < spec.traces.size(); ++t) {
    const auto& tr = spec.traces[t];
    for (std::size_t i = 0; i < tr.value.size(); ++i) {
      const double fitted = o.model.size() > t ? o.model[t][i] : std::nan("");
      out << t + 1 << ",\"" << tr.getLabel() << "\"," << formatNumber(tr.angle_deg[i]) << ','
          << formatNumber(tr.value[i]) << ',' << (std::isfinite(fitted) ? formatNumber(fitted) : "")
          << ',' << (std::isfinite(fitted) ? formatNumber(fitted - tr.value[i]) : "") << ','
          << formatNumber(tr.weight) << '\n';
    }
  }
  return out.str();
}

std::string makeFitHistoryCsv(const FitSpec& spec, const FitOutcome& o) {
  std::ostringstream out;
  out << "# pistondyn fit: the Levenberg-Marquardt steps (iteration 0: the start); accepted "
         "steps lower the sum of squares; evaluation: the run folder under evaluations/\n";
  out << "iteration";
  for (const auto& v : spec.study.variables)
    out << ',' << v.key;
  out << ",sum_of_squares,lambda,accepted,evaluation\n";
  for (const auto& it : o.iterations) {
    out << it.number;
    for (const double x : it.x)
      out << ',' << formatNumber(x);
    out << ',' << (std::isfinite(it.sumOfSquares) ? formatNumber(it.sumOfSquares) : "") << ','
        << formatNumber(it.lambda) << ',' << (it.accepted ? "true" : "false") << ','
        << it.evaluation << '\n';
  }
  return out.str();
}

}  // namespace pistondyn::design
