#pragma once
/// \file
/// A working engine deck from a handful of drawing and operating values (`pistondyn new`):
/// the values given are written as they are, marked [U]; every other engine value is an
/// estimate for an engine of that type and size, marked EST with its rule in the deck's
/// comment; the skirt profile table is written from the example decks' scaling rule and a
/// cylinder-pressure table is generated (mbd_models/SingleZonePressureModel.h: fired and
/// scaled to the imep, or motored) unless one is given. README.md, "A deck from a drawing
/// (`pistondyn new`)", lists every rule.
///
/// makeNewDeck() only computes (the files' names and text); writeNewDeck() writes them
/// all-or-nothing: into a temporary folder beside the target, checked by loadEngineDeck(),
/// then renamed into place.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace pistondyn::io {

/// The kind of engine whose estimates fill the deck.
enum class EngineType {
  PassengerCarGasoline,  ///< "gasoline": the gasoline example's ratios (EA211 bore/stroke)
  SmallAirCooled,        ///< "small-air-cooled": the Briggs & Stratton example's ratios
  Diesel,                ///< "diesel": passenger-car and light-duty diesel ratios
};

/// "gasoline", "small-air-cooled", "diesel" (the command line's names).
const char* getEngineTypeName(EngineType type);
/// The type of a command-line name; nullopt if there is none.
std::optional<EngineType> parseEngineType(const std::string& name);
/// Every command-line name, in the enum's order.
std::vector<std::string> getEngineTypeNames();

/// What the user gives. Every optional value left empty is estimated (or defaulted).
struct NewDeckRequest {
  std::string name;  ///< engine.name (--name): not empty, no control characters
  EngineType type = EngineType::PassengerCarGasoline;  ///< whose estimates
  double bore_mm = 0.0;    ///< cylinder bore [mm], required
  double stroke_mm = 0.0;  ///< stroke [mm], required
  std::optional<double> conrodLength_mm;    ///< rod length [mm]; L/r at least 2.5
  std::optional<double> compressionRatio;   ///< (V_d + V_c)/V_c
  std::optional<double> pinOffset_mm;       ///< + towards thrust [mm]
  std::optional<double> speed_rpm;          ///< constant crank speed [rpm]
  std::optional<double> imep_kPa;           ///< fired: the generated table's net imep [kPa]
  bool motored = false;                     ///< generate a motored table (no combustion)
  std::string pressureTableFile;            ///< a table to copy instead ("" : generate)
  std::optional<double> coldRadialClearance_um;  ///< skirt-liner radial clearance [um]
  std::optional<std::string> oilGrade;           ///< a grade of lubrication/OilGrades.h
  std::optional<double> oilTemperature_degC;     ///< the film's temperature [degC]
  std::string commandLine;  ///< the command that made the deck, for its header ("" : none)
};

/// A refused request: the message names the option and what is expected.
class NewDeckError : public std::invalid_argument {
 public:
  /// What was refused.
  enum class Kind {
    BadValue,     ///< a value is not usable (not positive, implausible)
    BadTable,     ///< the given pressure table cannot be read or is not a pressure table
    Conflict,     ///< two choices that exclude each other (an imep and a table)
    Folder,       ///< the output folder (exists and is not empty, no parent, not writable)
    FailedCheck,  ///< the deck made does not pass its own check
  };
  /// The message and what was refused.
  explicit NewDeckError(const std::string& what, Kind kind = Kind::BadValue)
      : std::invalid_argument(what), kind_(kind) {}
  Kind getKind() const { return kind_; }  ///< what was refused

 private:
  Kind kind_;
};

/// One file of a new deck folder.
struct NewDeckFile {
  std::string name;  ///< file name in the folder
  std::string text;  ///< its content
};

/// A new deck: its files (engine.yaml first) and what the command tells the user.
struct NewDeck {
  std::vector<NewDeckFile> files;      ///< engine.yaml, skirt_profile.csv, the pressure table
  std::vector<std::string> estimated;  ///< the keys filled with an estimate (EST), in order
  std::vector<std::string> notes;      ///< warnings worth printing (a bore outside the type's)
  double imep_kPa = 0.0;               ///< of the pressure table (generated: its target)
  double peakPressure_bar = 0.0;       ///< largest knot of the pressure table
  double peakPressureAngle_deg = 0.0;  ///< its crank angle
};

/// Computes the deck. Throws NewDeckError when a value is not positive, implausible for an
/// engine (bore and stroke outside the deck's plausible ranges, stroke/bore outside
/// [0.4, 2.5], L/r outside [2.5, 8], a mean piston speed above 30 m/s, an imep outside
/// (0, 3000] kPa), when the choices conflict (an imep or --motored with a table, an imep
/// with --motored), or when the given pressure table cannot be read (the message names the
/// file and line).
NewDeck makeNewDeck(const NewDeckRequest& request);

/// Why `folder` cannot receive a new deck, or "" if it can: it must not exist, or be an
/// empty folder, and its parent must be an existing folder this process may write in.
std::string findNewDeckFolderProblem(const std::string& folder);

/// Writes `deck` into `folder` all-or-nothing: the files go into a temporary folder beside
/// it, the deck is loaded and checked there (loadEngineDeck: a deck that does not pass
/// `pistondyn check` is never written), and the folder is renamed into place. Throws
/// NewDeckError if the folder is refused (findNewDeckFolderProblem) or the deck fails its
/// check, std::runtime_error if writing fails; `folder` is then as it was and no temporary
/// folder is left. Checks common::throwIfCancelled() before the rename.
void writeNewDeck(const NewDeck& deck, const std::string& folder);

}  // namespace pistondyn::io
