// Bad input: every parameter check throws std::invalid_argument whose message names the
// struct or function, the member (and row) and what was expected (docs/CONVENTIONS.md).
// Reference: the messages the conventions ask for.
#include <gtest/gtest.h>

#include <cmath>

#include "ExpectInvalidArgument.h"
#include "SkirtTestSupport.h"
#include "pistondyn/skirt/GapAssembly.h"

namespace ps = pistondyn::skirt;
using pistondyn::test::expectInvalidArgument;
using ps::test::kPi;

namespace {

ps::GapAssemblyParameters valid() {
  ps::GapAssemblyParameters p;
  p.coldRadialClearance_m = 50e-6;
  p.linerTopHeight_m = 0.25;
  p.travel = {0.12, 0.20};
  return p;
}

template <class Edit>
void expectGridRejected(Edit edit, std::initializer_list<std::string_view> fragments) {
  ps::SkirtSideGridParameters p = ps::test::thrustSide();
  edit(p);
  expectInvalidArgument([&] { ps::SkirtSideGrid g(p); }, fragments);
}

template <class Edit>
void expectAssemblyRejected(Edit edit, std::initializer_list<std::string_view> fragments) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(9, 7));
  ps::GapAssemblyParameters p = valid();
  edit(p);
  expectInvalidArgument([&] { ps::GapAssembly a(g, p); }, fragments);
}

TEST(SkirtBadInput, SkirtSideGridParameters) {
  using P = ps::SkirtSideGridParameters;
  const char* s = "SkirtSideGridParameters";
  expectGridRejected([](P& p) { p.radius_m = 0.0; }, {s, "radius_m", "positive"});
  expectGridRejected([](P& p) { p.arcWidth_rad = kPi; },
                     {s, "arcWidth_rad", "less than pi", "a skirt grid wider than the skirt"});
  expectGridRejected([](P& p) { p.arcWidth_rad = 4.0; }, {"a skirt grid wider than the skirt"});
  expectGridRejected([](P& p) { p.arcWidth_rad = -0.1; }, {s, "arcWidth_rad", "positive"});
  expectGridRejected([](P& p) { p.arcWidth_rad = NAN; }, {s, "arcWidth_rad", "finite"});
  expectGridRejected([](P& p) { p.nPhi = 2; }, {s, "nPhi = 2", "at least 3"});
  expectGridRejected([](P& p) { p.nY = 1; }, {s, "nY = 1", "at least 3"});
  expectGridRejected([](P& p) { p.skirtTopHeight_m = INFINITY; },
                     {s, "skirtTopHeight_m", "finite"});
  expectGridRejected([](P& p) { p.skirtLength_m = -0.01; }, {s, "skirtLength_m", "positive"});
  expectGridRejected([](P& p) { p.axialClustering = -1.0; },
                     {s, "axialClustering", "non-negative"});
  expectGridRejected([](P& p) { p.circumferentialClustering = -0.5; },
                     {s, "circumferentialClustering", "non-negative"});
}

TEST(SkirtBadInput, CalcLoadsOnPiston) {
  const ps::SkirtSideGrid g(ps::test::thrustSide(5, 4));
  Eigen::ArrayXd p = Eigen::ArrayXd::Zero(20), small = Eigen::ArrayXd::Zero(19);
  expectInvalidArgument([&] { g.calcLoadsOnPiston(small); },
                        {"SkirtSideGrid::calcLoadsOnPiston", "normalPressure_Pa", "expected 20"});
  expectInvalidArgument([&] { g.calcLoadsOnPiston(p, small, p); },
                        {"axialShear_Pa", "19 entries", "or 0 for none"});
  Eigen::ArrayXd bad = p;
  bad[7] = NAN;
  expectInvalidArgument([&] { g.calcLoadsOnPiston(p, p, bad); },
                        {"circumferentialShear_Pa[7]", "finite"});
}

