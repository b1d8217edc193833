// A user's own program on the installed pistondyn::io: run a deck, write its results.
//   run_deck DECK.yaml OUT_DIR [key.path=value]...
#include <cstdio>
#include <string>
#include <vector>

#include <pistondyn/io/RunDeck.h>

int main(int argc, char** argv) {
  if (argc < 3)
    return 2;
  const std::vector<std::string> overrides(argv + 3, argv + argc);
  const auto deck = pistondyn::io::loadEngineDeck(argv[1], overrides);
  const auto outcome = pistondyn::io::runDeck(deck, argv[2]);
  std::printf("run_deck: %s: %ld rows, mean crank torque %.4f N m, peak side force %.1f N\n",
              deck.engine.name.c_str(), outcome.rows, outcome.summary.meanCrankTorque_Nm,
              outcome.summary.liner->sideForceMax_N);
  return 0;
}
