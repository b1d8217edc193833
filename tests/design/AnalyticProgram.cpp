// The pistondyn program with the TEST-ONLY analytic liner (tests/support/AnalyticTestLiner.h)
// registered as "analytic_test": the design loop's tests run `optimize`, `fit` and
// `propagate` through the real program on a model whose answers are known in closed form.
// Not installed, never part of the shipped program.

#include "AnalyticTestLiner.h"
#include "Subcommand.h"

int main(int argc, char** argv) {
  pistondyn_test::registerAnalyticTestLiner(pistondyn::io::LinerRegistry::getGlobal());
  return pistondyn::app::runProgram(argc, argv);
}
