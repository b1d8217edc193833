// Grid convergence of the starved skirt (issue 10's criterion "doubling the film grid in both
// directions changes fmep by < 2 %"), on the passenger-car example exactly as its deck
// stands (but for its stepper: BDF2 at 0.25 deg, the setting the test was written with):
// partially flooded (its supply film), hot shapes, mass-conserving film, the deck's grid
// (64 x 48 per side), three cycles from the deck's start, last cycle's fmep, against the
// same run on the doubled grid (128 x 96). The grid is read from the deck, so the test
// follows a change of the default.
//
// History: with the nodal-mean faces and the upwind fill fraction (the keys' defaults) it
// failed, -8.4 % (3.208 -> 2.937 kPa): the circumferential spacing hardly matters, the axial
// spacing converged at first order, because two discretisations along y were first order,
// the fill fraction's upwind transport and the nodal-mean faces at a contact's rim. The deck
// now takes the linear-gap faces and the limited second-order fill-fraction flux
// (plugin/README.md, "Known limitations").
// Measured 2026-12-05: 2.8613 -> 2.8065 kPa, -1.91 % (374 s + 698 s on a shared machine).
// Label `slow` (about 18 min on one core): outside the default run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "SkirtTestDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace {

using namespace pistondyn;
namespace ts = pistondyn::testsupport;

struct Outcome {
  double fmep_kPa = 0.0;
  double asperityWork_J = 0.0, frictionWork_J = 0.0;  // last cycle
  double wall_s = 0.0;
};

// The deck as it stands (serial sides: one core per run), on nPhi x nY (0: the deck's grid).
plugin::LubricatedSkirtParameters deckParameters(int nPhi, int nY) {
  std::vector<std::string> grid;
  if (nPhi > 0)
    grid = {"liner.grid.nodes_circumferential=" + std::to_string(nPhi),
            "liner.grid.nodes_axial=" + std::to_string(nY)};
  plugin::LubricatedSkirtParameters p =
      ts::deckSkirtParameters(io::loadEngineDeck(ts::gasolineDeckPath(), grid));
  p.parallelSides = false;
  return p;
}

// Integral over time of |F v| between rows k - 1 and k (trapezoid) [J].
double workBetweenRows(const std::vector<double>& time, const std::vector<double>& force,
                       const std::vector<double>& speed, std::size_t k) {
  return 0.5 * (time[k] - time[k - 1]) *
         (std::abs(force[k] * speed[k]) + std::abs(force[k - 1] * speed[k - 1]));
}

Outcome run(const plugin::LubricatedSkirtParameters& p) {
  ts::SkirtModel m = ts::makeGasolineSkirtModel(p.grid.nPhi, p.grid.nY, &p);
  plugin::SimulationSettings s = ts::bdf2StepperSettings(3);
  s.untilPeriodic = false;
  plugin::CycleSimulation sim(*m.model, s);
  plugin::ResultTableSink table;
  sim.run({&table});
  const plugin::ResultTable t = table.releaseTable();
  const auto angle = t.column("crank_angle_deg");
  const auto asperity = t.column("asperity_friction_N");
  const auto friction = t.column("friction_force_N");
  const auto speed = t.column("piston_vy_mps");
  const auto time = t.column("time_s");
  Outcome o;
  o.fmep_kPa = sim.getStats().cycleFmep_Pa.back() / 1e3;
  o.wall_s = sim.getStats().wallTime_s;
  // |F v| over the last 720 deg of rows: the asperity share of the work.
  for (std::size_t k = 1; k < angle.size(); ++k) {
    if (angle[k] <= angle.back() - 720.0) continue;
    o.asperityWork_J += workBetweenRows(time, asperity, speed, k);
    o.frictionWork_J += workBetweenRows(time, friction, speed, k);
  }
  return o;
}

TEST(StarvedSkirtGrid, DoublingTheDecksGridChangesFmepByLessThanTwoPercent) {
  const plugin::LubricatedSkirtParameters deck = deckParameters(0, 0);
  ASSERT_TRUE(std::isfinite(deck.supplyFilm.constant_m) || !deck.supplyFilm.thickness_m.empty())
      << "the deck's skirt is no longer partially flooded";
  const int nPhi = deck.grid.nPhi, nY = deck.grid.nY;
  const Outcome base = run(deck);
  const Outcome fine = run(deckParameters(2 * nPhi, 2 * nY));
  const double change = (fine.fmep_kPa - base.fmep_kPa) / base.fmep_kPa;
  std::printf(
      "[StarvedSkirtGrid] third cycle fmep %.4f kPa (%d x %d, %.0f s) -> %.4f kPa (%d x %d, "
      "%.0f s): %+.2f %%; asperity work %.4f of %.4f J -> %.4f of %.4f J\n",
      base.fmep_kPa, nPhi, nY, base.wall_s, fine.fmep_kPa, 2 * nPhi, 2 * nY, fine.wall_s,
      100.0 * change, base.asperityWork_J, base.frictionWork_J, fine.asperityWork_J,
      fine.frictionWork_J);
  EXPECT_LT(std::abs(change), 0.02);
}

}  // namespace
