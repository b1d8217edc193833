// The lubricated skirt element over whole cycles of the passenger-car example engine:
// the force on the piston against the closed-form free-body side force of the primary
// motion corrected by the piston's own lateral inertia, the moment against the piston's
// Newton-Euler balance about the pin, and the friction work (a continuous state) against
// the time integral of the friction power.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <tuple>

#include "SkirtTestDeck.h"
#include "SliderCrankClosedForm.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/GasForceElement.h"
#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"
#include "pistondyn/lubrication/PatirChengFlowFactors.h"
#include "pistondyn/plugin/LubricatedSkirtElement.h"
#include "pistondyn/plugin/PistonPose.h"
#include "pistondyn/skirt/SkirtSideSolver.h"

namespace {

using namespace pistondyn;
namespace ts = pistondyn::testsupport;

double maxAbs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v)
    m = std::max(m, std::abs(x));
  return m;
}

// Two cycles on a coarse grid (the balance holds on any grid); rows of the second.
struct CycleRun {
  explicit CycleRun(double outputStep_deg) : setup(ts::makeGasolineSkirtModel(32, 24)) {
    plugin::SimulationSettings s;
    s.integrator = plugin::SimulationSettings::Integrator::LinearlyImplicitBDF;
    s.outputStep_deg = outputStep_deg;
    s.cycles = 2;
    plugin::CycleSimulation sim(*setup.model, s);
    const auto& ct = setup.model->getCrankTrain();
    const auto& mass = setup.engine.mass;
    table = sim.run({}, [&](const SimTK::State& st) {
      // Lateral inertia force of the piston side (piston + floating pin) [N], and the
      // piston body's Newton-Euler moment terms about the pin centre P.
      const SimTK::Vec3 comP(mass.piston.comX_m, mass.piston.comY_m, 0);
      const SimTK::Vec3 aG = ct.getPiston().findStationAccelerationInGround(st, comP);
      const SimTK::Vec3 aPin = ct.getPin().getBodyOriginAcceleration(st);
      lateralInertia.push_back(mass.piston.mass_kg * aG[0] + mass.pin.mass_kg * aPin[0]);
      pinLateralAcceleration.push_back(aPin[0]);
      const SimTK::Vec3 G = ct.getPiston().findStationLocationInGround(st, comP);
      const SimTK::Vec3 P = ct.getPiston().findStationLocationInGround(st, ct.getPinAxisInPiston());
      const SimTK::Vec3 O = ct.getPiston().getBodyOriginLocation(st);
      const SimTK::Vec3 crown =
          ct.getPiston().findStationLocationInGround(st, ct.getCrownCentreInPiston());
      const double alpha = ct.getPiston().getBodyAngularAcceleration(st)[2];
      momentTerms.push_back({G, P, O, crown, aG, alpha, ct.getPiston().getBodyRotation(st).y()});
    });
    stats = sim.getStats();
  }
  struct MomentTerms {
    SimTK::Vec3 G, P, O, crown, aG;
    double angularAcceleration;
    SimTK::UnitVec3 pistonAxis;
  };
  ts::SkirtModel setup;
  plugin::ResultTable table;
  plugin::SimulationStats stats;
  std::vector<double> lateralInertia, pinLateralAcceleration;
  std::vector<MomentTerms> momentTerms;
};

