// Sweep decks (pistondyn::io, SweepDeck.h): the cases a deck generates, the Latin
// hypercube's stratification and reproducibility, the fingerprint, and every class of bad
// input rejected with the sweep deck's file:line, the key and the case. Running sweeps
// (threads, resume, MPI, exit codes) is tested at process level in tests/app.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "ScratchDeck.h"
#include "Sha256.h"  // io/src: the fingerprint's hash, checked against FIPS 180-2
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/ResultWriters.h"
#include "pistondyn/io/SweepDeck.h"

namespace fs = std::filesystem;
using namespace pistondyn_test;
using pistondyn::io::loadSweepDeck;
using pistondyn::io::makeLatinHypercube;
using pistondyn::io::SweepPlan;

namespace {

// The interval of `v` as SweepDeck.h defines it.
long stratumOf(double v, double lo, double hi, long n) {
  return static_cast<long>(std::floor((v - lo) / (hi - lo) * static_cast<double>(n)));
}

// Every interval of every key holds exactly one sample, and every sample is in its range.
void expectStratified(const std::vector<std::vector<double>>& samples,
                      const std::vector<std::pair<double, double>>& ranges) {
  const long n = static_cast<long>(samples.size());
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    const auto [lo, hi] = ranges[k];
    std::vector<int> hits(static_cast<std::size_t>(n), 0);
    for (const auto& s : samples) {
      ASSERT_EQ(s.size(), ranges.size());
      ASSERT_GE(s[k], lo);
      ASSERT_LT(s[k], hi);
      const long j = stratumOf(s[k], lo, hi, n);
      ASSERT_GE(j, 0);
      ASSERT_LT(j, n);
      ++hits[static_cast<std::size_t>(j)];
    }
    for (long j = 0; j < n; ++j)
      EXPECT_EQ(hits[static_cast<std::size_t>(j)], 1) << "key " << k << " interval " << j;
  }
}

TEST(LatinHypercube, EveryIntervalOfEveryKeyHoldsExactlyOneSample) {
  // Ranges of very different widths and signs (a tiny width tests the interval rounding).
  const std::vector<std::pair<double, double>> ranges = {
      {-1.0, 1.0}, {1500.0, 4000.0}, {1e-9, 1.0000001e-9}, {-1e6, 3e6}};
  for (const long n : {1L, 2L, 7L, 100L, 1000L}) {
    SCOPED_TRACE(n);
    expectStratified(makeLatinHypercube(ranges, n, 12345), ranges);
  }
}

TEST(LatinHypercube, TheSameSeedGivesTheSameSamplesAndAnotherSeedOthers) {
  const std::vector<std::pair<double, double>> ranges = {{0.0, 1.0}, {-3.0, 5.0}};
  const auto a = makeLatinHypercube(ranges, 50, 7);
  const auto b = makeLatinHypercube(ranges, 50, 7);
  const auto c = makeLatinHypercube(ranges, 50, 8);
  EXPECT_EQ(a, b);  // bit for bit
  EXPECT_NE(a, c);
  expectStratified(c, ranges);
}

// The pairing of intervals is random, not the diagonal: with 50 samples the chance that
// two keys' strata coincide sample by sample is 1/50!.
TEST(LatinHypercube, KeysArePairedByIndependentPermutations) {
  const std::vector<std::pair<double, double>> ranges = {{0.0, 1.0}, {0.0, 1.0}};
  const auto s = makeLatinHypercube(ranges, 50, 3);
  int same = 0;
  for (const auto& p : s)
    same += stratumOf(p[0], 0, 1, 50) == stratumOf(p[1], 0, 1, 50) ? 1 : 0;
  EXPECT_LT(same, 50);
}

TEST(LatinHypercube, RejectsZeroSamplesAndEmptyRanges) {
  EXPECT_THROW(makeLatinHypercube({{0.0, 1.0}}, 0, 1), std::invalid_argument);
  EXPECT_THROW(makeLatinHypercube({{1.0, 1.0}}, 4, 1), std::invalid_argument);
  EXPECT_THROW(makeLatinHypercube({{2.0, 1.0}}, 4, 1), std::invalid_argument);
}

