// pistondyn::common's nodal-field convention and views (common/include/pistondyn/common/
// NodalField.h): node (i, j) of an nA x nB grid at k = i + nA*j, views without copies.
//
// Independent references: the index formula written out here, the addresses of the viewed
// memory, and the grids of lubrication/ and mapping/ that use the convention.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "ExpectInvalidArgument.h"
#include "pistondyn/common/NodalField.h"
#include "pistondyn/lubrication/FilmGrid.h"
#include "pistondyn/mapping/CylinderGrid.h"

namespace pc = pistondyn::common;

namespace {

// Field value that names its node: 100 i + j.
Eigen::ArrayXd namedField(int nA, int nB) {
  Eigen::ArrayXd f(nA * nB);
  for (int j = 0; j < nB; ++j)
    for (int i = 0; i < nA; ++i)
      f[i + nA * j] = 100.0 * i + j;
  return f;
}

}  // namespace

TEST(NodalField, GridViewPutsNodeIJAtIPlusNATimesJ) {
  const int nA = 5, nB = 3;
  const Eigen::ArrayXd field = namedField(nA, nB);
  const auto grid = pc::asGrid(field, nA, nB);
  ASSERT_EQ(grid.rows(), nA);
  ASSERT_EQ(grid.cols(), nB);
  for (int j = 0; j < nB; ++j)
    for (int i = 0; i < nA; ++i) {
      EXPECT_EQ(grid(i, j), 100.0 * i + j);
      EXPECT_EQ(pc::nodeIndex(i, j, nA), i + nA * j);
    }
}

// The views are views: same addresses, and writes go through to the field.
TEST(NodalField, ViewsShareTheFieldsMemory) {
  const int nA = 4, nB = 6;
  Eigen::ArrayXd field = namedField(nA, nB);
  auto grid = pc::asGrid(field, nA, nB);
  EXPECT_EQ(grid.data(), field.data());
  EXPECT_EQ(&grid(3, 5), &field[3 + nA * 5]);
  grid(2, 1) = -7.0;
  EXPECT_EQ(field[2 + nA * 1], -7.0);
  grid.col(4) = 0.5;  // all of node row j = 4
  for (int i = 0; i < nA; ++i)
    EXPECT_EQ(field[i + nA * 4], 0.5);

  auto column = pc::asColumnVector(field);
  EXPECT_EQ(column.data(), field.data());
  EXPECT_EQ(column.size(), field.size());
  column[5] = 42.0;
  EXPECT_EQ(field[5], 42.0);
  const Eigen::ArrayXd& constField = field;
  EXPECT_EQ(pc::asColumnVector(constField).data(), field.data());
  EXPECT_EQ(pc::asGrid(constField, nA, nB).data(), field.data());
  EXPECT_EQ(pc::asColumnVector(constField, nA, nB).data(), field.data());
  EXPECT_EQ(pc::asColumnVector(field, nA, nB).data(), field.data());
}

// A field handed on as an Eigen::Ref (an output argument, or a segment of a longer array) views
// the memory the Ref refers to, not a copy.
TEST(NodalField, GridViewOfARefIsAViewOfTheReferredMemory) {
  const int nA = 3, nB = 2;
  Eigen::ArrayXd storage = Eigen::ArrayXd::Zero(10);
  auto fill = [&](Eigen::Ref<Eigen::ArrayXd> field) {
    auto grid = pc::asGrid(field, nA, nB);
    EXPECT_EQ(grid.data(), field.data());
    grid(2, 1) = 5.0;
  };
  fill(storage.segment(4, nA * nB));
  EXPECT_EQ(storage[4 + 2 + nA * 1], 5.0);
  EXPECT_EQ(storage.sum(), 5.0);  // nothing else written
  const Eigen::Ref<const Eigen::ArrayXd> constRef = storage.segment(4, nA * nB);
  EXPECT_EQ(pc::asGrid(constRef, nA, nB).data(), storage.data() + 4);
  EXPECT_EQ(pc::asGrid(constRef, nA, nB)(2, 1), 5.0);
  pistondyn::test::expectInvalidArgument([&] { fill(storage.segment(0, 5)); },
                                         {"asGrid", "field has 5 entries", "3 * 2 = 6"});
}