TEST(SkirtBadInput, AxialProfileParameters) {
  using P = ps::GapAssemblyParameters;
  const char* s = "AxialProfileParameters";
  const auto table = [](P& p, Eigen::VectorXd h) {
    p.skirtProfile.axial.height_m = h;
    p.skirtProfile.axial.radialDrop_m = Eigen::VectorXd::Zero(h.size());
  };
  expectAssemblyRejected(
      [&](P& p) {
        Eigen::VectorXd h(5);
        h << -0.03, -0.01, 0.01, 0.005, 0.03;  // row 3 goes back down
        table(p, h);
      },
      {s, "height_m[3] = 0.005", "greater than height_m[2] = 0.01", "strictly increasing"});
  expectAssemblyRejected(
      [&](P& p) {
        table(p, Eigen::VectorXd::LinSpaced(4, -0.03, 0.03));
        p.skirtProfile.axial.radialDrop_m.resize(3);
      },
      {s, "radialDrop_m has 3 entries", "height_m has 4"});
  expectAssemblyRejected(
      [&](P& p) {
        table(p, Eigen::VectorXd::LinSpaced(4, -0.03, 0.03));
        p.skirtProfile.axial.radialDrop_m[2] = NAN;
      },
      {s, "radialDrop_m[2]", "finite"});
  // the grid is y in [-25, 15] mm
  expectAssemblyRejected([&](P& p) { table(p, Eigen::VectorXd::LinSpaced(4, -0.02, 0.03)); },
                         {s, "height_m covers [-0.02, 0.03]", "needs [-0.025, 0.015]"});
  expectAssemblyRejected(
      [&](P& p) {
        table(p, Eigen::VectorXd::LinSpaced(4, -0.03, 0.02));
        p.skirtProfile.axial.mirrored = true;  // needs [-0.015, 0.025]
      },
      {s, "mirrored", "needs [-0.015, 0.025]"});
}

TEST(SkirtBadInput, OvalityParameters) {
  using P = ps::GapAssemblyParameters;
  const char* s = "OvalityParameters";
  expectAssemblyRejected([](P& p) { p.skirtProfile.ovality.cos4Coefficient = 0.6; },
                         {s, "cos4Coefficient = 0.6", "[-0.5, 0.5]", "monotone"});
  expectAssemblyRejected([](P& p) { p.skirtProfile.ovality.diametralOvality_m = NAN; },
                         {s, "diametralOvality_m", "finite"});
  const auto table = [](P& p, Eigen::VectorXd a, Eigen::VectorXd d) {
    p.skirtProfile.ovality.model = ps::OvalityModel::Table;
    p.skirtProfile.ovality.tableAngle_rad = a;
    p.skirtProfile.ovality.tableRadialDrop_m = d;
  };
  expectAssemblyRejected(
      [&](P& p) { table(p, Eigen::Vector3d(0.1, 0.5, 1.0), Eigen::Vector3d(0, 1e-6, 2e-6)); },
      {s, "tableAngle_rad[0] = 0.1", "must be 0", "one quadrant"});
  expectAssemblyRejected(
      [&](P& p) { table(p, Eigen::Vector3d(0.0, 0.5, 1.0), Eigen::Vector3d(1e-6, 1e-6, 2e-6)); },
      {s, "tableRadialDrop_m[0]", "must be 0", "thrust-axis radius"});
  expectAssemblyRejected(
      [&](P& p) { table(p, Eigen::Vector3d(0.0, 1.0, 2.0), Eigen::Vector3d(0, 1e-6, 2e-6)); },
      {s, "tableAngle_rad[2] = 2", "at most pi/2"});
  expectAssemblyRejected(
      [&](P& p) { table(p, Eigen::Vector3d(0.0, 0.2, 0.4), Eigen::Vector3d(0, 1e-6, 2e-6)); },
      {s, "tableAngle_rad covers [0, 0.4]", "needs [0, 0.52"});
  expectAssemblyRejected(
      [&](P& p) { table(p, Eigen::Vector3d(0.0, 0.8, 0.7), Eigen::Vector3d(0, 1e-6, 2e-6)); },
      {s, "tableAngle_rad[2] = 0.7", "strictly increasing"});
}

