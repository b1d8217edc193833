// The liner's oil film (skirt::LinerOilFilm) alone, and with the skirt's film on it
// (skirt::SkirtSideSolver, no Simbody):
//  - the balance: over random steps with random edge flows, the oil on the liner changes by
//    exactly its sources less its losses and the film's intake (round-off);
//  - the oil-control ring meters the film of the rows it passes;
//  - the one-dimensional flow balance (closed form): a round skirt at a fixed, centred pose in
//    a round bore (uniform gap c0, no pressure) slides at constant speed U over a uniform liner
//    film h_in. Its film carries theta c0 U / 2 per width: the inlet's U h_in when starved
//    (2 h_in < c0), U c0 / 2 when flooded. Past the transient of one skirt length, the trailing
//    edge leaves (1 - share) of that flow, over the speed, on the liner behind it:
//    (1 - share) h_in starved, (1 - share) c0 / 2 flooded, and the flooded skirt pushes the
//    excess h_in - c0 / 2 ahead of it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "SkirtTestSupport.h"
#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"
#include "pistondyn/lubrication/FlowFactorModel.h"
#include "pistondyn/skirt/LinerOilFilm.h"
#include "pistondyn/skirt/SkirtSideSolver.h"

namespace {

namespace ps = pistondyn::skirt;
namespace lub = pistondyn::lubrication;
namespace cf = pistondyn::contact_forces;

// A thrust side, 0.5 rad wide, 20 mm long from 5 mm above the pin, 16 x 24 nodes.
ps::SkirtSideGrid side() {
  ps::SkirtSideGridParameters p = ps::test::thrustSide(16, 24);
  p.arcWidth_rad = 0.5;
  p.skirtTopHeight_m = 0.005;
  p.skirtLength_m = 0.020;
  return ps::SkirtSideGrid(p);
}

double sum(const ps::LinerOilState& s) {
  const ps::LinerOilFlows& f = s.flows;
  return f.ringSource_m3 + f.splashSource_m3 + f.deficitSource_m3 - f.drainLoss_m3 -
         f.filmIntake_m3 - f.sideLeakage_m3 - f.skirtShareLoss_m3;
}

TEST(LinerOilFilm, BalanceClosesToRoundOffOverRandomSteps) {
  const ps::SkirtSideGrid g = side();
  ps::LinerOilParameters p;
  p.ringHeightAbovePin_m = 0.012;
  p.ringFilm_m = 0.8e-6;
  p.floodedBelow_m = 0.050;
  p.splashBelow_m = 0.070;
  p.splashRate_mps = 2e-3;
  p.maxFilm_m = 20e-6;
  p.initialFilm_m = 1.5e-6;
  const ps::LinerOilFilm liner(g, p, 0.060, 0.140);
  ps::LinerOilState s = liner.makeInitialState(0.060);
  const double start = liner.storedVolume_m3(s);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int nc = liner.columns();
  Eigen::ArrayXd bottom(nc), top(nc), sideMin(g.nY()), sideMax(g.nY());
  double Y = 0.060, throughput = 0.0;  // volumes moved, the scale of the round-off
  for (int step = 0; step < 4000; ++step) {
    const double t = step * 1e-5, v = 8.0 * std::sin(2.0 * M_PI * t / 0.02);
    const double dt = 1e-5;
    for (int i = 0; i < nc; ++i) {
      bottom[i] = 1e-7 * u(rng);  // m^3/s per node, either sign
      top[i] = 1e-7 * u(rng);
    }
    sideMin = 1e-8 * (Eigen::ArrayXd::Random(g.nY()) + 1.0);
    sideMax = 1e-8 * (Eigen::ArrayXd::Random(g.nY()) + 1.0);
    throughput += (bottom.abs().sum() + top.abs().sum()) * dt;
    Y += v * dt;
    const ps::LinerOilState before = s;
    s = liner.advance(before, Y, v, 360.0 * t / 0.06, dt, {&bottom, &top, &sideMin, &sideMax});
    const double change = liner.storedVolume_m3(s) - liner.storedVolume_m3(before);
    const ps::LinerOilFlows &f = s.flows, &f0 = before.flows;
    throughput += std::abs(f.ringSource_m3 - f0.ringSource_m3) +
                  std::abs(f.splashSource_m3 - f0.splashSource_m3) +
                  std::abs(f.drainLoss_m3 - f0.drainLoss_m3) +
                  std::abs(f.sideLeakage_m3 - f0.sideLeakage_m3);
    ASSERT_NEAR(change, sum(s) - sum(before), 1e-12 * throughput + 1e-20) << "step " << step;
    ASSERT_TRUE((s.volume_m3 >= 0.0).all()) << "step " << step;
  }
  EXPECT_NEAR(liner.storedVolume_m3(s) - start, sum(s), 1e-12 * throughput);
  std::printf("[LinerOilFilm] balance over 4000 random steps: stored %.4e -> %.4e m^3, "
              "ring %+.3e, splash %+.3e, deficit %.3e, drain %.3e, film intake %+.3e m^3\n",
              start, liner.storedVolume_m3(s), s.flows.ringSource_m3, s.flows.splashSource_m3,
              s.flows.deficitSource_m3, s.flows.drainLoss_m3, s.flows.filmIntake_m3);
}

TEST(LinerOilFilm, RingMetersTheFilmOfTheRowsItPasses) {
  const ps::SkirtSideGrid g = side();
  ps::LinerOilParameters p;
  p.ringHeightAbovePin_m = 0.012;
  p.ringFilm_m = 0.7e-6;
  p.initialFilm_m = 3e-6;
  const ps::LinerOilFilm liner(g, p, 0.060, 0.140);
  ps::LinerOilState s = liner.makeInitialState(0.140);
  const Eigen::ArrayXd none = Eigen::ArrayXd::Zero(liner.columns());
  const Eigen::ArrayXd noSide = Eigen::ArrayXd::Zero(g.nY());
  // Down the stroke in 0.2 mm steps: the ring passes every row from 152 down to 72 mm.
  for (double Y = 0.140; Y > 0.060 + 1e-9; Y -= 0.0002)
    s = liner.advance(s, Y - 0.0002, -5.0, 100.0, 4e-5, {&none, &none, &noSide, &noSide});
  Eigen::ArrayXd film;
  liner.calcMeanFilmPerRow(s, film);
  int checked = 0;
  for (int m = 0; m < liner.rows(); ++m) {
    const double c = liner.rowHeight_m(m);
    if (c > 0.0725 && c < 0.1515) {  // rows the ring's lower edge crossed
      EXPECT_NEAR(film[m], 0.7e-6, 1e-18) << "row at " << c;
      ++checked;
    }
  }
  // Every row centre in the ring's path (79 mm at the row spacing), less one at either end.
  EXPECT_GE(checked, static_cast<int>(0.079 / liner.rowSpacing_m()) - 2);
}

// The skirt side with its liner, a centred round skirt of clearance c0 sliding down at speed
// v (U = -v up through the skirt), stepped in time without Simbody.
struct Sweep {
  double trailingFilm_m = 0.0, aheadFilm_m = 0.0;
};

Sweep sweep(double inletFilm_m, double c0_m, double share) {
  const ps::SkirtSideGrid g = side();
  ps::GapAssemblyParameters gp;
  gp.coldRadialClearance_m = c0_m;
  gp.travel.lowestPinHeight_m = 0.060;
  gp.travel.highestPinHeight_m = 0.140;
  ps::SkirtSideSettings settings;
  settings.lubrication.cavitation = lub::CavitationModel::MassConserving;
  settings.lubrication.solver.tolerance = 1e-10;
  ps::LinerOilParameters lp;
  lp.ringHeightAbovePin_m = 0.040;  // far above: it reaches no row the test reads
  lp.ringFilm_m = inletFilm_m;
  lp.initialFilm_m = inletFilm_m;
  lp.skirtShare = share;
  lp.maxFilm_m = 100e-6;
  cf::GreenwoodTrippParameters gt;
  gt.roughnessSurface1_m = 0.1e-6;
  gt.roughnessSurface2_m = 0.1e-6;
  ps::SkirtSideSolver solver(g, gp, std::make_shared<const lub::SmoothFlowFactors>(),
                             std::make_shared<const cf::GreenwoodTrippLaw>(gt),
                             cf::BoundaryFriction(cf::BoundaryFrictionParameters()), settings,
                             nullptr, ps::LinerOilFilm(g, lp, 0.060, 0.140));
  const ps::LinerOilFilm& liner = *solver.getLinerOilFilm();
  const double v = -5.0, dY = liner.rowSpacing_m() / 4.0, dt = dY / std::abs(v);
  // The film's oil moves at U / 2 through the skirt: its content is steady once the liner
  // has travelled two skirt lengths (40 mm); the rows read were left after 45 mm.
  const double Y0 = 0.120, travel = 0.055;
  ps::SkirtSideHistory history;
  ps::SkirtSideSolution solution;
  ps::SkirtSideConditions c;
  c.viscosity_Pas = 0.01;
  c.poseDerivativesWanted = false;
  const int steps = static_cast<int>(travel / dY);
  for (int k = 0; k <= steps; ++k) {
    ps::SkirtSideMotion motion;
    motion.pinHeight_m = Y0 + v * dt * k;
    motion.axialVelocity_mps = v;
    c.stepSinceHistory_s = k == 0 ? 0.0 : dt;
    solver.solve(motion, c, history, solution);
    history = solution.next;
  }
  // The rows the top edge left in the last 8 mm of the travel (the film steady), but not the
  // rows still next to it; the interior columns (the film's first and last columns hold the
  // ambient pressure: no oil crosses the skirt's edges there).
  const double Y = Y0 + v * dt * steps, top = Y + g.getSkirtTopHeight_m();
  Eigen::ArrayXd film;
  liner.calcFilm(history.liner, film);
  const int nc = liner.columns();
  Sweep r;
  int n = 0;
  for (int m = 0; m < liner.rows(); ++m) {
    const double height = liner.rowHeight_m(m);
    if (height > top + 2.0 * liner.rowSpacing_m() && height < top + 0.008) {
      r.trailingFilm_m += film.segment(nc * m + 1, nc - 2).sum();
      n += nc - 2;
    }
  }
  r.trailingFilm_m /= n;
  return r;
}

TEST(LinerOilTransport, StarvedSkirtLeavesItsInletFilmBehindLessTheSkirtsShare) {
  const double hIn = 1.0e-6, c0 = 6e-6, share = 0.3;  // 2 h_in < c0: starved
  const Sweep r = sweep(hIn, c0, share);
  std::printf("[LinerOilTransport] starved: left behind %.4f um, closed form %.4f um\n",
              r.trailingFilm_m * 1e6, (1.0 - share) * hIn * 1e6);
  EXPECT_NEAR(r.trailingFilm_m, (1.0 - share) * hIn, 0.01 * (1.0 - share) * hIn);
}

TEST(LinerOilTransport, FloodedSkirtLeavesHalfItsGapBehindLessTheSkirtsShare) {
  const double hIn = 8e-6, c0 = 6e-6, share = 0.5;  // 2 h_in > c0: flooded
  const Sweep r = sweep(hIn, c0, share);
  std::printf("[LinerOilTransport] flooded: left behind %.4f um, closed form %.4f um\n",
              r.trailingFilm_m * 1e6, (1.0 - share) * 0.5 * c0 * 1e6);
  EXPECT_NEAR(r.trailingFilm_m, (1.0 - share) * 0.5 * c0, 0.01 * (1.0 - share) * 0.5 * c0);
}

}  // namespace
