// pistondyn check DECK.yaml [--set key.path=value]... [--fidelity full|preview]
//                 [--log-level LEVEL]

#include <iostream>

#include "CommandSupport.h"
#include "Logging.h"
#include "Subcommand.h"

namespace pistondyn::app {
namespace {

class CheckCommand final : public Subcommand {
 public:
  explicit CheckCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "check", "read and check a deck and its pressure table; simulates nothing")) {
    app_->add_option("DECK", deck_, "engine deck (YAML; every key names its unit, e.g. bore_mm)")
        ->required()
        ->type_name("DECK.yaml");
    addSetOption(*app_, overrides_);
    addFidelityOption(*app_, fidelity_);
    addLogLevelOption(*app_, logLevel_);
    app_->set_help_flag("-h,--help", "print this help and exit");
    app_->footer(deckHelpFooter());
  }

  int execute() override {
    setUpLogging(logLevel_);
    const auto deck = loadDeckOrReport(deck_, overrides_, toFidelity(fidelity_));
    if (!deck)
      return kExitBadInput;
    std::cout << "pistondyn: " << deck_
              << " is valid (imep from its pressure table: " << io::calcDeckImep_Pa(*deck) / 1e3
              << " kPa)\n";
    if (!deck->fidelityNote.empty())
      std::cout << "  fidelity preview: " << deck->fidelityNote << "\n";
    return kExitOk;
  }

 private:
  std::string deck_, logLevel_ = "warn", fidelity_ = "full";
  std::vector<std::string> overrides_;
};

}  // namespace

std::unique_ptr<Subcommand> addCheckCommand(CLI::App& program) {
  return std::make_unique<CheckCommand>(program);
}

}  // namespace pistondyn::app
