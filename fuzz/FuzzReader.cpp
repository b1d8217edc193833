// One libFuzzer target per line of Readers.def: PISTONDYN_FUZZ_TARGET names the line this
// executable runs. Each input is written to a file and read through io's real loading path
// (the file on disk, its checks, its messages); the reader must either return a result
// that passes checkResult() below or throw the line's rejection type. Anything else — any
// other exception, a crash, a leak, undefined behaviour (the build has ASan and UBSan), a
// hang (libFuzzer's -timeout) — is a finding: the input is saved as a reproducer.
//
// Input format: the file's bytes, optionally followed by a line "#%set" and then one
// --set assignment per line (used by the deck target; other readers ignore them). '#'
// starts a comment in YAML and CSV, so seeds stay valid files up to that line.
//
// Built without PISTONDYN_FUZZ, ReplayMain.cpp drives the same entry point over the seed
// corpus and the committed reproducers (fuzz/regressions/), as ordinary CTest tests.

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <typeinfo>
#include <variant>
#include <vector>

#include "PistondynIoHeaders.h"  // every public header of pistondyn::io (generated)

#ifndef PISTONDYN_FUZZ_TARGET
#error "PISTONDYN_FUZZ_TARGET must name a line of Readers.def"
#endif

namespace {

namespace fs = std::filesystem;
namespace io = pistondyn::io;

// A broken promise of a reader: report it and abort, so that libFuzzer keeps the input.
[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "\npistondyn fuzz (%s): %s\n", PISTONDYN_FUZZ_TARGET, what.c_str());
  std::fflush(stderr);
  std::abort();
}

void require(bool ok, const std::string& what) {
  if (!ok)
    fail(what);
}

// ---- checks of what a reader accepted ---------------------------------------------------

// Every quantity io knows (the enum has no "last" member; getUnits() is empty beyond it).
std::vector<io::Quantity> allQuantities() {
  std::vector<io::Quantity> out;
  for (int q = 0; !io::getUnits(static_cast<io::Quantity>(q)).empty(); ++q)
    out.push_back(static_cast<io::Quantity>(q));
  return out;
}

// CsvTable.h: a header, rows as wide as it, every field finite; SI columns finite too.
void checkResult(const io::CsvTable& t) {
  require(!t.columns.empty(), "a table without columns was accepted");
  require(t.rowLines.size() == t.rows.size(), "rowLines and rows differ in length");
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    require(t.rows[i].size() == t.columns.size(), "row " + t.where(i) + " has the wrong width");
    for (const double v : t.rows[i])
      require(std::isfinite(v), "a non-finite value was accepted at " + t.where(i));
  }
  static const std::vector<io::Quantity> kQuantities = allQuantities();
  for (const std::string& name : t.columns) {
    require(t.hasColumn(name) && t.columns[t.columnIndex(name)] == name, "column lookup");
    require(t.getColumn(name).size() == t.rows.size(), "getColumn length");
    for (const io::Quantity q : kQuantities) {
      if (!io::findUnitSuffix(name, q))
        continue;
      try {
        for (const double v : t.getColumnSI(name, q))
          require(std::isfinite(v), "getColumnSI('" + name + "') returned a non-finite value");
      } catch (const io::DeckError&) {
        // a value that is finite as written but not in SI: rejected naming the line
      }
    }
  }
  // The probe name is not in the header (the fuzzer learns it from the comparison and
  // writes it there: not a finding).
  const std::string probe = "\x01no such column";
  if (std::find(t.columns.begin(), t.columns.end(), probe) != t.columns.end())
    return;
  try {
    (void)t.columnIndex(probe);
    fail("columnIndex found a column that is not there");
  } catch (const io::DeckError&) {
  }
}

// CylinderPressureCurve.h: positive, finite pressure and finite slope at every angle,
// a finite imep on a plausible engine.
void checkResult(const pistondyn::mbd::CylinderPressureCurve& c) {
  const auto& a = c.getAngles_deg();
  require(a.size() >= 4 && a.size() == c.getPressures_Pa().size(), "knot count");
  std::vector<double> probes = {-1e6, -720.0, -0.5, 0.0, 359.75, 720.0, 1e6};
  for (double x = 0.0; x <= 720.0; x += 7.3)
    probes.push_back(x);
  for (std::size_t i = 0; i + 1 < a.size(); ++i)
    probes.push_back(0.5 * (a[i] + a[i + 1]));
  for (const double x : probes) {
    const double p = c.calcPressure_Pa(x);
    require(std::isfinite(p) && p > 0.0, "pressure not positive and finite at an angle");
    require(std::isfinite(c.calcPressureSlope_Paperdeg(x)), "slope not finite at an angle");
  }
  require(std::isfinite(c.getPeakPressure_Pa()) && c.getPeakPressure_Pa() > 0.0, "peak");
  pistondyn::mbd::CrankTrainGeometry g;  // the gasoline example engine
  g.crankRadius_m = 0.040;
  g.conrodLength_m = 0.140;
  g.compressionRatio = 10.0;
  const pistondyn::mbd::SliderCrank kin(g);
  const pistondyn::mbd::CylinderVolume vol(kin, 0.0745, g.compressionRatio);
  require(std::isfinite(pistondyn::mbd::calcImep_Pa(c, vol)), "imep not finite");
}

