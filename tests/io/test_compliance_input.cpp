// Reading a structural compliance: Matrix Market forms, node tables, and every bad input the
// reader must reject with the file and the line or entry named. The expected matrices are
// written by hand here (independent of any FE run).

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "pistondyn/io/ComplianceInput.h"
#include "pistondyn/io/DeckError.h"
#include "pistondyn/io/MatrixMarket.h"

namespace {

namespace fs = std::filesystem;
namespace pio = pistondyn::io;

class ComplianceInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pistondyn_compliance_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  // 2 angles (0 and 180 deg: a full circle) x 2 heights (-1 and 3 mm).
  std::string nodes2x2() const {
    return write("nodes.csv", "# test grid\nnode,phi_deg,y_mm\n1,0,-1\n2,180,-1\n3,0,3\n4,180,3\n");
  }
  // A symmetric positive definite 4 x 4 matrix [m/N] (diagonally dominant).
  static std::string spdArray() {
    return "%%MatrixMarket matrix array real general\n% a comment\n4 4\n"
           "4e-9\n1e-9\n0.5e-9\n0\n"
           "1e-9\n4e-9\n0\n0.5e-9\n"
           "0.5e-9\n0\n4e-9\n1e-9\n"
           "0\n0.5e-9\n1e-9\n4e-9\n";
  }

  // Expects DeckError whose message contains every needle.
  template <typename F>
  static void expectError(F&& f, std::initializer_list<std::string> needles) {
    try {
      f();
      ADD_FAILURE() << "no DeckError";
    } catch (const pio::DeckError& e) {
      const std::string m = e.what();
      for (const std::string& n : needles)
        EXPECT_NE(m.find(n), std::string::npos) << "'" << n << "' not in: " << m;
    }
  }

  fs::path dir_;
};

TEST_F(ComplianceInput, ArrayGeneralReadsColumnMajorAndConvertsTheNodes) {
  const std::string n = nodes2x2();
  const std::string m = write("c.mtx", spdArray());
  const auto c = pio::readStructuralCompliance(m, n);
  ASSERT_EQ(c.nodeCount(), 4);
  EXPECT_EQ(c.nPhi(), 2);
  EXPECT_EQ(c.nY(), 2);
  EXPECT_FALSE(c.fullCircle);  // 2 angles: too few for a ring (CylinderGrid::fullCircle needs 3)
  EXPECT_DOUBLE_EQ(c.phi_rad[1], M_PI);
  EXPECT_DOUBLE_EQ(c.y_m[0], -1e-3);
  EXPECT_DOUBLE_EQ(c.y_m[1], 3e-3);
  EXPECT_DOUBLE_EQ(c.compliance_m_per_N(0, 0), 4e-9);
  EXPECT_DOUBLE_EQ(c.compliance_m_per_N(1, 0), 1e-9);
  EXPECT_DOUBLE_EQ(c.compliance_m_per_N(3, 1), 0.5e-9);
  EXPECT_DOUBLE_EQ(c.compliance_m_per_N(3, 0), 0.0);
  EXPECT_FALSE(c.hasGasDisplacement());
}