// The check: over the whole cycle, the lateral force that film and contact exert
// on the piston equals the free-body side force of the primary motion corrected by the
// piston's own lateral inertia m x'', within 1 % of the peak side force. The closed form
// (tests/support/SliderCrankClosedForm.h) takes the measured axial loads: the gas force and
// the skirt friction.
TEST(LubricatedSkirt, ForceBalanceMatchesTheClosedFormSideForce) {
  CycleRun run(2.0);
  const auto& t = run.table;
  const auto angle = t.column("crank_angle_deg"), side = t.column("side_force_N"),
             gas = t.column("gas_force_N"), friction = t.column("friction_force_N"),
             tilt = t.column("tilt_mrad");
  const auto cf = ts::ClosedForm::of(run.setup.engine);
  const double phiTdc = cf.tdcPhi();
  const std::size_t begin = angle.size() / 2;  // the second cycle
  std::vector<double> reference, residual;
  for (std::size_t i = begin; i < angle.size(); ++i) {
    const auto k = cf.at(angle[i] * M_PI / 180.0 + phiTdc);
    // Friction along +y on the piston reduces the load towards the crank.
    const double axial = gas[i] - friction[i];
    const double sCf = ts::freeBody(run.setup.engine, k, axial).sideForceOnLiner_N;
    reference.push_back(sCf);
    // Piston side, x: m x'' = F_rod,x + F_skirt,x + F_gas,x, with the gas force along the
    // tilted piston axis (F_gas,x = -F_gas sin(tilt)), so F_rod,x = side force (= -F_skirt,x)
    // + m x'' + F_gas sin(tilt); F_rod,x is the closed form's side force up to the rod's own
    // secondary inertia. That part, from the rod's moment balance about the crank pin C with
    // the pin's lateral acceleration x_P'' added to the primary motion (the rod turns by
    // -cos(beta) x_P''/L more, its centre of mass moves by (l_G/L) x_P''): the rod-on-piston
    // lateral force changes by -(m_r l_G^2 + I_r) x_P'' / L^2 (cos(beta) cancels).
    const auto& rod = run.setup.engine.mass.conrod;
    const double L = run.setup.engine.geometry.conrodLength_m;
    const double rodInertia = -(rod.mass_kg * rod.comY_m * rod.comY_m + rod.inertiaZZ_kgm2) /
                              (L * L) * run.pinLateralAcceleration[i];
    residual.push_back(side[i] + run.lateralInertia[i] + gas[i] * std::sin(1e-3 * tilt[i]) -
                       (sCf + rodInertia));
  }
  const double peak = maxAbs(reference), worst = maxAbs(residual);
  std::printf("  peak side force %.1f N, worst residual %.2f N (%.3f %%), max |m x''| %.2f N\n",
              peak, worst, 100 * worst / peak, maxAbs(run.lateralInertia));
  EXPECT_LE(worst, 0.01 * peak);
}

// The moment on the piston: Newton-Euler of the piston body about the pin centre P with the
// element's reported loads (side force, friction at the piston-frame origin O, moment on the
// liner about O), the gas force along the piston axis at the crown centre and gravity:
//   M_skirt,O + [(O-P) x F_skirt]_z + [(crown-P) x F_gas]_z + [(G-P) x m g]_z
//     = I_G theta'' + m [(G-P) x a_G]_z
// (a floating pin transmits no moment). Within 1 % of the peak moment the element reports.
TEST(LubricatedSkirt, MomentBalanceAboutThePin) {
  CycleRun run(2.0);
  const auto& t = run.table;
  const auto side = t.column("side_force_N"), friction = t.column("friction_force_N"),
             moment = t.column("liner_moment_Nm"), gas = t.column("gas_force_N");
  const auto& mass = run.setup.engine.mass.piston;
  const double g = run.setup.engine.gravity_mps2;
  std::vector<double> residual;
  for (std::size_t i = side.size() / 2; i < side.size(); ++i) {
    const auto& m = run.momentTerms[i];
    const SimTK::Vec3 fSkirt(-side[i], friction[i], 0.0);
    const SimTK::Vec3 fGas = -gas[i] * SimTK::Vec3(m.pistonAxis);
    const double lhs = -moment[i] + SimTK::cross(m.O - m.P, fSkirt)[2] +
                       SimTK::cross(m.crown - m.P, fGas)[2] +
                       SimTK::cross(m.G - m.P, SimTK::Vec3(0, -mass.mass_kg * g, 0))[2];
    const double rhs = mass.inertiaZZ_kgm2 * m.angularAcceleration +
                       mass.mass_kg * SimTK::cross(m.G - m.P, m.aG)[2];
    residual.push_back(lhs - rhs);
  }
  const double peak = maxAbs(std::vector<double>(moment.begin() + moment.size() / 2, moment.end()));
  const double worst = maxAbs(residual);
  std::printf("  peak liner moment %.3f N m, worst residual %.2e N m\n", peak, worst);
  ASSERT_GT(peak, 1.0);
  EXPECT_LE(worst, 0.01 * peak);
}