// EngineDeck.h: what `pistondyn check` does after loading (checked by loadAndCheckDeck).
// Every number the deck's readers read (in SI; the liner's keys included) is finite, so no
// table or key reaches the model as NaN or Inf.
void checkResult(const io::EngineDeck& deck) {
  require(deck.cylinderPressure != nullptr, "an accepted deck has no pressure curve");
  require(static_cast<bool>(deck.makeLinerElement), "an accepted deck has no liner maker");
  for (const io::ResolvedInput& in : deck.inputs) {
    if (const auto* x = std::get_if<double>(&in.value))
      require(std::isfinite(*x), "input " + in.siPath + " is not finite");
    if (const auto* v = std::get_if<std::vector<double>>(&in.value)) {
      for (const double x : *v)
        require(std::isfinite(x), "input " + in.siPath + " has a non-finite value");
    }
  }
  for (const double a : deck.fieldDumpAngles_deg)
    require(std::isfinite(a), "a field-dump angle is not finite");
}

// Readers whose result has no checks of its own.
void checkResult(const Eigen::MatrixXd& m) {
  require(m.rows() > 0 && m.cols() > 0, "an empty matrix was accepted");
  require(m.allFinite(), "a non-finite matrix entry was accepted");
}

// The reader's promises (ComplianceInput.h): a square symmetric matrix of the node count,
// positive diagonal, finite; a tensor grid of strictly increasing angles and heights.
void checkResult(const pistondyn::mapping::StructuralCompliance& c) {
  const auto& C = c.compliance_m_per_N;
  require(c.nodeCount() > 0 && C.rows() == c.nodeCount() && C.cols() == c.nodeCount(),
          "compliance size differs from the node count");
  require(C.allFinite(), "a non-finite compliance entry was accepted");
  require((C - C.transpose()).cwiseAbs().maxCoeff() == 0.0, "the result is not symmetrised");
  require((C.diagonal().array() > 0.0).all(), "a non-positive diagonal was accepted");
  for (int i = 1; i < c.nPhi(); ++i)
    require(c.phi_rad[i] > c.phi_rad[i - 1], "node angles not increasing");
  for (int i = 1; i < c.nY(); ++i)
    require(c.y_m[i] > c.y_m[i - 1], "node heights not increasing");
}

// WarmStartFile.h: every number finite, the last cycle's two lists of one length, every element
// record finite.
void checkResult(const pistondyn::plugin::WarmStart& w) {
  const auto& x = w.state;
  for (const double v : {w.crankAngle_deg, w.outputStep_deg, x.lateral_m, x.tilt_rad,
                         x.transverse_m, x.lateralRate_mps, x.tiltRate_radps,
                         x.transverseRate_mps, x.crankSpeed_radps})
    require(std::isfinite(v), "a non-finite warm-start value was accepted");
  require(w.lastCycleLateral_m.size() == w.lastCycleTilt_rad.size(), "unequal last-cycle lists");
  for (const auto* list : {&w.lastCycleLateral_m, &w.lastCycleTilt_rad})
    for (const double v : *list)
      require(std::isfinite(v), "a non-finite last-cycle value was accepted");
  require(!w.lastCycleFmep_Pa || std::isfinite(*w.lastCycleFmep_Pa), "a non-finite fmep");
  for (const auto& e : w.elements)
    for (const double v : e.record)
      require(std::isfinite(v), "a non-finite element record value was accepted");
}

template <class T>
void checkResult(const T&) {}

// `pistondyn check DECK --set ...`: load, then the imep of its table.
io::EngineDeck loadAndCheckDeck(const std::string& path,
                                const std::vector<std::string>& overrides) {
  io::EngineDeck deck = io::loadEngineDeck(path, overrides);
  (void)io::calcDeckImep_Pa(deck);
  return deck;
}

// ---- the work folder ----------------------------------------------------------------------

struct WorkFolder {
  fs::path dir;
  fs::path input;
  ~WorkFolder() {
    std::error_code ec;
    if (!dir.empty())
      fs::remove_all(dir, ec);
  }
};
WorkFolder* gWork = nullptr;

void removeWorkFolder() {
  delete gWork;
  gWork = nullptr;
}

