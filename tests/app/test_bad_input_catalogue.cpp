// The bad-input catalogue of issue 13 (item 6) as one table through the real program, on
// the example deck with the lubricated skirt: malformed YAML, wrong types, missing and
// extra keys, values out of range or implausible, pressure and skirt tables with
// non-monotonic axes, wrong column counts or NaN, unreadable paths and hostile files, bad
// overrides and an output folder that is a file. Each case must exit with its code (1: bad
// input, 2: bad command line), print one message per problem that names the file:line or
// the key and what is expected, and leave no result file behind. Compliance files of the
// wrong size or not symmetric (liner.elastic_skirt.*) are here too; tests/io
// ComplianceInput.* checks their reader's every other rejection.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "ScratchDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;

namespace {

class BadInputCatalogue : public SkirtScratchDeck {
 public:
  using SkirtScratchDeck::deck;
  using SkirtScratchDeck::editDeck;
  using SkirtScratchDeck::writeFile;
  using SkirtScratchDeck::writeTable;
  int line(const std::string& needle) const { return lineOf(needle); }
  fs::path dir() const { return dir_; }
};

struct BadInput {
  std::string name;
  std::function<void(BadInputCatalogue&)> prepare;  // edits the deck or writes files
  std::string args;                                 // after `run DECK --out DIR`
  int exitCode;
  std::vector<std::string> expected;  // substrings of stderr ("<deck>" is the deck's path)
};

std::string lineText(int n) {
  return std::to_string(n);
}

// A case of the elastic skirt: the 2 x 2 node table nodes.csv and the matrix c.mtx (a
// Matrix Market array of the given size line and entries) beside the deck, both set.
BadInput complianceCase(const std::string& name, const std::string& sizeAndEntries,
                        std::vector<std::string> expected) {
  return {name,
          [sizeAndEntries](auto& f) {
            f.writeFile("nodes.csv", "node,phi_deg,y_mm\n1,0,-1\n2,30,-1\n3,0,3\n4,30,3\n");
            f.writeFile("c.mtx", "%%MatrixMarket matrix array real general\n" + sizeAndEntries);
          },
          "--set liner.elastic_skirt.compliance_file=c.mtx "
          "--set liner.elastic_skirt.nodes_file=nodes.csv",
          1,
          std::move(expected)};
}

TEST_F(BadInputCatalogue, EachCaseExitsNamingWhereAndWhatAndWritesNothing) {
  const std::string table = kTable;  // the pressure table beside the deck
  const std::vector<BadInput> catalogue = {
      {"malformed YAML",
       [](auto& f) { f.editDeck("  bore_mm: 74.5", "  bore_mm: [74.5"); },
       "",
       1,
       {"<deck>:", "not valid YAML"}},
      {"wrong type: text for a number",
       [](auto& f) { f.editDeck("bore_mm: 74.5", "bore_mm: wide"); },
       "",
       1,
       {"<deck>:@bore_mm@: geometry.bore_mm: 'wide' is not a number"}},
      {"wrong type: a list for a section",
       [](auto& f) { f.editDeck("drive:\n", "drive: [1, 2]\nnot_drive:\n"); },
       "",
       1,
       {"<deck>:@drive@: drive: expected a section (indented 'key: value' lines), found a list"}},
      {"wrong type: a value for a section (--set)",
       [](auto&) {},
       "--set 'piston=[1, 2]'",
       1,
       {"--set piston: 'piston' is a section of the deck, not a value"}},
      {"wrong type: not a switch",
       [](auto& f) { f.editDeck("until_periodic: true", "until_periodic: maybe"); },
       "",
       1,
       {"<deck>:@until_periodic@: simulation.until_periodic: expected true or false"}},
      {"missing key",
       [](auto& f) { f.editDeck("  bore_mm: 74.5", "  # no bore"); },
       "",
       1,
       {"geometry.bore_mm: missing key (a number is required)"}},
      {"extra key",
       [](auto& f) { f.editDeck("  bore_mm: 74.5", "  bore_mm: 74.5\n  bore_in: 3"); },
       "",
       1,
       {"<deck>:@bore_in@: geometry.bore_in: unknown key", "`pistondyn keys`"}},
      {"duplicate key",
       [](auto& f) { f.editDeck("  bore_mm: 74.5", "  bore_mm: 74.5\n  bore_mm: 75"); },
       "",
       1,
       {"geometry.bore_mm: duplicate key"}},
      {"out of the valid range",
       [](auto&) {},
       "--set drive.speed_rpm=60000",
       1,
       {"--set drive.speed_rpm: must be between 1 and 50000 rpm (got 60000)"}},
      {"out of the plausible range (a unit slip)",
       [](auto&) {},
       "--set geometry.bore_mm=0.0745",
       1,
       {"--set geometry.bore_mm:", "plausible range [20, 1000] mm", "given in m"}},
      {"cross-key: rod too short",
       [](auto&) {},
       "--set geometry.conrod_length_mm=30",
       1,
       {"--set geometry.conrod_length_mm: the rod must be longer than half the stroke"}},
      // Impossible bodies (issue 37): a pin axis or a centre of mass outside its body.
      {"cross-key: pin axis outside the piston",
       [](auto&) {},
       "--set geometry.pin_offset_mm=50",
       1,
       {"--set geometry.pin_offset_mm: the pin axis must lie well inside the piston: |pin "
        "offset| below a quarter of the bore, 18.625 mm here",
        "got 50 mm"}},
      {"cross-key: rod centre of mass beyond the small end",
       [](auto&) {},
       "--set conrod.com_from_big_end_mm=500",
       1,
       {"--set conrod.com_from_big_end_mm: the centre of mass lies between the big-end and "
        "small-end centres: less than geometry.conrod_length_mm (140 mm), got 500 mm"}},
      {"cross-key: piston centre of mass beside the bore",
       [](auto&) {},
       "--set piston.com_towards_thrust_mm=-40",
       1,
       {"--set piston.com_towards_thrust_mm: the centre of mass lies inside the piston: "
        "|offset| below half the bore (37.25 mm), got -40 mm"}},
      {"cross-key: piston centre of mass above the crown",
       [](auto&) {},
       "--set piston.com_above_pin_mm=30",
       1,
       {"--set piston.com_above_pin_mm: the centre of mass lies inside the piston: below the "
        "crown top (piston.compression_height_mm = 28 mm), got 30 mm"}},
      {"empty engine name",
       [](auto& f) { f.editDeck("  name: \"", "  name: \"\"  # \""); },
       "",
       1,
       {"<deck>:@name@: engine.name: is empty: give the engine a name"}},
      {"stated imep of 0",
       [](auto&) {},
       "--set gas.stated_imep_kPa=0",
       1,
       {"--set gas.stated_imep_kPa: 0 is not a valid stated imep", "or leave the key out"}},
      {"a 100 kB value is echoed shortened",
       [](auto&) {},
       "--set geometry.bore_mm=" + std::string(100000, '7') + "x",
       1,
       {"--set geometry.bore_mm: '" + std::string(80, '7') +
        "...' (100001 characters, shown shortened) is not a number"}},
      // The elastic skirt's compliance (liner.elastic_skirt.*): a 2 x 2 node table with a
      // matrix of the wrong size, and with one that breaks Maxwell-Betti reciprocity.
      complianceCase("compliance of the wrong size for its node table",
                     "3 3\n4e-9\n0\n0\n0\n4e-9\n0\n0\n0\n4e-9\n",
                     {"liner.elastic_skirt.compliance_file", "c.mtx: 3 x 3 matrix, expected 4 x 4",
                      "nodes.csv"}),
      complianceCase("compliance not symmetric",
                     "4 4\n4e-9\n3e-9\n0\n0\n1e-9\n4e-9\n0\n0\n0\n0\n4e-9\n0\n0\n0\n0\n4e-9\n",
                     {"liner.elastic_skirt.compliance_file", "c.mtx: not symmetric: entry (2, 1)",
                      "Maxwell-Betti"}),
      complianceCase("compliance header claiming a huge matrix (refused before allocating)",
                     "20000 20000\n4e-9\n",
                     {"liner.elastic_skirt.compliance_file",
                      "c.mtx: 20000 x 20000 matrix, expected 4 x 4", "nodes.csv"}),
      {"pressure table: angles not increasing",
       [table](auto& f) {
         f.writeTable("crank_angle_deg,pressure_bar\n0,40\n10,30\n5,20\n720,40\n");
       },
       "",
       1,
       {"gas.cylinder_pressure_file: ", table + ":4: crank angle 5 deg is not greater"}},
      {"pressure table: wrong column count and NaN, all at once",
       [table](auto& f) {
         f.writeTable("crank_angle_deg,pressure_bar\n0,40\n10,30,7\n20,nan\n720,40\n");
       },
       "",
       1,
       {table + ":3: expected 2 columns (crank angle, pressure), found 3",
        table + ":4: pressure 'nan' is not a number"}},
      {"pressure table: header without a unit",
       [table](auto& f) { f.writeTable("crank_angle_deg,pressure\n0,1\n"); },
       "",
       1,
       {table + ":1: expected the header 'crank_angle_deg,pressure_<unit>'"}},
      {"pressure table: not covering the cycle",
       [table](auto& f) {
         f.writeTable("crank_angle_deg,pressure_bar\n0,1\n100,2\n200,1\n300,1\n400,1\n");
       },
       "",
       1,
       {"gas.cylinder_pressure_file: ", table, "720"}},
      {"pressure table: too few rows",
       [table](auto& f) { f.writeTable("crank_angle_deg,pressure_bar\n0,1\n100,2\n200,1\n"); },
       "",
       1,
       {"gas.cylinder_pressure_file: ", table + ": CylinderPressureCurve: needs at least 4 rows"}},
      {"pressure table: a folder",
       [](auto& f) { fs::create_directories(f.dir() / "tables"); },
       "--set gas.cylinder_pressure_file=tables",
       1,
       {"--set gas.cylinder_pressure_file: '", "tables' is a folder, not a file"}},
      {"pressure table: no such file",
       [](auto&) {},
       "--set gas.cylinder_pressure_file=nope.csv",
       1,
       {"--set gas.cylinder_pressure_file: cannot open '", "nope.csv'"}},
      {"skirt profile: heights not increasing",
       [](auto& f) {
         f.writeFile(kProfileTable,
                     "height_above_pin_mm,radial_drop_um\n-20,40\n0,1\n-5,2\n15,30\n");
       },
       "",
       1,
       {"liner.skirt_profile.axial_profile_file: ",
        "skirt_profile.csv:4: height_above_pin_mm -5 is not above the previous row's 0 mm"}},
      {"skirt profile: a column in another unit",
       [](auto& f) {
         f.writeFile(kProfileTable, "height_above_pin_mm,radial_drop_mm\n-20,0.04\n15,0.03\n");
       },
       "",
       1,
       {"liner.skirt_profile.axial_profile_file: ", "the table needs a column 'radial_drop_um'"}},
      {"skirt profile: a column it does not take",
       [](auto& f) {
         f.writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um,note\n-20,40,1\n15,30,2\n");
       },
       "",
       1,
       {"liner.skirt_profile.axial_profile_file: ", "unexpected column 'note'"}},
      {"skirt profile: wrong column count in a row",
       [](auto& f) {
         f.writeFile(kProfileTable, "height_above_pin_mm,radial_drop_um\n-20,40\n0,1,7\n15,30\n");
       },
       "",
       1,
       {"liner.skirt_profile.axial_profile_file: ", "skirt_profile.csv:3"}},
      {"skirt temperature table: NaN",
       [](auto& f) {
         f.writeFile("t.csv", "height_above_pin_mm,temperature_degC\n-18,nan\n12,90\n");
       },
       "--set liner.thermal.piston_temperature_file=t.csv "
       "--set liner.thermal.piston_expansion_per_K=2.1e-5",
       1,
       {"liner.thermal.piston_temperature_file: ", "t.csv:2"}},
      {"oil supply table: angle beyond the cycle",
       [](auto& f) { f.writeFile("s.csv", "crank_angle_deg,film_um\n0,0.5\n720,0.5\n"); },
       "--set liner.oil_supply.film_um=null --set liner.oil_supply.film_file=s.csv",
       1,
       {"liner.oil_supply.film_file: ", "s.csv:3: crank_angle_deg 720 deg is outside the cycle"}},
      {"bad override: no value",
       [](auto&) {},
       "--set geometry.bore_mm",
       1,
       {"--set geometry.bore_mm: expected key.path=value"}},
      {"bad override: a section set to a value",
       [](auto&) {},
       "--set geometry=5",
       1,
       {"--set geometry: 'geometry' is a section of the deck, not a value"}},
      {"a second YAML document",
       [](auto& f) { std::ofstream(f.deck(), std::ios::app) << "---\nengine: {name: b}\n"; },
       "",
       1,
       {"a second YAML document (after '---')"}},
      {"a NUL byte",
       [](auto& f) {
         std::ofstream(f.deck(), std::ios::binary)
             << std::string("engine:\n  name: \"a\0m\"\n", 22);
       },
       "",
       1,
       {"<deck>:2: holds a NUL byte"}},
      {"output folder is a file",
       [](auto& f) { std::ofstream(f.dir() / "out_file") << "x"; },
       "@out_file",
       2,
       {"--out ", "out_file is a file, not a folder; nothing was simulated"}},
  };
  for (const BadInput& c : catalogue) {
    SCOPED_TRACE(c.name);
    // A fresh copy of the example deck and its tables for every case.
    TearDown();
    SetUp();
    c.prepare(*this);
    fs::path out = dir_ / "results";
    std::string args = c.args;
    if (args.rfind("@", 0) == 0) {  // the case names its own --out
      out = dir_ / args.substr(1);
      args.clear();
    }
    const bool outExisted = fs::exists(out);
    const std::string before = outExisted ? readFile(out) : "";
    EXPECT_EQ(runProgram(args, out), c.exitCode);
    const std::string err = programStderr();
    for (std::string e : c.expected) {
      // "<deck>" is the deck's path, "@key@" the line the key is on.
      if (const auto p = e.find("<deck>"); p != std::string::npos)
        e.replace(p, 6, deck());
      if (const auto p = e.find('@'); p != std::string::npos) {
        const auto q = e.find('@', p + 1);
        e.replace(p, q - p + 1, lineText(line(e.substr(p + 1, q - p - 1) + ":")));
      }
      EXPECT_NE(err.find(e), std::string::npos) << "expected: " << e << "\nstderr:\n" << err;
    }
    EXPECT_EQ(err.find("nan kPa"), std::string::npos) << err;
    EXPECT_EQ(err.find("inf %"), std::string::npos) << err;
    EXPECT_LT(err.size(), 2000u) << "a message of " << err.size() << " characters";
    // Nothing written: no output folder, or the file that was there untouched.
    if (outExisted)
      EXPECT_EQ(readFile(out), before);
    else
      EXPECT_FALSE(fs::exists(out)) << out;
  }
}

}  // namespace