// Friction work is a continuous state integrated with the motion; it must equal the time
// integral of the friction power (Simpson's rule over 0.5 deg rows, whose own error is far
// below the 0.5 % allowed), and fmep is that work per cycle over the displacement.
TEST(LubricatedSkirt, FrictionWorkIsTheIntegralOfFrictionPower) {
  CycleRun run(0.5);
  const auto& t = run.table;
  const auto time = t.column("time_s"), power = t.column("friction_power_W"),
             work = t.column("friction_work_J");
  const std::size_t n = time.size(), begin = n / 2;  // second cycle: rows begin .. n-1
  ASSERT_EQ((n - 1 - begin) % 2, 0u);
  const double h = time[begin + 1] - time[begin];
  double simpson = power[begin] + power[n - 1];
  for (std::size_t i = begin + 1; i < n - 1; ++i)
    simpson += ((i - begin) % 2 ? 4.0 : 2.0) * power[i];
  simpson *= h / 3.0;
  const double integrated = work[n - 1] - work[begin];
  std::printf("  cycle friction work: state %.6f J, Simpson of the power %.6f J\n", integrated,
              simpson);
  ASSERT_GT(integrated, 0.1);
  EXPECT_NEAR(integrated, simpson, 5e-3 * integrated);
  ASSERT_EQ(run.stats.cycleFmep_Pa.size(), 2u);
  const double displacement = ts::displacement_m3(run.setup.engine);
  EXPECT_NEAR(run.stats.cycleFmep_Pa[1], integrated / displacement,
              1e-9 * run.stats.cycleFmep_Pa[1]);
  std::printf("  fmep of the two cycles: %.4f %.4f kPa\n", run.stats.cycleFmep_Pa[0] / 1e3,
              run.stats.cycleFmep_Pa[1] / 1e3);
}

// One cycle of a model with BDF2 at 0.25 deg (ts::bdf2StepperSettings): its rows and the
// run's figures.
std::pair<plugin::ResultTable, plugin::SimulationStats> runOneCycle(
    plugin::PistonAssemblyModel& model) {
  plugin::CycleSimulation sim(model, ts::bdf2StepperSettings(1));
  plugin::ResultTable table = sim.run();
  return {std::move(table), sim.getStats()};
}

// Issue 12: the two sides solved on two threads give the serial run's results. The sides
// share only read-only data and are summed in the same order, so the rows must agree to the
// last bit; 1e-12 relative is the bound. A starved film (mass-conserving, 0.5 um
// supply) so that the fill-fraction histories the sides carry between steps are exercised.
TEST(LubricatedSkirt, ParallelSidesGiveTheSerialResults) {
  auto run = [](bool parallel) {
    plugin::LubricatedSkirtParameters p = ts::exampleSkirtParameters(16, 12);
    p.supplyFilm.constant_m = 0.5e-6;
    p.parallelSides = parallel;
    return runOneCycle(*ts::makeGasolineSkirtModel(16, 12, &p).model);
  };
  const auto [serial, serialStats] = run(false);
  const auto [parallel, parallelStats] = run(true);
  ASSERT_EQ(serial.columns, parallel.columns);
  ASSERT_EQ(serial.rows.size(), parallel.rows.size());
  ASSERT_GT(serial.rows.size(), 700u);
  EXPECT_EQ(serialStats.integratorSteps, parallelStats.integratorSteps);
  double worst = 0.0;
  for (std::size_t i = 0; i < serial.rows.size(); ++i) {
    for (std::size_t j = 0; j < serial.columns.size(); ++j) {
      const double a = serial.rows[i][j], b = parallel.rows[i][j];
      const double rel = std::abs(a - b) / std::max(1e-300, std::max(std::abs(a), std::abs(b)));
      worst = std::max(worst, rel);
      ASSERT_LE(rel, 1e-12) << serial.columns[j] << " at row " << i << ": " << a << " vs " << b;
    }
  }
  std::printf("  %zu rows x %zu columns, largest relative difference %.3g\n", serial.rows.size(),
              serial.columns.size(), worst);
}