TEST(SkirtBadInput, BoreDistortionParameters) {
  using P = ps::GapAssemblyParameters;
  const char* s = "BoreDistortionParameters";
  const auto order = [](int n) {
    ps::BoreDistortionOrder o;
    o.order = n;
    o.depth_m = Eigen::Vector2d(0.0, 0.1);
    o.amplitude_m = Eigen::Vector2d(1e-6, 2e-6);
    o.phase_rad = Eigen::Vector2d(0.0, 0.1);
    return o;
  };
  expectAssemblyRejected([&](P& p) { p.linerShape.orders = {order(13)}; },
                         {s, "orders[0].order = 13", "0..12"});
  expectAssemblyRejected([&](P& p) { p.linerShape.orders = {order(-1)}; },
                         {s, "orders[0].order = -1"});
  expectAssemblyRejected(
      [&](P& p) {
        p.linerShape.orders = {order(4), order(2), order(4)};
      },
      {s, "orders[2].order = 4", "twice"});
  expectAssemblyRejected(
      [&](P& p) {
        p.linerShape.orders = {order(3)};
        p.linerShape.orders[0].depth_m[1] = 0.0;
      },
      {s, "orders[0].depth_m[1] = 0", "strictly increasing"});
  expectAssemblyRejected(
      [&](P& p) {
        p.linerShape.orders = {order(3)};
        p.linerShape.orders[0].phase_rad.resize(1);
      },
      {s, "orders[0].phase_rad has 1 entries"});
  expectAssemblyRejected(
      [&](P& p) {
        p.linerShape.orders = {order(1), order(5)};
        p.linerShape.orders[1].amplitude_m[0] = INFINITY;
      },
      {s, "orders[1].amplitude_m[0]", "finite"});
  expectAssemblyRejected(
      [&](P& p) {
        p.linerShape.orders = {order(2)};
        p.linerTopHeight_m = NAN;
      },
      {"GapAssemblyParameters", "linerTopHeight_m", "finite"});
}

TEST(SkirtBadInput, ThermalParameters) {
  using P = ps::GapAssemblyParameters;
  expectAssemblyRejected(
      [](P& p) {
        p.pistonThermal.expansionCoefficient_perK = 21e-6;
        p.pistonThermal.height_m = Eigen::Vector3d(-0.03, 0.0, 0.03);
        p.pistonThermal.temperature_degC = Eigen::Vector3d(150.0, -280.0, 200.0);
      },
      {"PistonThermalParameters", "temperature_degC[1] = -280", "above absolute zero"});
  expectAssemblyRejected(
      [](P& p) {
        p.pistonThermal.height_m = Eigen::Vector2d(-0.03, 0.03);
        p.pistonThermal.temperature_degC = Eigen::Vector2d(150.0, 200.0);
      },
      {"PistonThermalParameters", "expansionCoefficient_perK = nan", "must be set"});
  expectAssemblyRejected(
      [](P& p) {
        p.pistonThermal.expansionCoefficient_perK = 21e-6;
        p.pistonThermal.nodalTemperature_degC = Eigen::ArrayXd::Constant(10, 150.0);
      },
      {"PistonThermalParameters", "nodalTemperature_degC has 10 entries", "expected 63"});
  expectAssemblyRejected(
      [](P& p) {
        p.pistonThermal.expansionCoefficient_perK = 21e-6;
        p.pistonThermal.nodalTemperature_degC = Eigen::ArrayXd::Constant(63, 150.0);
        p.pistonThermal.nodalTemperature_degC[40] = -273.15;  // at absolute zero
      },
      {"nodalTemperature_degC[40] = -273.15", "above absolute zero"});
  expectAssemblyRejected(
      [](P& p) {
        p.linerThermal.expansionCoefficient_perK = -1e-6;
        p.linerThermal.depth_m = Eigen::Vector2d(0.0, 0.2);
        p.linerThermal.temperature_degC = Eigen::Vector2d(120.0, 80.0);
      },
      {"LinerThermalParameters", "expansionCoefficient_perK = -1e-06", "non-negative"});
  expectAssemblyRejected(
      [](P& p) {
        p.linerThermal.expansionCoefficient_perK = 11e-6;
        p.linerThermal.depth_m = Eigen::Vector2d(0.2, 0.0);
        p.linerThermal.temperature_degC = Eigen::Vector2d(120.0, 80.0);
      },
      {"LinerThermalParameters", "depth_m[1] = 0", "strictly increasing"});
  expectAssemblyRejected([](P& p) { p.referenceTemperature_degC = -300.0; },
                         {"GapAssemblyParameters", "referenceTemperature_degC = -300"});
}

TEST(SkirtBadInput, GapAssemblyParameters) {
  using P = ps::GapAssemblyParameters;
  const char* s = "GapAssemblyParameters";
  expectAssemblyRejected([](P& p) { p.coldRadialClearance_m = NAN; },
                         {s, "coldRadialClearance_m = nan", "finite"});
  expectAssemblyRejected([](P& p) { p.travel.lowestPinHeight_m = NAN; },
                         {s, "travel.lowestPinHeight_m", "finite"});
  expectAssemblyRejected(
      [](P& p) {
        p.travel = {0.2, 0.1};
      },
      {s, "travel.highestPinHeight_m = 0.1", "must not be below"});
  expectAssemblyRejected([](P& p) { p.coldRadialClearance_m = -1e-6; },
                         {"hot running clearance is -1e-06 m", "thrust side"});
}

}  // namespace
