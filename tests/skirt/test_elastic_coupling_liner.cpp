// skirt::ElasticCoupling with the elastic liner ("The liner" in ElasticCoupling.h): the
// gasoline example's committed FE skirt and liner (examples/fe/gasoline_1400_2000rpm, read by a
// plain parser), its thrust side's film grid, and a fixed film pressure (a smooth load that
// does not depend on the gap, so the coupled answer is the compliances' linear response).
// References independent of the code under test:
//   1. the liner's part of the gap term (with liner minus without) against the liner's own
//      route: the pressure mapped straight onto the liner grid at the pin's height
//      (mapping::ForceMap, consistent loads), u_L = C_L f, read on the film nodes by the bicubic
//      spline of the liner grid (mapping::HermiteSurface); at a pin height on a liner row, one
//      between rows and one near TDC, where the liner's clamped top shapes the response;
//   2. the modal scheme with every mode of the side's nodes gives the Aitken answer;
//   3. bad input: a liner that is not a full circle, the Newton scheme, a solve before the
//      position is set, a pin height that takes the skirt off the liner grid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ElasticCouplingTestSupport.h"
#include "ExpectInvalidArgument.h"
#include "pistondyn/mapping/ForceMap.h"
#include "pistondyn/mapping/HermiteSurface.h"
#include "pistondyn/skirt/ElasticCoupling.h"
#include "pistondyn/skirt/ModalCoupling.h"