// A free crank on an enormous flywheel turns at the prescribed speed to 1e-4, but reaches each
// row's crank angle by restarting the integrator from the previous row whenever its time
// estimate overshoots; each restart solves the films again at an accepted instant. Such a
// solve must keep what the mass-conserving film holds (SkirtSideSolver.cpp, setInputs): the
// free crank's cycle then equals the prescribed one (measured: u_lat within 0.04 um, fmep
// +0.08 %; when such a solve took a steady film instead: 3.9 um, the thrust side's film oil 41 %
// off, fmep +1.0 %). The fully flooded mass-conserving film (its cavitated regions hold oil
// from step to step), whose motion is smooth: a starved skirt that rattles would amplify the
// restarts' integrator history alone.
TEST(LubricatedSkirt, AFreeCrankOnAHugeFlywheelRunsThePrescribedCycle) {
  auto run = [](bool free) {
    plugin::LubricatedSkirtParameters p = ts::exampleSkirtParameters(16, 12);
    p.supplyFilm.constant_m = std::numeric_limits<double>::infinity();
    mbd::CrankDrive drive = ts::loadGasolineSkirtDeck(16, 12).engine.drive;
    drive.mode = mbd::CrankDrive::Mode::Free;
    drive.flywheelInertia_kgm2 = 1e4;
    return runOneCycle(*ts::makeGasolineSkirtModel(16, 12, &p, free ? &drive : nullptr).model);
  };
  const auto [prescribed, prescribedStats] = run(false);
  const auto [free, freeStats] = run(true);
  const std::vector<double> a = prescribed.column("u_lat_um"), b = free.column("u_lat_um");
  const std::vector<double> fa = prescribed.column("film_oil_volume_thrust_mm3"),
                            fb = free.column("film_oil_volume_thrust_mm3");
  ASSERT_EQ(a.size(), b.size());
  double lateral = 0.0, oil = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    lateral = std::max(lateral, std::abs(a[i] - b[i]));
    oil = std::max(oil, std::abs(fa[i] - fb[i]) / std::max(1e-3, std::abs(fa[i])));
  }
  std::printf("  free crank: %ld steps (prescribed %ld); largest difference of u_lat %.4f um, "
              "of the thrust side's film oil %.2e relative; fmep %.5f / %.5f kPa\n",
              freeStats.integratorSteps, prescribedStats.integratorSteps, lateral, oil,
              freeStats.cycleFmep_Pa.at(0) / 1e3, prescribedStats.cycleFmep_Pa.at(0) / 1e3);
  EXPECT_LT(lateral, 0.2);  // um: the periodic test's pose tolerance
  EXPECT_NEAR(freeStats.cycleFmep_Pa.at(0), prescribedStats.cycleFmep_Pa.at(0),
              0.005 * prescribedStats.cycleFmep_Pa.at(0));
  // The step error estimate of the same trajectory agrees (the free crank's restarts at
  // first order take more, shorter steps). Its landings' restarts discard the steps beyond an
  // output angle and their error estimates with them; counted, they added 10 % here (measured
  // 0.96x the prescribed crank's, 1.10x with them), within the bounds below: on this heavy
  // flywheel the overshoots are short, so the bounds check agreement, not that rule.
  const double errorFree_um = freeStats.cycleStepErrorEstimate_um.at(0),
               errorPrescribed_um = prescribedStats.cycleStepErrorEstimate_um.at(0);
  std::printf("  step error estimate: free crank %.4f um, prescribed %.4f um\n", errorFree_um,
              errorPrescribed_um);
  EXPECT_LT(errorFree_um, 1.5 * errorPrescribed_um);
  EXPECT_GT(errorFree_um, errorPrescribed_um / 1.5);
}

}  // namespace

