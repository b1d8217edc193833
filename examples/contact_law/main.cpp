// Example: write your own force element's physics - here the asperity contact law of the
// lubricated skirt - and swap it in.
//
//   1. Write the law: a subclass of contact_forces::AsperityContactLaw (PowerLawContactLaw.h:
//      pressure, its slope and the real-area fraction as functions of the nominal gap, and
//      the composite roughness sigma it works with).
//   2. Read the engine deck as usual (io::loadEngineDeck), take the skirt parameters the
//      deck's factory read (LubricatedSkirtElement::getParameters()), set
//      LubricatedSkirtParameters::contactLaw to your law, and replace the deck's liner
//      element in the model (PistonAssemblyModel::replaceElement). Nothing else changes:
//      the film, the gap, the friction and the outputs use whatever law they are given.
//      The law's sigma must be the deck's roughness pair (the element checks it: one
//      roughness for the flow factors and the contact).
//   3. Run the model (io::runModel) and read the summary, as for any deck.
//
// The check this program makes (it is the test example_contact_law): the law written here
// from the published formulas must give what the library's own implementation of the same
// fit gives (GreenwoodTrippLaw with TailIntegralModel::PowerLawFit) - node by node, and
// for a whole starved-skirt cycle of the gasoline example (fmep, asperity share of the
// friction work, minimum h/sigma), while the element's default law (exact Greenwood-Tripp
// integrals) gives another cycle - so the comparison sees which law the element used. The
// same formulas with their terms grouped the same way give the same doubles; the starved
// cycle must then be the same to the last bit (it amplifies any difference: rounding-level
// changes of the contact pressure move its fmep by percents through the step control, the
// starved skirt not being converged in the step, plugin/README.md). A coarse 16 x 12 grid,
// one cycle: a few seconds.
//
// Run: contact_law_example [DECK.yaml] [--set key.path=value]...

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "PowerLawContactLaw.h"
#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/RunDeck.h"
#include "pistondyn/plugin/LubricatedSkirtElement.h"

namespace {

using namespace pistondyn;

double relative(double a, double b) {
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300});
}

// The deck's skirt parameters (as its factory read them from the deck); throws
// std::invalid_argument when the deck's liner is not the lubricated skirt.
plugin::LubricatedSkirtParameters skirtParameters(const io::EngineDeck& deck) {
  const auto model = io::buildModel(deck);
  return model->getElementAs<plugin::LubricatedSkirtElement>("lubricated_skirt").getParameters();
}

// Runs the deck with the skirt of parameters `p` (no files written).
io::RunOutcome runWith(const io::EngineDeck& deck, const plugin::LubricatedSkirtParameters& p) {
  auto model = io::buildModel(deck);
  model->replaceElement("lubricated_skirt", std::make_unique<plugin::LubricatedSkirtElement>(p));
  return io::runModel(deck, *model, "");
}

}  // namespace