TEST_F(ComplianceInput, CoordinateSymmetricAndArraySymmetricGiveTheSameMatrix) {
  const std::string n = nodes2x2();
  const auto general = pio::readStructuralCompliance(write("g.mtx", spdArray()), n);
  // Lower triangle only; entries not given are 0; several spaces and a blank line are fine.
  const auto coord = pio::readStructuralCompliance(
      write("c.mtx",
            "%%MatrixMarket matrix coordinate real symmetric\n%\n4 4 8\n1 1 4e-9\n"
            "2 1 1e-9\n3 1 0.5e-9\n2 2 4e-9\n\n4   2  0.5e-9\n3 3 4e-9\n4 3 1e-9\n"
            "4 4 4e-9\n"),
      n);
  const auto arraySym = pio::readStructuralCompliance(
      write("s.mtx",
            "%%MatrixMarket MATRIX Array Real Symmetric\n4 4\n4e-9 1e-9 0.5e-9 0\n"
            "4e-9 0 0.5e-9\n4e-9 1e-9\n4e-9\n"),
      n);
  EXPECT_EQ((coord.compliance_m_per_N - general.compliance_m_per_N).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((arraySym.compliance_m_per_N - general.compliance_m_per_N).cwiseAbs().maxCoeff(), 0.0);
}

TEST_F(ComplianceInput, GasFieldAndUnitsConvertToSI) {
  const std::string n = write("n.csv",
                              "node,phi_rad,y_m,gas_u_r_um_per_MPa\n1,0,0.001,2.5\n2,1,0.001,-1\n"
                              "3,2,0.001,0\n1e0,0,0.002,0\n");
  // ids must be 1..n: the '1e0' above is node 1 again -> rejected
  expectError([&] { pio::readStructuralCompliance(write("c.mtx", spdArray()), n); },
              {"n.csv:5", "node 1, expected 4"});
  const std::string good = write("n2.csv",
                                 "node,phi_rad,y_m,gas_u_r_um_per_MPa\n1,0,0.001,2.5\n"
                                 "2,1,0.001,-1\n3,0,0.002,0\n4,1,0.002,4\n");
  pio::ComplianceReadOptions mm;
  mm.matrixToSI = 1e-3;  // a file in mm/N
  const auto c = pio::readStructuralCompliance(write("c.mtx", spdArray()), good, mm);
  EXPECT_FALSE(c.fullCircle);  // 2 angles 1 rad apart: a sector
  EXPECT_DOUBLE_EQ(c.compliance_m_per_N(0, 0), 4e-12);
  ASSERT_TRUE(c.hasGasDisplacement());
  EXPECT_DOUBLE_EQ(c.gasDisplacement_m_per_Pa[0], 2.5e-12);  // 2.5 um/MPa
  EXPECT_DOUBLE_EQ(c.gasDisplacement_m_per_Pa[3], 4e-12);
}

TEST_F(ComplianceInput, SymmetryIsCheckedToTheStatedToleranceAndSymmetrised) {
  const std::string n = nodes2x2();
  // (2,1) = 1e-9 + 2e-14: asymmetry 2e-14 / 4e-9 = 5e-6 of the diagonal: within 1e-5.
  std::string text = spdArray();
  text.replace(text.find("1e-9\n0.5e-9\n0\n"), 5, "1.00002e-9\n");
  const auto c = pio::readStructuralCompliance(write("c.mtx", text), n);
  EXPECT_DOUBLE_EQ(c.compliance_m_per_N(1, 0), c.compliance_m_per_N(0, 1));
  EXPECT_NEAR(c.compliance_m_per_N(1, 0), 1.00001e-9, 1e-22);
  pio::ComplianceReadOptions strict;
  strict.symmetryTolerance = 1e-6;
  expectError([&] { pio::readStructuralCompliance(write("c.mtx", text), n, strict); },
              {"c.mtx", "not symmetric", "(2, 1)", "Maxwell-Betti"});
}

TEST_F(ComplianceInput, NotSymmetricNamesTheEntry) {
  std::string text = spdArray();
  text.replace(text.find("0\n0.5e-9\n1e-9\n4e-9\n"), 2, "2e-9\n");  // (1,4) = 2e-9, (4,1) = 0
  expectError([&] { pio::readStructuralCompliance(write("c.mtx", text), nodes2x2()); },
              {"c.mtx", "not symmetric", "(4, 1)", "(1, 4)"});
}

TEST_F(ComplianceInput, WrongSizeForTheNodeTable) {
  const std::string m =
      write("c.mtx", "%%MatrixMarket matrix array real general\n2 2\n1\n0\n0\n1\n");
  expectError([&] { pio::readStructuralCompliance(m, nodes2x2()); },
              {"c.mtx", "2 x 2 matrix, expected 4 x 4", "nodes.csv"});
}

// The size line is checked against the size the caller expects before the matrix is
// allocated: a header claiming 20000 x 20000 (3.2 GB dense) with one entry is refused
// at once (tests/app FirstHourEdges.HugeMatrixMarketHeaderIsRefusedBeforeAllocating runs it
// under a memory limit).
TEST_F(ComplianceInput, DeclaredSizeIsCheckedBeforeAllocating) {
  const std::string huge =
      write("h.mtx", "%%MatrixMarket matrix coordinate real symmetric\n20000 20000 1\n1 1 4e-9\n");
  expectError([&] { pio::readMatrixMarketDense(huge, 4, " for the 4 nodes of n.csv"); },
              {"h.mtx: 20000 x 20000 matrix, expected 4 x 4 for the 4 nodes of n.csv"});
  expectError([&] { pio::readStructuralCompliance(huge, nodes2x2()); },
              {"h.mtx: 20000 x 20000 matrix, expected 4 x 4", "nodes.csv"});
  // Beyond 20000 rows the header is refused whatever the caller expects.
  expectError(
      [&] {
        pio::readMatrixMarketDense(
            write("g.mtx", "%%MatrixMarket matrix array real general\n20001 1\n1\n"));
      },
      {"g.mtx:2", "expected 1 to 20000 rows and columns"});
}

TEST_F(ComplianceInput, NaNAndNonNumbersAreRejectedWithTheLine) {
  std::string text = spdArray();
  text.replace(text.find("0.5e-9\n0\n1e-9"), 6, "nan");  // entry (3, 1), line 6
  expectError([&] { pio::readStructuralCompliance(write("c.mtx", text), nodes2x2()); },
              {"c.mtx:6", "'nan' is not a finite number"});
  expectError(
      [&] {
        pio::readMatrixMarketDense(
            write("i.mtx", "%%MatrixMarket matrix coordinate real general\n2 2 1\n1 1 inf\n"));
      },
      {"i.mtx:3", "'inf'"});
  expectError(
      [&] {
        pio::readMatrixMarketDense(
            write("x.mtx", "%%MatrixMarket matrix coordinate real general\n2 2 1\n1 x 1\n"));
      },
      {"x.mtx:3", "column index 'x'"});
}

TEST_F(ComplianceInput, WrongHeaderIsNotMatrixMarket) {
  expectError([&] { pio::readMatrixMarketDense(write("a.mtx", "4 4\n1\n")); },
              {"a.mtx:1", "not a Matrix Market file"});
  expectError(
      [&] {
        pio::readMatrixMarketDense(
            write("b.mtx", "%%MatrixMarket matrix coordinate complex general\n1 1 1\n1 1 1 0\n"));
      },
      {"b.mtx:1", "field 'complex'"});
  expectError(
      [&] {
        pio::readMatrixMarketDense(
            write("c.mtx", "%%MatrixMarket matrix coordinate pattern general\n1 1 1\n1 1\n"));
      },
      {"c.mtx:1", "field 'pattern'"});
  expectError(
      [&] {
        pio::readMatrixMarketDense(
            write("d.mtx", "%%MatrixMarket matrix array real skew-symmetric\n1 1\n0\n"));
      },
      {"d.mtx:1", "symmetry 'skew-symmetric'"});
  expectError(
      [&] {
        pio::readMatrixMarketDense(
            write("e.mtx", "%%MatrixMarket matrix array real general\n2 2 4\n"));
      },
      {"e.mtx:2", "size line"});
  expectError([&] { pio::readMatrixMarketDense(write("f.mtx", "")); }, {"f.mtx:1", "empty"});
}

TEST_F(ComplianceInput, EntryCountsAndIndicesAreChecked) {
  const std::string h = "%%MatrixMarket matrix coordinate real symmetric\n";
  expectError([&] { pio::readMatrixMarketDense(write("a.mtx", h + "2 2 2\n1 1 1\n")); },
              {"a.mtx", "ends after 1 of 2 entries"});
  expectError([&] { pio::readMatrixMarketDense(write("b.mtx", h + "2 2 1\n1 2 1\n")); },
              {"b.mtx:3", "above the diagonal"});
  expectError([&] { pio::readMatrixMarketDense(write("c.mtx", h + "2 2 2\n1 1 1\n1 1 2\n")); },
              {"c.mtx:4", "given twice"});
  expectError([&] { pio::readMatrixMarketDense(write("d.mtx", h + "2 2 1\n3 1 1\n")); },
              {"d.mtx:3", "outside the 2 x 2 matrix"});
  expectError([&] { pio::readMatrixMarketDense(write("e.mtx", h + "2 2 1\n1 1 1\n2 2 1\n")); },
              {"e.mtx:4", "more entries than the size line"});
  expectError(
      [&] {
        pio::readMatrixMarketDense(
            write("f.mtx", "%%MatrixMarket matrix array real general\n2 2\n1\n2\n3\n"));
      },
      {"f.mtx", "ends after 3 of 4 values"});
}

TEST_F(ComplianceInput, UnreadablePathNamesTheFile) {
  const std::string missing = (dir_ / "no_such.mtx").string();
  expectError([&] { pio::readStructuralCompliance(missing, nodes2x2()); },
              {"no_such.mtx", "cannot open"});
  expectError(
      [&] {
        pio::readStructuralCompliance(write("c.mtx", spdArray()), (dir_ / "no_nodes.csv").string());
      },
      {"no_nodes.csv"});
}

TEST_F(ComplianceInput, DiagonalAndDefinitenessAreChecked) {
  std::string zeroDiag = spdArray();
  zeroDiag.replace(zeroDiag.find("0.5e-9\n0\n4e-9\n1e-9\n") + 9, 4, "0.0\n");  // (3,3) = 0
  expectError([&] { pio::readStructuralCompliance(write("z.mtx", zeroDiag), nodes2x2()); },
              {"z.mtx", "diagonal entry (3, 3)", "positive"});
  // Positive diagonal, symmetric, but indefinite: [[1, 2], [2, 1]] blocks.
  const std::string indefinite =
      "%%MatrixMarket matrix coordinate real symmetric\n4 4 6\n1 1 1\n2 1 2\n2 2 1\n3 3 1\n"
      "4 3 2\n4 4 1\n";
  expectError([&] { pio::readStructuralCompliance(write("i.mtx", indefinite), nodes2x2()); },
              {"i.mtx", "not positive definite"});
}

TEST_F(ComplianceInput, NodeTableMustBeATensorGrid) {
  const std::string m = write("c.mtx", spdArray());
  expectError(
      [&] {
        pio::readStructuralCompliance(
            m, write("a.csv", "node,phi_deg,y_mm\n1,0,0\n2,90,0\n3,90,1\n4,0,1\n"));
      },
      {"a.csv:4", "angle 90 deg, expected 0 deg"});
  expectError(
      [&] {
        pio::readStructuralCompliance(
            m, write("b.csv", "node,phi_deg,y_mm\n1,0,0\n2,90,0\n3,0,-1\n4,90,-1\n"));
      },
      {"b.csv:4", "heights must increase"});
  expectError(
      [&] {
        pio::readStructuralCompliance(
            m, write("c.csv", "node,phi_deg,y_mm\n1,0,0\n2,400,0\n3,0,1\n4,90,1\n"));
      },
      {"c.csv:3", "outside [0, 360)"});
  expectError(
      [&] {
        pio::readStructuralCompliance(
            m, write("d.csv", "node,angle,y_mm\n1,0,0\n2,90,0\n3,0,1\n4,90,1\n"));
      },
      {"d.csv", "no column 'phi_<angle unit>'"});
  expectError(
      [&] {
        pio::readStructuralCompliance(
            m, write("e.csv", "node,phi_deg,y_mm\n1,0,0\n2,90,0\n3,180,0\n4,0,1\n"));
      },
      {"e.csv", "not a multiple of the 3 angles"});
  expectError(
      [&] {
        pio::readStructuralCompliance(
            m, write("f.csv", "node,phi_deg,y_mm\n1,0,0\n2,nan,0\n3,0,1\n4,90,1\n"));
      },
      {"f.csv:3"});
}

}  // namespace