// A film solve that does not converge throws, and the stepper retries the step: its solve and
// its reference-solver fallback must still be counted (summary.json's film_solves and
// film_fallbacks; issue 12: no fallback may happen silently). Until 2026-12-05 the counters
// were advanced after the solve returned, so a failing solve - the expensive kind, mostly
// Gauss-Seidel - was missing from both (seen: 86 % of a cycle's time in the fallback, 0
// fallbacks reported).
TEST(LubricatedSkirt, FilmSolvesThatFailAreCountedWithTheirFallbacks) {
  plugin::LubricatedSkirtParameters p = ts::exampleSkirtParameters(16, 12);
  p.lubrication.solver.maxActiveSetIterations = 1;  // no chance to settle ...
  p.lubrication.solver.maxSweeps = 1;               // ... nor to finish in the fallback
  p.lubrication.solver.fallbackToReference = true;
  const ts::SkirtModel m = ts::makeGasolineSkirtModel(16, 12, &p);
  m.model->buildSystem();
  const auto& ct = m.model->getCrankTrain();
  SimTK::State st = m.model->getDefaultState();
  ct.setPose(st, 20.0 * M_PI / 180.0, 38e-6);
  ct.setRates(st, m.engine.drive.speed_radps);
  EXPECT_THROW(m.model->getSystem().realize(st, SimTK::Stage::Dynamics), std::runtime_error);
  ASSERT_TRUE(m.skirt().getSolverCounters().has_value());
  EXPECT_EQ(m.skirt().getSolverCounters()->filmSolves, 2);     // both sides are always solved
  EXPECT_EQ(m.skirt().getSolverCounters()->filmFallbacks, 2);  // and both fell back
}

// setForceJacobianWanted(false) (the stepper's Jacobian reuse): the rigid skirt then solves its
// films without the squeeze derivatives - the same forces to the last bit (the derivative
// solves come after the film's own and change nothing in it) - gives the same stiffness part
// of the Jacobian (asperity contact), and NaN for the damping part it did not compute.
TEST(LubricatedSkirt, EvaluationWithoutJacobianGivesTheSameForces) {
  auto evaluate = [](bool wanted) {
    const ts::SkirtModel m = ts::makeGasolineSkirtModel(16, 12);
    m.model->buildSystem();
    const auto& ct = m.model->getCrankTrain();
    SimTK::State st = m.model->getDefaultState();
    ct.setPose(st, 20.0 * M_PI / 180.0, 38e-6);  // into the asperities: contact stiffness
    ct.setRates(st, m.engine.drive.speed_radps);
    m.model->setForceJacobianWanted(wanted);
    m.model->getSystem().realize(st, SimTK::Stage::Acceleration);
    m.model->setForceJacobianWanted(true);
    plugin::ForceJacobian jacobian;
    m.model->calcElementForceJacobian(st, jacobian);
    const auto& r = m.skirt().getResults(st);
    return std::make_tuple(r.forceOnPiston_N, r.momentOnPiston_Nm, r.dQ_dPoseRate, r.dQ_dPose,
                           m.skirt().getSolverCounters()->filmSolves);
  };
  const auto [fWith, mWith, dWith, kWith, solvesWith] = evaluate(true);
  const auto [fWithout, mWithout, dWithout, kWithout, solvesWithout] = evaluate(false);
  EXPECT_EQ(solvesWith, solvesWithout);
  ASSERT_GT(fWith.norm(), 1.0);   // the film carries a load here
  ASSERT_GT(dWith.norm(), 0.0);   // and has squeeze damping
  ASSERT_GT(kWith.norm(), 0.0);   // and the asperities a stiffness
  EXPECT_TRUE(dWithout.array().isNaN().all());  // left out, never read as zero damping
  EXPECT_EQ((kWith - kWithout).norm(), 0.0);
  EXPECT_EQ((fWith - fWithout).norm(), 0.0);
  EXPECT_EQ((mWith - mWithout).norm(), 0.0);
}