int main(int argc, char** argv) {
  std::string deckPath =
      std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/gasoline_1400_2000rpm/engine.yaml";
  // The deck's partially flooded skirt (the asperities carry load), one cycle on a coarse
  // grid so that the example runs in seconds.
  std::vector<std::string> overrides = {
      "liner.grid.nodes_circumferential=16", "liner.grid.nodes_axial=12",
      "simulation.until_periodic=false", "simulation.cycles=1", "simulation.output_step_deg=2"};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--set" && i + 1 < argc)
      overrides.push_back(argv[++i]);
    else
      deckPath = arg;
  }
  io::EngineDeck deck;
  plugin::LubricatedSkirtParameters base;
  try {
    deck = io::loadEngineDeck(deckPath, overrides);
    base = skirtParameters(deck);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "contact law example: %s\n", e.what());
    return 1;
  }

  // The library's implementation of the same fit: Greenwood-Tripp with the power-law tails.
  contact_forces::GreenwoodTrippParameters gt = base.asperity;
  gt.roughnessSurface1_m = base.roughness.rq1_m;
  gt.roughnessSurface2_m = base.roughness.rq2_m;
  gt.tailModel = contact_forces::TailIntegralModel::PowerLawFit;
  const contact_forces::GreenwoodTrippLaw library(gt);

  // 1. The user's law, from the same surface data.
  examples::PowerLawContactParameters mine;
  mine.compositeSigma_m = std::hypot(base.roughness.rq1_m, base.roughness.rq2_m);
  mine.effectiveModulus_Pa = library.effectiveModulus_Pa();
  mine.roughnessParameter = gt.roughnessParameter;
  mine.sigmaOverBeta = gt.sigmaOverBeta;
  const auto law = std::make_shared<const examples::PowerLawContactLaw>(mine);

  // Node by node over h/sigma from -2 to 5.
  double worstPressure = 0.0, worstSlope = 0.0, worstArea = 0.0;
  for (int k = 0; k <= 700; ++k) {
    const double h = (-2.0 + 0.01 * k) * mine.compositeSigma_m;
    const contact_forces::ContactNodeState a = law->calcNode(h), b = library.calcNode(h);
    if (b.pressure_Pa > 0.0) {
      worstPressure = std::max(worstPressure, relative(a.pressure_Pa, b.pressure_Pa));
      worstSlope = std::max(worstSlope, relative(a.dPressure_dGap_PaPerM, b.dPressure_dGap_PaPerM));
      worstArea = std::max(worstArea, relative(a.realAreaFraction, b.realAreaFraction));
    } else if (a.pressure_Pa != 0.0) {
      worstPressure = 1.0;  // contact where the fit has none
    }
  }
  std::printf("contact law example: %s vs the library's %s with power-law tails\n", law->name(),
              library.name());
  std::printf(
      "  node by node, h/sigma -2 .. 5 (701 gaps): largest relative difference %.2e "
      "(pressure), %.2e (slope), %.2e (area)\n",
      worstPressure, worstSlope, worstArea);

  // 2. and 3. The skirt with the user's law, and with the library's fit, for one cycle.
  plugin::LubricatedSkirtParameters withMine = base, withLibrary = base;
  withMine.contactLaw = law;
  withLibrary.asperity.tailModel = contact_forces::TailIntegralModel::PowerLawFit;
  io::RunOutcome a, b;
  try {
    a = runWith(deck, withMine);
    b = runWith(deck, withLibrary);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "contact law example: the run failed: %s\n", e.what());
    return 1;
  }
  const auto& fa = *a.summary.liner;
  const auto& fb = *b.summary.liner;
  const double fmepA = a.stats.cycleFmep_Pa.back(), fmepB = b.stats.cycleFmep_Pa.back();
  const double shareA = *fa.asperityFrictionWork_J / *fa.frictionWork_J;
  const double shareB = *fb.asperityFrictionWork_J / *fb.frictionWork_J;
  std::printf("  one cycle, %s, %dx%d grid:\n", deck.engine.name.c_str(), base.grid.nPhi,
              base.grid.nY);
  std::printf("    fmep %.6f kPa (user law) vs %.6f kPa (library fit), rel. %.2e\n", fmepA / 1e3,
              fmepB / 1e3, relative(fmepA, fmepB));
  std::printf("    asperity share of the friction work %.6f vs %.6f\n", shareA, shareB);
  std::printf("    min h/sigma thrust %.6f vs %.6f, anti-thrust %.6f vs %.6f\n",
              *fa.minGapOverSigmaThrust, *fb.minGapOverSigmaThrust, *fa.minGapOverSigmaAntiThrust,
              *fb.minGapOverSigmaAntiThrust);
  // The element's own default law, the exact Greenwood-Tripp integrals, for contrast.
  io::RunOutcome c;
  try {
    c = runWith(deck, base);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "contact law example: the run failed: %s\n", e.what());
    return 1;
  }
  const double fmepC = c.stats.cycleFmep_Pa.back();
  std::printf("    (the exact Greenwood-Tripp law: fmep %.6f kPa, rel. %.2e)\n", fmepC / 1e3,
              relative(fmepA, fmepC));
  // The same formulas with the same grouping: the same doubles, node by node and over the
  // cycle.
  const bool nodesAgree = worstPressure == 0.0 && worstSlope == 0.0 && worstArea == 0.0;
  const bool runsAgree = fmepA == fmepB && shareA == shareB &&
                         *fa.minGapOverSigmaThrust == *fb.minGapOverSigmaThrust &&
                         *fa.minGapOverSigmaAntiThrust == *fb.minGapOverSigmaAntiThrust;
  // The law must carry load in this run, and the element must have used it (the default
  // law's cycle differs), or the comparison says nothing.
  const bool meaningful = shareA > 0.01 && relative(fmepA, fmepC) > 1e-3;
  std::printf("  %s\n", nodesAgree && runsAgree && meaningful ? "agree" : "DISAGREE");
  return nodesAgree && runsAgree && meaningful ? 0 : 1;
}
