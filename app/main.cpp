// The pistondyn program's entry point; the program itself is runProgram() (Program.cpp),
// which test programs reuse with models of their own registered first.

#include "Subcommand.h"

int main(int argc, char** argv) {
  return pistondyn::app::runProgram(argc, argv);
}