// Jacobian reuse over a whole flooded cycle (a film-borne skirt, its use case): the cycle with
// the stepper keeping its damping Jacobian over up to 20 steps follows the one that evaluates
// it every time far more closely than either follows the step-converged trajectory (0.125 deg,
// 5 nm): each step is converged by the Newton iteration either way. Seen: 0.013-0.041 um
// against 0.26-0.36 um, fmep equal to 4e-5. (Starved, where the film's active set and the
// asperity contact switch within steps, it is not: BENCHMARKS.md.)
TEST(LubricatedSkirt, JacobianReuseFollowsTheFloodedCycle) {
  auto run = [](int reuse, double maxStep_deg, double poseTolerance_m) {
    plugin::LubricatedSkirtParameters p = ts::exampleSkirtParameters(16, 12);
    // the default supply: fully flooded (SupplyFilm::constant_m = inf)
    ts::SkirtModel setup = ts::makeGasolineSkirtModel(16, 12, &p);
    plugin::SimulationSettings s;
    s.integrator = plugin::SimulationSettings::Integrator::LinearlyImplicitBDF;
    s.outputStep_deg = 1.0;
    s.cycles = 1;
    s.maxStep_deg = maxStep_deg;
    s.poseTolerance_m = poseTolerance_m;
    s.jacobianReuseSteps = reuse;
    plugin::CycleSimulation sim(*setup.model, s);
    plugin::ResultTable table = sim.run();
    return std::make_pair(table, sim.getStats());
  };
  // (Named references, not structured bindings: those cannot be captured by the lambdas
  // below in C++17.)
  const auto fineRun = run(0, 0.125, 5e-9);
  const auto freshRun = run(0, 0.25, 1e-8);
  const auto keptRun = run(20, 0.25, 1e-8);
  const plugin::ResultTable &fine = fineRun.first, &fresh = freshRun.first, &kept = keptRun.first;
  const plugin::SimulationStats &freshStats = freshRun.second, &keptStats = keptRun.second;
  ASSERT_EQ(fresh.columns, kept.columns);
  ASSERT_EQ(fresh.rows.size(), kept.rows.size());
  ASSERT_EQ(fresh.rows.size(), fine.rows.size());
  const auto column = [&](const char* name) {
    const auto it = std::find(fresh.columns.begin(), fresh.columns.end(), name);
    EXPECT_NE(it, fresh.columns.end()) << name;
    return static_cast<std::size_t>(it - fresh.columns.begin());
  };
  const std::size_t poseColumns[] = {column("u_lat_um"), column("u_lat_skirt_top_um"),
                                     column("u_lat_skirt_bottom_um")};
  const auto largestDifference_um = [&](const plugin::ResultTable& a,
                                        const plugin::ResultTable& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.rows.size(); ++i)
      for (std::size_t j : poseColumns)
        worst = std::max(worst, std::abs(a.rows[i][j] - b.rows[i][j]));
    return worst;
  };
  const double reuseEffect_um = largestDifference_um(fresh, kept);
  const double stepError_um = largestDifference_um(fresh, fine);
  ASSERT_FALSE(freshStats.cycleFmep_Pa.empty());
  ASSERT_FALSE(keptStats.cycleFmep_Pa.empty());
  const double fmepChange = keptStats.cycleFmep_Pa.back() / freshStats.cycleFmep_Pa.back() - 1.0;
  std::printf("  fmep %.5f / %.5f kPa (%+.4f %%); pose: reuse changes it by %.4f um, the step "
              "error of either is %.4f um; steps %ld / %ld\n",
              freshStats.cycleFmep_Pa.back() / 1e3, keptStats.cycleFmep_Pa.back() / 1e3,
              100.0 * fmepChange, reuseEffect_um, stepError_um, freshStats.integratorSteps,
              keptStats.integratorSteps);
  ASSERT_GT(stepError_um, 0.05);  // the reference is distinguishable at all
  EXPECT_LT(reuseEffect_um, 0.25 * stepError_um);
  EXPECT_LT(std::abs(fmepChange), 5e-4);
}

