// pistondyn keys [--markdown]
//
// Every deck key with its unit, default, valid and plausible range and meaning, from the
// key tables the deck readers use (io/DeckKeys.h): the reference an installed program
// carries with it. --markdown prints the block README.md holds (a test compares them).
// (Its --help names no README: an installed prefix has the program, not the source tree.)

#include <iostream>

#include "Subcommand.h"
#include "pistondyn/io/DeckReference.h"

namespace pistondyn::app {
namespace {

class KeysCommand final : public Subcommand {
 public:
  explicit KeysCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "keys",
            "list every deck key with its unit, default, valid and plausible range "
            "(the deck reference)")) {
    app_->add_flag(
        "--markdown", markdown_,
        "print the reference as Markdown tables, as the project's documentation holds it "
        "(default: plain text)");
    app_->set_help_flag("-h,--help", "print this help and exit");
    app_->footer(
        "A value outside its valid range is an error; one outside its plausible range (the\n"
        "engines pistondyn is for) too, naming the unit slip it suggests, unless the deck\n"
        "lists the key under checks.allow_implausible. Exit code 0.");
  }

  int execute() override {
    std::cout << (markdown_ ? io::makeDeckReferenceMarkdown() : io::makeDeckReferenceText());
    return kExitOk;
  }

 private:
  bool markdown_ = false;
};

}  // namespace

std::unique_ptr<Subcommand> addKeysCommand(CLI::App& program) {
  return std::make_unique<KeysCommand>(program);
}

}  // namespace pistondyn::app