// A private folder holding the example engines' files and fuzz/data (decks' tables
// resolve there).
void makeWorkFolder() {
  std::string pattern = (fs::temp_directory_path() / "pistondyn_fuzz_XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr)
    fail("cannot create a work folder under " + fs::temp_directory_path().string());
  gWork = new WorkFolder{pattern, fs::path(pattern) / "input"};
  std::atexit(removeWorkFolder);
  const fs::path source(PISTONDYN_SOURCE_DIR);
  // Both engines' files, the gasoline engine's after (its names win: most seeds are
  // derived from its deck), then the fuzz targets' own small tables (fuzz/data).
  for (const fs::path& folder :
       {source / "examples/engines/briggs_stratton_500",
        source / "examples/engines/gasoline_1400_2000rpm", source / "fuzz/data"}) {
    const bool decksToo = folder.filename() == "data";  // fuzz/data/skirt_tables.yaml
    for (const auto& e : fs::directory_iterator(folder)) {
      if (e.is_regular_file() && (decksToo || e.path().extension() != ".yaml"))
        fs::copy_file(e.path(), gWork->dir / e.path().filename(),
                      fs::copy_options::overwrite_existing);
    }
  }
}

// A file of the work folder (fuzz/data and the example engines' files).
std::string dataFile(const std::string& name) {
  return (gWork->dir / name).string();
}

// The lubricated-skirt deck of fuzz/data with the table `key` replaced by the input
// (`--set <key>=input`, resolved in the deck's folder), then checked like the deck target.
io::EngineDeck loadSkirtDeckWithTable(const std::string& key) {
  return loadAndCheckDeck((gWork->dir / "skirt_tables.yaml").string(), {key + "=input"});
}

// Splits the input at the first line "#%set": the file's bytes, then --set lines.
void splitInput(const std::uint8_t* data, std::size_t size, std::string& file,
                std::vector<std::string>& overrides) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kMarker = "#%set\n";
  std::size_t at = all.rfind(kMarker, 0) == 0 ? 0 : all.find("\n" + std::string(kMarker));
  if (at == std::string_view::npos) {
    file.assign(all);
    return;
  }
  if (at != 0)
    ++at;  // keep the newline that ends the file's last line
  file.assign(all.substr(0, at));
  std::string_view rest = all.substr(at + kMarker.size());
  while (!rest.empty()) {
    const std::size_t nl = rest.find('\n');
    std::string_view line = rest.substr(0, nl);
    if (!line.empty())
      overrides.emplace_back(line);
    if (nl == std::string_view::npos)
      break;
    rest.remove_prefix(nl + 1);
  }
}

void writeInput(const std::string& bytes) {
  std::ofstream out(gWork->input, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out)
    fail("cannot write " + gWork->input.string());
}

// A rejection names where the problem is: it starts with a file of the work folder
// ("<file>[:<line>]: ...") or with the --set assignment ("--set key.path: ...").
void requireNamesItsSource(const std::string_view message) {
  const std::string dir = gWork->dir.string() + "/";
  require(message.rfind(dir, 0) == 0 || message.rfind("--set ", 0) == 0,
          "a rejection that names neither a file nor a --set: " + std::string(message));
}

// PISTONDYN_FUZZ_VERBOSE=1: say for each input whether it was accepted or how it was
// rejected (to check that seeds reach what they are meant to, and to read a finding).
void tell(const std::string& what) {
  static const bool verbose = std::getenv("PISTONDYN_FUZZ_VERBOSE") != nullptr;
  if (verbose)
    std::fprintf(stderr, "pistondyn fuzz (%s): %s\n", PISTONDYN_FUZZ_TARGET, what.c_str());
}

// Runs the Readers.def line this executable was built for.
void runReader(const std::string& path, const std::vector<std::string>& overrides) {
  (void)overrides;
#define PISTONDYN_FUZZ_READER(TARGET, REJECTION, CALL)                                            \
  if (std::string_view(#TARGET) == PISTONDYN_FUZZ_TARGET) {                                       \
    try {                                                                                         \
      const auto& result = CALL;                                                                  \
      checkResult(result);                                                                        \
      tell("accepted");                                                                           \
    } catch (const REJECTION& e) {                                                                \
      tell(std::string("rejected: ") + e.what());                                                 \
      requireNamesItsSource(e.what());                                                            \
    } catch (const std::exception& e) {                                                           \
      fail(std::string("threw ") + typeid(e).name() + " instead of " #REJECTION ": " + e.what()); \
    } catch (...) {                                                                               \
      fail("threw something that is not a std::exception");                                       \
    }                                                                                             \
    return;                                                                                       \
  }
#include "Readers.def"
#undef PISTONDYN_FUZZ_READER
  fail("no line of Readers.def is named " PISTONDYN_FUZZ_TARGET);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  makeWorkFolder();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string file;
  std::vector<std::string> overrides;
  splitInput(data, size, file, overrides);
  writeInput(file);
  runReader(gWork->input.string(), overrides);
  return 0;
}