// A column-major 2-D field (contact_forces) flattens to the same k = i + nA*j, in place.
TEST(NodalField, TwoDimensionalArrayFlattensInPlaceWithTheSameIndex) {
  const int nA = 3, nB = 7;
  Eigen::ArrayXXd grid(nA, nB);
  for (int j = 0; j < nB; ++j)
    for (int i = 0; i < nA; ++i)
      grid(i, j) = 100.0 * i + j;
  const auto column = pc::asColumnVector(grid);
  EXPECT_EQ(column.data(), grid.data());
  ASSERT_EQ(column.size(), nA * nB);
  const Eigen::ArrayXd flat = column.array();
  EXPECT_TRUE((flat == namedField(nA, nB)).all());
  pc::asColumnVector(grid)[pc::nodeIndex(1, 2, nA)] = -1.0;
  EXPECT_EQ(grid(1, 2), -1.0);
}

TEST(NodalField, ShapeThatDoesNotFitTheFieldThrows) {
  Eigen::ArrayXd field = Eigen::ArrayXd::Zero(12);
  const Eigen::ArrayXd& constField = field;
  using pistondyn::test::expectInvalidArgument;
  expectInvalidArgument([&] { (void)pc::asGrid(field, 5, 2); },
                        {"asGrid", "field has 12 entries", "nA * nB = 5 * 2 = 10"});
  expectInvalidArgument([&] { (void)pc::asGrid(constField, 4, 4); }, {"asGrid", "16"});
  expectInvalidArgument([&] { (void)pc::asColumnVector(constField, 13, 1); },
                        {"asColumnVector", "field has 12 entries"});
  expectInvalidArgument([&] { (void)pc::asColumnVector(field, 2, 5); }, {"asColumnVector"});
  expectInvalidArgument([&] { (void)pc::asGrid(field, -3, -4); }, {"asGrid", "-3 x -4"});
  EXPECT_NO_THROW((void)pc::asGrid(field, 3, 4));
  EXPECT_NO_THROW((void)pc::asGrid(field, 12, 1));
  const Eigen::ArrayXd empty;
  EXPECT_EQ(pc::asGrid(empty, 0, 9).size(), 0);
}

// The modules' grids number their nodes by the same rule (FilmGrid: nA = nx; CylinderGrid:
// nA = nPhi).
TEST(NodalField, FilmGridAndCylinderGridUseTheConvention) {
  const auto film = pistondyn::lubrication::FilmGrid::uniform(6, 0.01, 4, 0.02, false);
  const auto cylinder =
      pistondyn::mapping::CylinderGrid::sector(0.04, pistondyn::mapping::uniformNodes(-0.5, 0.5, 7),
                                               pistondyn::mapping::uniformNodes(0, 0.03, 5));
  for (int j = 0; j < film.ny(); ++j)
    for (int i = 0; i < film.nx(); ++i)
      EXPECT_EQ(film.nodeIndex(i, j), pc::nodeIndex(i, j, film.nx()));
  for (int j = 0; j < cylinder.nY(); ++j)
    for (int i = 0; i < cylinder.nPhi(); ++i)
      EXPECT_EQ(cylinder.index(i, j), pc::nodeIndex(i, j, cylinder.nPhi()));
  // The grids' own flat nodal arrays view as nx x ny: the area weights are the tensor product
  // of the 1-D weights, wx[i] * wy[j] at (i, j).
  const auto area = pc::asGrid(film.areaWeights_m2(), film.nx(), film.ny());
  for (int j = 0; j < film.ny(); ++j)
    for (int i = 0; i < film.nx(); ++i)
      EXPECT_DOUBLE_EQ(area(i, j), film.xWeights_m()[i] * film.yWeights_m()[j]);
}
