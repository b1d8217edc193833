// pistondyn new DIR --bore-mm B --stroke-mm S [--rod-mm L] [--speed-rpm N]
//               [--imep-kPa P | --motored | --pressure-table FILE] [--type TYPE] [...]
//
// A working engine deck folder from a handful of drawing and operating values
// (io/NewDeck.h): every other value an estimate for an engine of that type and size,
// marked EST with its rule in the deck's comments; a pressure table generated when none is
// given. All-or-nothing: a refused value or folder writes nothing.

#include <iostream>
#include <optional>
#include <sstream>

#include "Logging.h"
#include "Subcommand.h"
#include "pistondyn/io/NewDeck.h"

namespace pistondyn::app {
namespace {

// The exit code of a refused request: a value or folder of the command line is a usage
// error (2, as a refused --out); a pressure table that cannot be read, or a deck that does
// not pass its check, is bad input (1).
int getExitCode(io::NewDeckError::Kind kind) {
  switch (kind) {
    case io::NewDeckError::Kind::BadTable:
    case io::NewDeckError::Kind::FailedCheck:
      return kExitBadInput;
    case io::NewDeckError::Kind::BadValue:
    case io::NewDeckError::Kind::Conflict:
    case io::NewDeckError::Kind::Folder:
      return kExitUsage;
  }
  return kExitUsage;
}

// `text` as one shell word (for the deck's header: the command that made it).
std::string quoteForShell(const std::string& text) {
  if (!text.empty() && text.find_first_of(" \t\n'\"\\$`*?[]{}()<>|&;#~") == std::string::npos)
    return text;
  std::string out = "'";
  for (const char c : text)
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The last component of the folder's path ("decks/my_engine/" gives "my_engine").
std::string getFolderName(const std::string& folder) {
  std::string name = folder;
  while (name.size() > 1 && name.back() == '/')
    name.pop_back();
  const std::size_t slash = name.rfind('/');
  return slash == std::string::npos ? name : name.substr(slash + 1);
}

// Shortest text of a number as given ("74.5", "2000").
std::string numberText(double x) {
  std::ostringstream s;
  s.precision(10);
  s << x;
  return s.str();
}

class NewCommand final : public Subcommand {
 public:
  explicit NewCommand(CLI::App& program)
      : Subcommand(program.add_subcommand(
            "new", "write a working engine deck folder from the bore, the stroke and a few "
                   "operating values; every other value an estimate marked EST with its rule")) {
    app_->add_option("DIR", folder_,
                     "the deck folder to make (must not exist, or be empty): engine.yaml, "
                     "skirt_profile.csv and the cylinder pressure table")
        ->required()
        ->type_name("DIR");
    addDrawingOptions();
    addOperatingOptions();
    addLinerOptions();
    addLogLevelOption(*app_, logLevel_);
    app_->set_help_flag("-h,--help", "print this help and exit");
    app_->footer(
        "Every value not given is estimated for an engine of the --type and size (ratios to\n"
        "the bore, stroke and rod, most of them scaled from the example decks) and marked\n"
        "EST with its rule in engine.yaml; values given are marked [U]. The deck is checked\n"
        "as `pistondyn check` checks it before anything is written. Then:\n"
        "  pistondyn run DIR/engine.yaml --out DIR/results --fidelity preview\n"
        "Exit codes: 0 written; 1 the pressure table cannot be read, or the deck made does\n"
        "not pass its check; 2 a bad option or value, or a folder that exists and is not\n"
        "empty; 3 writing failed. Nothing is written unless the exit code is 0.");
  }

  int execute() override {
    setUpLogging(logLevel_);
    io::NewDeckRequest request = makeRequest();
    try {
      // The folder first: a refused folder costs no table generation.
      if (const std::string problem = io::findNewDeckFolderProblem(folder_); !problem.empty())
        throw io::NewDeckError(folder_ + " " + problem, io::NewDeckError::Kind::Folder);
      const io::NewDeck deck = io::makeNewDeck(request);
      io::writeNewDeck(deck, folder_);
      printSummary(deck);
    } catch (const io::NewDeckError& e) {
      std::cerr << "pistondyn new: " << e.what() << "; nothing was written\n";
      return getExitCode(e.getKind());
    } catch (const std::runtime_error& e) {
      std::cerr << "pistondyn new: " << e.what() << "; nothing was written\n";
      return kExitFailed;
    }
    return kExitOk;
  }

 private:
  void addDrawingOptions() {
    app_->add_option("--bore-mm", request_.bore_mm, "cylinder bore [mm]")
        ->required()
        ->type_name("MM");
    app_->add_option("--stroke-mm", request_.stroke_mm, "stroke [mm]")
        ->required()
        ->type_name("MM");
    app_->add_option("--rod-mm", rod_mm_,
                     "connecting-rod length, big-end to small-end centre [mm] (default: "
                     "estimated from the stroke by the type's L/r)")
        ->type_name("MM");
    app_->add_option("--compression-ratio", compressionRatio_,
                     "(swept + clearance volume) / clearance volume (default: the type's)")
        ->type_name("RATIO");
    app_->add_option("--pin-offset-mm", pinOffset_mm_,
                     "pin offset, + towards the thrust side [mm] (default: the type's)")
        ->type_name("MM");
    app_->add_option("--type", type_,
                     "the kind of engine whose estimates fill the deck (default: gasoline)")
        ->check(CLI::IsMember(io::getEngineTypeNames()))
        ->type_name("TYPE");
    app_->add_option("--name", name_,
                     "engine.name, which labels the results (default: the folder's name)")
        ->type_name("TEXT");
  }

  void addOperatingOptions() {
    app_->add_option("--speed-rpm", speed_rpm_, "constant crank speed [rpm] (default: the type's)")
        ->type_name("RPM");
    auto* imep = app_->add_option("--imep-kPa", imep_kPa_,
                                  "net imep the generated fired pressure table is scaled to "
                                  "[kPa] (default: the type's part load)")
                     ->type_name("KPA");
    auto* motored = app_->add_flag("--motored", request_.motored,
                                   "generate a motored pressure table (no combustion)");
    auto* table = app_->add_option("--pressure-table", request_.pressureTableFile,
                                   "a cylinder-pressure table to copy into the deck instead of "
                                   "generating one (CSV: crank_angle_deg and the pressure with "
                                   "its unit, 0 deg = firing TDC)")
                      ->type_name("FILE");
    // Listed here so that --help shows them; makeNewDeck() refuses them too, with the reason.
    imep->excludes(motored);
    table->excludes(imep);
    table->excludes(motored);
  }

  void addLinerOptions() {
    app_->add_option("--clearance-um", clearance_um_,
                     "cold radial skirt-liner clearance [um] (default: the type's share of "
                     "the bore)")
        ->type_name("UM");
    app_->add_option("--oil-grade", oilGrade_, "SAE grade of the oil (default: the type's)")
        ->type_name("GRADE");
    app_->add_option("--oil-temperature-degC", oilTemperature_degC_,
                     "the oil film's temperature [degC] (default: 105 fired, 40 motored)")
        ->type_name("DEGC");
  }

  io::NewDeckRequest makeRequest() const {
    io::NewDeckRequest r = request_;
    r.name = name_ ? *name_ : getFolderName(folder_);
    r.type = *io::parseEngineType(type_);  // CLI11 has checked it is one of the names
    r.conrodLength_mm = rod_mm_;
    r.compressionRatio = compressionRatio_;
    r.pinOffset_mm = pinOffset_mm_;
    r.speed_rpm = speed_rpm_;
    r.imep_kPa = imep_kPa_;
    r.coldRadialClearance_um = clearance_um_;
    r.oilGrade = oilGrade_;
    r.oilTemperature_degC = oilTemperature_degC_;
    r.commandLine = describeCommand();
    return r;
  }

  // The command as given (its options in a fixed order), for the deck's header.
  std::string describeCommand() const {
    std::string c = "pistondyn new " + quoteForShell(folder_);
    const auto add = [&c](const char* option, const std::optional<double>& v) {
      if (v)
        c += std::string(" ") + option + " " + numberText(*v);
    };
    if (type_ != "gasoline")
      c += " --type " + type_;
    if (name_)
      c += " --name " + quoteForShell(*name_);
    add("--bore-mm", request_.bore_mm);
    add("--stroke-mm", request_.stroke_mm);
    add("--rod-mm", rod_mm_);
    add("--compression-ratio", compressionRatio_);
    add("--pin-offset-mm", pinOffset_mm_);
    add("--speed-rpm", speed_rpm_);
    add("--imep-kPa", imep_kPa_);
    if (request_.motored)
      c += " --motored";
    if (!request_.pressureTableFile.empty())
      c += " --pressure-table " + quoteForShell(request_.pressureTableFile);
    add("--clearance-um", clearance_um_);
    if (oilGrade_)
      c += " --oil-grade " + quoteForShell(*oilGrade_);
    add("--oil-temperature-degC", oilTemperature_degC_);
    return c;
  }

  void printSummary(const io::NewDeck& deck) const {
    std::cout << "pistondyn new: wrote " << folder_ << "/ (";
    for (std::size_t i = 0; i < deck.files.size(); ++i)
      std::cout << (i ? ", " : "") << deck.files[i].name;
    std::cout << ")\n";
    std::cout.precision(4);
    std::cout << "  pressure table: imep " << deck.imep_kPa << " kPa, peak "
              << deck.peakPressure_bar << " bar at " << deck.peakPressureAngle_deg << " deg\n";
    std::cout << "  " << deck.estimated.size()
              << " values estimated (marked EST with their rule in engine.yaml):";
    for (const std::string& key : deck.estimated)
      std::cout << " " << key;
    std::cout << "\n";
    for (const std::string& note : deck.notes)
      std::cout << "  note: " << note << "\n";
    std::cout << "  next: pistondyn run " << folder_ << "/engine.yaml --out " << folder_
              << "/results --fidelity preview\n";
  }

  std::string folder_, type_ = "gasoline", logLevel_ = "warn";
  io::NewDeckRequest request_;
  std::optional<std::string> name_, oilGrade_;
  std::optional<double> rod_mm_, compressionRatio_, pinOffset_mm_, speed_rpm_, imep_kPa_;
  std::optional<double> clearance_um_, oilTemperature_degC_;
};

}  // namespace

std::unique_ptr<Subcommand> addNewCommand(CLI::App& program) {
  return std::make_unique<NewCommand>(program);
}

}  // namespace pistondyn::app