namespace {

namespace ps = pistondyn::skirt;
namespace pm = pistondyn::mapping;

// A smooth load on the thrust side [Pa]: a cosine bump centred on the thrust line and 4 mm
// below the pin axis, 3 MPa at its peak (1.25 kN in total: the example's peak side force).
Eigen::ArrayXd bumpPressure(const ps::SkirtSideGrid& side) {
  Eigen::ArrayXd p(side.nodeCount());
  for (int k = 0; k < side.nodeCount(); ++k) {
    const double phi = side.getNodePhi_rad()[k], y = side.getNodeY_m()[k];
    const double a = std::cos(phi / 0.7 * 1.5707963267948966);
    const double b = std::cos((y + 0.004) / 0.016 * 1.5707963267948966);
    p[k] = 3e6 * std::max(a, 0.0) * std::max(a, 0.0) * std::max(b, 0.0) * std::max(b, 0.0);
  }
  return p;
}

ps::FilmPressureFunction fixedFilm(const Eigen::ArrayXd& p) {
  return [p](const Eigen::ArrayXd&, ps::FilmPressureEvaluation& out) {
    out.normalPressure_Pa = p;
    out.minFilmThickness_m = 5e-6;
    out.pressureStiffness_Pa_per_m = Eigen::ArrayXd::Zero(p.size());
  };
}

ps::ElasticCouplingParameters aitken() {
  ps::ElasticCouplingParameters c;
  c.scheme = ps::ElasticCouplingScheme::Aitken;
  c.absoluteTolerance_m = 1e-13;
  c.relativeTolerance = 0.0;
  c.deformationRelativeTolerance = 0.0;
  c.maxIterations = 200;
  return c;
}

// The gap term of the deformation under the fixed pressure [m], with or without the liner.
Eigen::ArrayXd gapTerm(const ps::SkirtSideGrid& side, const pm::StructuralCompliance& skirt,
                       const pm::StructuralCompliance* liner, double pinHeight_m,
                       const ps::ElasticCouplingParameters& parameters) {
  const auto owned = ps::makeElasticCoupling(side, skirt, parameters, liner);
  ps::ElasticCoupling& coupling = *owned;
  if (liner)
    coupling.setLinerPosition(pinHeight_m);
  const ps::ElasticCouplingReport r = coupling.solve(fixedFilm(bumpPressure(side)));
  EXPECT_TRUE(r.converged) << r.residual_m;
  return coupling.pistonElastic_m();
}

// The liner's own route: consistent loads on the liner grid (+ outward), its compliance, its
// bicubic spline on the film nodes. Returns the gap opening [m].
Eigen::ArrayXd linerRoute(const ps::SkirtSideGrid& side, const pm::StructuralCompliance& liner,
                          double pinHeight_m, double& totalForce_N) {
  const pm::CylinderGrid linerGrid =
      pm::CylinderGrid::fullCircle(side.getRadius_m(), liner.phi_rad, liner.y_m);
  const pm::ForceMap map(side.getCylinderGrid(), linerGrid, {0.0, pinHeight_m});
  Eigen::VectorXd f(linerGrid.nodeCount());
  const pm::LoadBalance b = map.apply(bumpPressure(side).matrix(), f);
  EXPECT_EQ(b.unmapped_N, 0.0);
  totalForce_N = f.sum();
  const Eigen::VectorXd u = liner.compliance_m_per_N * f;
  const pm::HermiteSurface surface(linerGrid, u);
  Eigen::VectorXd onFilm(side.nodeCount());
  pm::HermiteGridWorkspace ws;
  surface.evaluateOnGrid(side.getCylinderGrid(), {0.0, pinHeight_m}, onFilm, ws);
  return onFilm.array();
}

TEST(ElasticCouplingLiner, LinerPartMatchesTheLinersOwnGridRoute) {
  const ps::SkirtSideGrid side = ps::test::gasolineThrustSide();
  const pm::StructuralCompliance skirt = ps::test::gasolineCompliance("skirt");
  const pm::StructuralCompliance liner = ps::test::gasolineCompliance("liner");
  const Eigen::ArrayXd rigidLiner = gapTerm(side, skirt, nullptr, 0.0, aitken());
  // Pin heights [m]: the gasoline liner's rows lie 5 mm apart from 82 mm; 0.130 puts the pin
  // row 12 mm above the pin on a liner row, 0.1325 half-way between two.
  for (const double pinHeight_m : {0.130, 0.1325, 0.1795}) {
    const Eigen::ArrayXd withLiner = gapTerm(side, skirt, &liner, pinHeight_m, aitken());
    const Eigen::ArrayXd linerPart = withLiner - rigidLiner;
    double total_N = 0.0;
    const Eigen::ArrayXd expected = linerRoute(side, liner, pinHeight_m, total_N);
    const double scale = expected.abs().maxCoeff();
    const double error = (linerPart - expected).abs().maxCoeff();
    std::printf(
        "[ElasticCouplingLiner] pin at %.4f m: liner opening %.3f um (own route), skirt alone "
        "%.3f um; largest difference %.4f um = %.2f %% of the liner's; load %.1f N\n",
        pinHeight_m, 1e6 * scale, 1e6 * rigidLiner.abs().maxCoeff(), 1e6 * error,
        100.0 * error / scale, total_N);
    EXPECT_GT(scale, 0.1e-6);  // the liner gives: a real check
    // Two interpolation routes (through the skirt's 3 mm rows, or straight): ~1 % apart; a
    // liner read one row (5 mm) off is 2-3 % off in the liner's middle.
    EXPECT_LT(error, 0.02 * scale);
    EXPECT_GT(linerPart.maxCoeff(), 0.0);  // the liner's give opens the gap
  }
}

// The committed files' own asymmetry (6e-8 of the largest diagonal entry) symmetrised, as
// pistondyn::io's reader does: the modal scheme works on the symmetric part, Aitken on the
// matrix as given, and this test compares the schemes, not the files.
pm::StructuralCompliance symmetric(pm::StructuralCompliance c) {
  const Eigen::MatrixXd s = 0.5 * (c.compliance_m_per_N + c.compliance_m_per_N.transpose());
  c.compliance_m_per_N = s;
  return c;
}

TEST(ElasticCouplingLiner, ModalWithEveryModeGivesTheAitkenAnswer) {
  const ps::SkirtSideGrid side = ps::test::gasolineThrustSide();
  const pm::StructuralCompliance skirt = symmetric(ps::test::gasolineCompliance("skirt"));
  const pm::StructuralCompliance liner = symmetric(ps::test::gasolineCompliance("liner"));
  ps::ElasticCouplingParameters modal = aitken();
  modal.scheme = ps::ElasticCouplingScheme::Modal;
  modal.modes = 1000;  // all of the side's nodes
  const double pinHeight_m = 0.1325;
  const Eigen::ArrayXd a = gapTerm(side, skirt, &liner, pinHeight_m, aitken());
  const Eigen::ArrayXd m = gapTerm(side, skirt, &liner, pinHeight_m, modal);
  const double error = (a - m).abs().maxCoeff();
  std::printf("[ElasticCouplingLiner] modal (all modes) vs Aitken: %.2e m of %.3e m\n", error,
              a.abs().maxCoeff());
  EXPECT_LT(error, 1e-9 * a.abs().maxCoeff() + 1e-12);
  // The same coupling moved back and forth returns the same modes' answer.
  ps::ModalCoupling coupling(side, skirt, modal, &liner);
  coupling.setLinerPosition(0.100);
  (void)coupling.solve(fixedFilm(bumpPressure(side)));
  coupling.setLinerPosition(pinHeight_m);
  const ps::ElasticCouplingReport r = coupling.solve(fixedFilm(bumpPressure(side)));
  ASSERT_TRUE(r.converged);
  EXPECT_LT((coupling.pistonElastic_m() - m).abs().maxCoeff(), 1e-9 * m.abs().maxCoeff() + 1e-12);
}

TEST(ElasticCouplingLinerBadInput, NamesTheProblem) {
  const ps::SkirtSideGrid side = ps::test::gasolineThrustSide(8, 6);
  const pm::StructuralCompliance skirt = ps::test::gasolineCompliance("skirt");
  const pm::StructuralCompliance liner = ps::test::gasolineCompliance("liner");
  using pistondyn::test::expectInvalidArgument;
  pm::StructuralCompliance sector = liner;
  sector.fullCircle = false;
  expectInvalidArgument([&] { const auto c = ps::makeElasticCoupling(side, skirt, aitken(), &sector); },
                        "full circle");
  ps::ElasticCouplingParameters newton = aitken();
  newton.scheme = ps::ElasticCouplingScheme::Newton;
  expectInvalidArgument([&] { const auto c = ps::makeElasticCoupling(side, skirt, newton, &liner); },
                        "modal or the Aitken");
  expectInvalidArgument(
      [&] {
        const auto c = ps::makeElasticCoupling(side, skirt, aitken(), &liner);
        (void)c->solve(fixedFilm(bumpPressure(side)));
      },
      "setLinerPosition");
  // Liner rows from 82 to 192 mm, skirt rows -18 .. +12 mm about the pin: a pin at 185 mm puts
  // the skirt top at 197 mm.
  expectInvalidArgument(
      [&] {
        const auto c = ps::makeElasticCoupling(side, skirt, aitken(), &liner);
        c->setLinerPosition(0.185);
      },
      "outside the liner's heights");
  expectInvalidArgument(
      [&] {
        const auto c = ps::makeElasticCoupling(side, skirt, aitken());
        c->setLinerPosition(0.1);
      },
      "no liner");
}

}  // namespace