// The skirt side without Simbody (skirt::SkirtSideSolver): a solver built here from the
// element's parameters and the engine, given the pose the State holds and the element's
// conditions, returns the element's side results bit for bit. Whatever the element adds
// between the State and a side (reading the pose, the sliding velocities, the viscosity, the
// supply) is thereby checked against a second wiring of the same parts.
TEST(LubricatedSkirt, SideSolvedWithoutSimbodyEqualsTheElementsSide) {
  ts::SkirtModel m = ts::makeGasolineSkirtModel(16, 12);
  m.model->buildSystem();
  const auto& ct = m.model->getCrankTrain();
  SimTK::State st = m.model->getDefaultState();
  ct.setPose(st, 40.0 * M_PI / 180.0, 12e-6, 2e-4);
  ct.setRates(st, m.engine.drive.speed_radps, 0.02, -0.5);
  m.model->getSystem().realize(st, SimTK::Stage::Acceleration);
  const plugin::LubricatedSkirtElement& element = m.skirt();
  const plugin::LubricatedSkirtParameters& p = element.getParameters();  // filled by the engine
  const plugin::PistonPose pose = plugin::calcPistonPose(ct, st);

  auto flowFactors = std::make_shared<const lubrication::PatirChengFlowFactors>(p.roughness);
  auto law = std::make_shared<const contact_forces::GreenwoodTrippLaw>(p.asperity);
  skirt::SkirtSideSettings settings;
  settings.lubrication = p.lubrication;
  settings.fillFractionHistoryOrder = p.fillFractionHistoryOrder;
  for (const plugin::SkirtSide side : {plugin::SkirtSide::Thrust, plugin::SkirtSide::AntiThrust}) {
    skirt::SkirtSideGridParameters g = p.grid;
    g.side = side == plugin::SkirtSide::Thrust ? skirt::SkirtSide::Thrust
                                               : skirt::SkirtSide::AntiThrust;
    g.radius_m = 0.5 * m.engine.piston.bore_m;
    g.skirtTopHeight_m = m.engine.piston.skirtTopAbovePin_m;
    g.skirtLength_m = m.engine.piston.skirtLength_m;
    skirt::SkirtSideSolver solver(skirt::SkirtSideGrid(g), p.gap, flowFactors, law,
                                  contact_forces::BoundaryFriction(p.boundaryFriction), settings);
    const skirt::SkirtSideMotion motion{{pose.lateral_m, pose.tilt_rad, pose.transverse_m},
                                        {pose.lateralRate_mps, pose.tiltRate_radps,
                                         pose.transverseRate_mps},
                                        pose.pinHeight_m,
                                        pose.axialVelocity_mps};
    skirt::SkirtSideConditions conditions;
    conditions.viscosity_Pas = element.getViscosity_Pas();
    conditions.supplyFilm_m = p.supplyFilm.calcThickness_m(ct.getCrankAngle_rad(st) * 180 / M_PI);
    skirt::SkirtSideSolution solution;
    solver.solve(motion, conditions, skirt::SkirtSideHistory{}, solution);

    const skirt::SkirtSideResults& alone = solver.getResults();
    const skirt::SkirtSideResults& inElement = element.getLastSideResults(side);
    const auto& cached = element.getResults(st).sides[side == plugin::SkirtSide::Thrust ? 0 : 1];
    if (side == plugin::SkirtSide::Thrust) {  // moving towards thrust: a loaded film there
      ASSERT_GT(alone.hydrodynamicNormalForce_N, 100.0);
    }
    EXPECT_TRUE((alone.film.pressure_Pa() == inElement.film.pressure_Pa()).all());
    EXPECT_TRUE((alone.film.fillFraction() == inElement.film.fillFraction()).all());
    EXPECT_TRUE((alone.contact.pressure_Pa == inElement.contact.pressure_Pa).all());
    EXPECT_EQ(alone.totalLoads.force_N, inElement.totalLoads.force_N);
    EXPECT_EQ(alone.totalLoads.moment_Nm, inElement.totalLoads.moment_Nm);
    EXPECT_EQ(alone.dLoads_dPoseRate, inElement.dLoads_dPoseRate);
    EXPECT_EQ(alone.dLoads_dPose, inElement.dLoads_dPose);
    EXPECT_EQ(alone.frictionPower_W, cached.frictionPower_W);
    EXPECT_EQ(alone.minFilmThickness_m, cached.minFilmThickness_m);
    EXPECT_EQ(alone.hydrodynamicFrictionAxial_N, cached.hydrodynamicFrictionAxial_N);
    EXPECT_EQ(alone.asperityNormalForce_N, cached.asperityNormalForce_N);
    // A mass-conserving film's history comes with the solution: this step's fill fraction.
    ASSERT_TRUE(solution.historyAdvanced);
    EXPECT_TRUE((solution.next.film.last.fillFraction == alone.film.fillFraction()).all());
  }
}
