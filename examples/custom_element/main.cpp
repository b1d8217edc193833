// Example: a user-written liner element selected from a deck, through the io library.
//
// The program registers the liner model "spring_guide" (SpringLinerGuide.h: compliant
// springs and dampers instead of the ideal guide's constraints) and then reads the same
// engine deck twice: with --set liner.model=ideal_guide and with
// --set liner.model=spring_guide (the example deck's own liner, the lubricated skirt, is
// not read then: its keys are that model's data). Nothing else in the deck, the model or
// the program changes; the summary's side-force figures come from whichever liner the
// deck selects.
//
// Run: custom_element_example [DECK.yaml] [--set key.path=value]... [--out DIR]
//      (--out: the spring_guide run's result folder, which `pistondyn plot DIR` draws like
//      any run's: the figures come from the liner role's outputs, not the element's type)
//      (default deck: the gasoline example engine; the overrides apply to both runs, so
//      spring keys such as liner.tilt_damping_Nms_per_rad belong in the deck's liner
//      section only when it selects spring_guide)

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "SpringLinerGuide.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/RunDeck.h"

int main(int argc, char** argv) {
  using namespace pistondyn;
  std::string deckPath =
      std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/gasoline_1400_2000rpm/engine.yaml";
  // Two cycles: let the compliant piston settle, compare the last one. An explicit
  // integrator for both liners (the deck's linearly_implicit_bdf2 is for the stiff skirt
  // film and takes no constraints, which the ideal guide is made of).
  std::vector<std::string> overrides = {"simulation.integrator=rk_merson",
                                        "simulation.until_periodic=false", "simulation.cycles=2"};
  std::string outDir;  // the spring run's result folder ("": none)
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--set" && i + 1 < argc) {
      overrides.push_back(argv[++i]);
    } else if (arg == "--out" && i + 1 < argc) {
      outDir = argv[++i];
    } else {
      deckPath = arg;
    }
  }
  examples::registerSpringLinerGuide();

  io::EngineDeck idealDeck, springDeck;
  try {
    overrides.push_back("liner.model=ideal_guide");
    idealDeck = io::loadEngineDeck(deckPath, overrides);
    overrides.back() = "liner.model=spring_guide";
    springDeck = io::loadEngineDeck(deckPath, overrides);
  } catch (const io::DeckError& e) {
    std::fprintf(stderr, "custom element: the deck was rejected:\n%s\n", e.what());
    return 1;
  }

  plugin::ResultTableSink idealRows, springRows;
  const io::RunOutcome ideal = io::runDeck(idealDeck, "", {}, {&idealRows});
  const io::RunOutcome spring = io::runDeck(springDeck, outDir, {}, {&springRows});

  const auto a = idealRows.getTable().column("side_force_N");
  const auto b = springRows.getTable().column("side_force_N");
  const auto u = springRows.getTable().column("u_lat_um");
  double peak = 0, diff = 0, uMax = 0;
  for (std::size_t i = a.size() / 2; i < a.size(); ++i) {
    peak = std::max(peak, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
    uMax = std::max(uMax, std::abs(u[i]));
  }
  std::printf("custom element: liner.model %s vs %s\n", idealDeck.linerModel.c_str(),
              springDeck.linerModel.c_str());
  std::printf(
      "  last cycle: peak ideal side force %.1f N, max difference %.1f N, "
      "max lateral displacement %.2f um, %ld steps in %.3f s\n",
      peak, diff, uMax, spring.stats.integratorSteps, spring.stats.wallTime_s);
  std::printf("  summary side force max: ideal %.1f N, springs %.1f N\n",
              ideal.summary.liner->sideForceMax_N, spring.summary.liner->sideForceMax_N);
  // The springs carry the same load as the ideal guide up to their dynamics.
  return diff < 0.2 * peak ? 0 : 1;
}