// FIPS 180-2 Appendix B, examples B.1-B.3 (and the empty message's published digest).
TEST(Sha256, MatchesThePublishedExamples) {
  using pistondyn::io::detail::sha256Hex;
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256Hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // The empty message (a padding-only block); B.2's 56 bytes need a second padding block.
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

// A sweep deck next to the scratch engine deck.
class SweepDeckTest : public ScratchDeck {
 protected:
  std::string writeSweep(const std::string& text, const std::string& name = "sweep.yaml") {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  // The DeckError message of loading the sweep ("" if it loads).
  std::string sweepRejection(const std::string& path,
                             const std::vector<std::string>& overrides = {}) {
    try {
      loadSweepDeck(path, overrides);
    } catch (const pistondyn::io::DeckError& e) {
      return e.what();
    }
    return "";
  }
  static int lineIn(const std::string& path, const std::string& needle) {
    std::ifstream in(path);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      if (line.find(needle) != std::string::npos)
        return n;
    }
    return -1;
  }
};

const char* kHeader =
    "base_deck: engine.yaml\n"
    "set:\n"
    "  liner.model: ideal_guide\n"
    "  simulation.output_step_deg: 10\n";

std::vector<std::string> assignmentsOf(const SweepPlan& plan, int index) {
  std::vector<std::string> out;
  for (const auto& a : plan.getCase(index).assignments)
    out.push_back(a.key + "=" + a.value);
  return out;
}

TEST_F(SweepDeckTest, BlocksCombineAsAProductWithTheFirstGridKeySlowest) {
  const std::string path = writeSweep(std::string(kHeader) +
                                      "cases:\n"
                                      "  - {piston.mass_g: 200}\n"
                                      "  - {piston.mass_g: 220, pin.mass_g: 50}\n"
                                      "latin_hypercube:\n"
                                      "  samples: 3\n"
                                      "  seed: 11\n"
                                      "  ranges:\n"
                                      "    piston.com_above_pin_mm: [2, 8]\n"
                                      "cartesian:\n"
                                      "  geometry.pin_offset_mm: [-0.50, 5e-1]\n"
                                      "  drive.speed_rpm: [1500, 3000]\n");
  const SweepPlan plan = loadSweepDeck(path);
  ASSERT_EQ(plan.cases.size(), 2u * 3u * 4u);
  std::vector<std::string> keys;
  for (const auto& k : plan.sweptKeys)
    keys.push_back(k.key);
  // Columns in deck order; a listed case need not set every key.
  EXPECT_EQ(keys, (std::vector<std::string>{"piston.mass_g", "pin.mass_g",
                                            "piston.com_above_pin_mm", "geometry.pin_offset_mm",
                                            "drive.speed_rpm"}));
  const auto lhs = makeLatinHypercube({{2.0, 8.0}}, 3, 11);
  const std::string s0 = pistondyn::io::formatNumber(lhs[0][0]);
  const std::string s1 = pistondyn::io::formatNumber(lhs[1][0]);
  // Numbers are normalised: 5e-1 and 0.50 are the case 0.5.
  EXPECT_EQ(assignmentsOf(plan, 1),
            (std::vector<std::string>{"piston.mass_g=200", "piston.com_above_pin_mm=" + s0,
                                      "geometry.pin_offset_mm=-0.5", "drive.speed_rpm=1500"}));
  EXPECT_EQ(assignmentsOf(plan, 2).back(), "drive.speed_rpm=3000");
  EXPECT_EQ(assignmentsOf(plan, 3)[2], "geometry.pin_offset_mm=0.5");
  EXPECT_EQ(assignmentsOf(plan, 5)[1], "piston.com_above_pin_mm=" + s1);
  EXPECT_EQ(assignmentsOf(plan, 13),
            (std::vector<std::string>{"piston.mass_g=220", "pin.mass_g=50",
                                      "piston.com_above_pin_mm=" + s0,
                                      "geometry.pin_offset_mm=-0.5", "drive.speed_rpm=1500"}));
  // Every --set of a case: the shared ones first.
  const auto all = plan.getOverrides(plan.getCase(1));
  EXPECT_EQ(all.front(), "liner.model=ideal_guide");
  EXPECT_EQ(all.size(), 2u + 4u);
  EXPECT_EQ(plan.getCaseFolderName(7), "case_0007");
}

TEST_F(SweepDeckTest, LatinHypercubeSamplesAreStratifiedAndReproducible) {
  const std::string text = std::string(kHeader) +
                           "latin_hypercube:\n"
                           "  samples: 9\n"
                           "  seed: 2024\n"
                           "  ranges:\n"
                           "    piston.mass_g: [180, 240]\n"
                           "    geometry.pin_offset_mm: [-1, 1]\n";
  const SweepPlan a = loadSweepDeck(writeSweep(text));
  const SweepPlan b = loadSweepDeck(writeSweep(text, "again.yaml"));
  ASSERT_EQ(a.cases.size(), 9u);
  std::vector<std::vector<double>> samples;
  for (const auto& c : a.cases) {
    std::vector<double> s;
    for (const auto& v : c.assignments)
      s.push_back(std::strtod(v.value.c_str(), nullptr));  // the text reads back exactly
    samples.push_back(s);
  }
  expectStratified(samples, {{180.0, 240.0}, {-1.0, 1.0}});
  EXPECT_EQ(samples, makeLatinHypercube({{180.0, 240.0}, {-1.0, 1.0}}, 9, 2024));
  for (std::size_t i = 0; i < a.cases.size(); ++i)
    EXPECT_EQ(assignmentsOf(a, a.cases[i].index), assignmentsOf(b, b.cases[i].index));
  // The same sweep in another file is the same sweep.
  EXPECT_EQ(a.fingerprint, b.fingerprint);
  const SweepPlan other = loadSweepDeck(writeSweep(
      std::string(text).replace(text.find("2024"), 4, "2025"), "other_seed.yaml"));
  EXPECT_NE(other.fingerprint, a.fingerprint);
}

TEST_F(SweepDeckTest, FingerprintFollowsTheBaseDeckAndTheSharedOverrides) {
  const std::string text = std::string(kHeader) + "cartesian:\n  drive.speed_rpm: [1500, 3000]\n";
  const std::string path = writeSweep(text);
  const SweepPlan a = loadSweepDeck(path);
  EXPECT_EQ(a.fingerprint.size(), 64u);
  EXPECT_EQ(a.baseDeckSha256, *pistondyn::io::detail::sha256HexOfFile(deck()));
  ASSERT_EQ(a.inputFiles.size(), 1u);  // the pressure table
  EXPECT_EQ(a.fingerprint, loadSweepDeck(path).fingerprint);
  EXPECT_NE(a.fingerprint, loadSweepDeck(path, {"simulation.cycles=2"}).fingerprint);
  editDeck("mass_g: 210.0", "mass_g: 211.0");
  EXPECT_NE(a.fingerprint, loadSweepDeck(path).fingerprint);
  // sweep.json reads back as the same sweep.
  const SweepPlan back = pistondyn::io::parseSweepJson(pistondyn::io::makeSweepJson(a));
  EXPECT_EQ(back.fingerprint, a.fingerprint);
  EXPECT_EQ(back.fixedOverrides, a.fixedOverrides);
  ASSERT_EQ(back.cases.size(), a.cases.size());
  for (const auto& c : a.cases)
    EXPECT_EQ(back.getOverrides(back.getCase(c.index)), a.getOverrides(c));
  EXPECT_THROW(pistondyn::io::parseSweepJson("{\"format\": 1}"), std::runtime_error);
}

TEST_F(SweepDeckTest, FolderNamesWidenForLargeSweeps) {
  SweepPlan plan;
  plan.cases.resize(12000);
  EXPECT_EQ(plan.getCaseFolderName(7), "case_00007");
  plan.cases.resize(9999);
  EXPECT_EQ(plan.getCaseFolderName(9999), "case_9999");
}

// ---- bad input: file:line, key, case; nothing is run ----------------------------------

TEST_F(SweepDeckTest, UnknownKeyInEveryCaseIsReportedOnceWithItsLine) {
  const std::string path = writeSweep(std::string(kHeader) +
                                      "cartesian:\n"
                                      "  geometry.pin_ofset_mm: [-0.5, 0.5]\n"
                                      "  drive.speed_rpm: [1500, 3000]\n");
  const std::string m = sweepRejection(path);
  EXPECT_NE(m.find(path + ":" + std::to_string(lineIn(path, "pin_ofset")) +
                   ": cartesian.geometry.pin_ofset_mm: every case: unknown key"),
            std::string::npos)
      << m;
}

TEST_F(SweepDeckTest, UnknownKeyOrBadValueInOneCaseNamesTheCase) {
  const std::string path = writeSweep(std::string(kHeader) +
                                      "cases:\n"
                                      "  - {drive.speed_rpm: 2000}\n"
                                      "  - {drive.sped_rpm: 2000}\n"
                                      "  - {drive.speed_rpm: 60000}\n");
  const std::string m = sweepRejection(path);
  EXPECT_NE(m.find(path + ":" + std::to_string(lineIn(path, "sped_rpm")) +
                   ": cases[2].drive.sped_rpm: case 2 (drive.sped_rpm=2000): unknown key"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find(path + ":" + std::to_string(lineIn(path, "60000")) +
                   ": cases[3].drive.speed_rpm: case 3 (drive.speed_rpm=60000): must be between "
                   "1 and 50000 rpm"),
            std::string::npos)
      << m;
}

TEST_F(SweepDeckTest, ABadSharedOverrideNamesItsLine) {
  const std::string path = writeSweep(
      "base_deck: engine.yaml\nset:\n  simulation.output_step_deg: 7\n"
      "cartesian:\n  drive.speed_rpm: [1500, 3000]\n");
  const std::string m = sweepRejection(path);
  EXPECT_NE(m.find(path + ":3: set.simulation.output_step_deg: every case: must divide 720"),
            std::string::npos)
      << m;
  const std::string m2 =
      sweepRejection(writeSweep("base_deck: engine.yaml\ncartesian:\n  drive.speed_rpm: [1500, 3000]\n",
                                "cl.yaml"),
                     {"geometry.bogus_mm=1"});
  EXPECT_NE(m2.find("every case: --set geometry.bogus_mm: unknown key"), std::string::npos) << m2;
}

TEST_F(SweepDeckTest, EmptyListsEmptyRangesAndZeroSamples) {
  const std::string path = writeSweep(
      "base_deck: engine.yaml\n"
      "cartesian:\n"
      "  geometry.pin_offset_mm: []\n"
      "latin_hypercube:\n"
      "  samples: 0\n"
      "  ranges:\n"
      "    drive.speed_rpm: [2000, 2000]\n"
      "    piston.mass_g: [240, 180]\n");
  const std::string m = sweepRejection(path);
  EXPECT_NE(m.find(path + ":3: cartesian.geometry.pin_offset_mm: empty list"), std::string::npos)
      << m;
  EXPECT_NE(m.find(path + ":5: latin_hypercube.samples: expected a whole number between 1 and "
                          "1000000 (got 0): a Latin hypercube needs at least one sample"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find(path + ":7: latin_hypercube.ranges.drive.speed_rpm: empty range [2000, 2000]"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find(path + ":8: latin_hypercube.ranges.piston.mass_g: empty range [240, 180]"),
            std::string::npos)
      << m;
  EXPECT_NE(sweepRejection(writeSweep("base_deck: engine.yaml\ncases: []\n", "c.yaml"))
                .find("cases: empty list"),
            std::string::npos);
}

TEST_F(SweepDeckTest, StructuralProblemsOfTheSweepDeck) {
  const std::string path = writeSweep(
      "base_deck: missing.yaml\n"
      "colour: blue\n"
      "set:\n"
      "  drive.speed_rpm: 2000\n"
      "cartesian:\n"
      "  drive.speed_rpm: [1500, 1500]\n"
      "  geometry: [1]\n"
      "  piston.mass_g: 200\n");
  const std::string m = sweepRejection(path);
  for (const std::string& expected :
       {path + ":1: base_deck: cannot open", path + ":2: colour: unknown key",
        path + ":6: cartesian.drive.speed_rpm: item 2: 1500 is listed twice",
        path + ":7: cartesian.geometry: expected an engine-deck key path",
        path + ":8: cartesian.piston.mass_g: expected a list of values"}) {
    EXPECT_NE(m.find(expected), std::string::npos) << expected << "\n" << m;
  }
  // A key in two blocks; a --set of a swept key; no cases at all.
  const std::string two = writeSweep(
      "base_deck: engine.yaml\nset:\n  drive.speed_rpm: 2000\n"
      "cartesian:\n  drive.speed_rpm: [1500, 3000]\n",
      "two.yaml");
  EXPECT_NE(sweepRejection(two).find(two + ":5: cartesian.drive.speed_rpm: the key is also set "
                                           "at " +
                                     two + ":3: set.drive.speed_rpm"),
            std::string::npos)
      << sweepRejection(two);
  const std::string swept =
      writeSweep("base_deck: engine.yaml\ncartesian:\n  drive.speed_rpm: [1500, 3000]\n", "s.yaml");
  EXPECT_NE(sweepRejection(swept, {"drive.speed_rpm=2000"})
                .find("--set drive.speed_rpm: the sweep varies this key"),
            std::string::npos);
  EXPECT_NE(sweepRejection(writeSweep("base_deck: engine.yaml\n", "none.yaml")).find("no cases"),
            std::string::npos);
  EXPECT_NE(sweepRejection((dir_ / "absent.yaml").string()).find("cannot open the sweep deck"),
            std::string::npos);
}

// A table a case reads is part of the sweep by its content: a resumed sweep whose skirt
// profile was edited is another sweep (SweepRun.h refuses its folder).
class SkirtSweepDeckTest : public SkirtScratchDeck {};

TEST_F(SkirtSweepDeckTest, TablesTheCasesReadArePartOfTheFingerprint) {
  writeFile("flat_profile.csv",
            "height_above_pin_mm,radial_drop_um\n-25,20\n-6,0\n25,60\n");
  const fs::path sweep = dir_ / "sweep.yaml";
  std::ofstream(sweep) << "base_deck: engine.yaml\n"
                          "cartesian:\n"
                          "  liner.skirt_profile.axial_profile_file: [skirt_profile.csv, "
                          "flat_profile.csv]\n";
  const SweepPlan a = loadSweepDeck(sweep.string());
  ASSERT_EQ(a.cases.size(), 2u);
  // The pressure table, the two temperature tables and both profiles, each by the SHA-256 of
  // its bytes.
  ASSERT_EQ(a.inputFiles.size(), 5u);
  std::set<std::string> hashes;
  for (const auto& f : a.inputFiles) {
    EXPECT_EQ(f.sha256, *pistondyn::io::detail::sha256HexOfFile(f.path)) << f.path;
    hashes.insert(f.sha256);
  }
  EXPECT_TRUE(hashes.count(*pistondyn::io::detail::sha256HexOfFile((dir_ / "flat_profile.csv").string())));
  writeFile("flat_profile.csv", "height_above_pin_mm,radial_drop_um\n-25,21\n-6,0\n25,60\n");
  EXPECT_NE(loadSweepDeck(sweep.string()).fingerprint, a.fingerprint);
}

}  // namespace
