// Each elastic coupling scheme alone (AitkenCoupling, NewtonCoupling, ModalCoupling through
// makeElasticCoupling) on a film function with a closed-form coupled solution: a linear film
// law p = p_ref - k h_el on the nodes of a thrust side, a half-space skirt compliance (Love's
// patch integral, ElasticCouplingTestSupport.h). With h_el = -H u (H the Hermite interpolation
// of structural values on the film nodes), f = -M p (M the consistent force map) and u = C f,
// the coupled deformation solves the linear system
//   (I + C M K H) u = -C M p_ref,
// solved here directly (a dense LU of the structural system). Every scheme must reach it to
// its tolerance; the loop's gain is above one, so the plain fixed point would not.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include <Eigen/LU>

#include "ElasticCouplingTestSupport.h"
#include "SkirtTestSupport.h"
#include "pistondyn/mapping/CylinderGrid.h"
#include "pistondyn/mapping/ForceMap.h"
#include "pistondyn/mapping/HermiteSurface.h"
#include "pistondyn/skirt/ElasticCoupling.h"

namespace ps = pistondyn::skirt;
namespace pm = pistondyn::mapping;

namespace {

struct LinearFilmCase {
  ps::SkirtSideGrid side;
  pm::StructuralCompliance compliance;
  pm::CylinderGrid structural;
  Eigen::ArrayXd referencePressure_Pa, stiffness_Pa_per_m;
};

LinearFilmCase linearFilmCase() {
  ps::SkirtSideGridParameters gp = ps::test::thrustSide(24, 18);
  gp.arcWidth_rad = 1.0;
  const ps::SkirtSideGrid side(gp);
  const double R = gp.radius_m;
  const Eigen::VectorXd phiS = pm::uniformNodes(-0.6, 0.6, 9);
  const Eigen::VectorXd yS = pm::uniformNodes(-0.025, 0.015, 7);
  pm::StructuralCompliance c = ps::test::halfSpaceCompliance(R, phiS, yS, 70e9, 0.33);
  const int n = side.nodeCount();
  Eigen::ArrayXd p(n), k(n);
  for (int i = 0; i < n; ++i) {
    const double phi = side.getNodePhi_rad()[i], y = side.getNodeY_m()[i] + 0.005;
    p[i] = 40e6 * std::exp(-std::pow(R * phi / 0.008, 2) - std::pow(y / 0.012, 2));
    k[i] = 3.0 * p[i] / 0.5e-6 + 1e11;  // a squeeze film's 3 p / h at 0.5 um, and a floor
  }
  return {side, c, pm::CylinderGrid::sector(R, phiS, yS), p, k};
}

// The coupled gap term of the linear film law, by a direct solve (the file comment).
Eigen::ArrayXd directSolution(const LinearFilmCase& c) {
  const pm::CylinderGrid& film = c.side.getCylinderGrid();
  const Eigen::Index ns = c.structural.nodeCount(), nf = film.nodeCount();
  const Eigen::MatrixXd M = pm::ForceMap(film, c.structural, {0.0, 0.0}).matrix();
  pm::HermiteSurface surface(c.structural, Eigen::VectorXd::Zero(ns));
  pm::HermiteGridWorkspace ws;
  Eigen::MatrixXd H(nf, ns);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(ns), column(nf);
  for (Eigen::Index j = 0; j < ns; ++j) {
    unit[j] = 1.0;
    surface.updateValues(unit);
    surface.evaluateOnGrid(film, {0.0, 0.0}, column, ws, pm::OutsidePolicy::ExtendEndCells);
    H.col(j) = column;
    unit[j] = 0.0;
  }
  const Eigen::MatrixXd& C = c.compliance.compliance_m_per_N;
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(ns, ns) +
                            C * M * c.stiffness_Pa_per_m.matrix().asDiagonal() * H;
  const Eigen::VectorXd u = A.partialPivLu().solve(-C * (M * c.referencePressure_Pa.matrix()));
  return -(H * u).array();
}

TEST(CouplingSchemes, EachSchemeReachesTheDirectSolutionOfALinearFilm) {
  const LinearFilmCase c = linearFilmCase();
  const Eigen::ArrayXd reference = directSolution(c);
  const double scale = reference.abs().maxCoeff();
  ASSERT_GT(scale, 1e-7);  // a deformation of a tenth of a micrometre or more
  const ps::FilmPressureFunction film = [&](const Eigen::ArrayXd& elastic_m,
                                            ps::FilmPressureEvaluation& out) {
    out.normalPressure_Pa = c.referencePressure_Pa - c.stiffness_Pa_per_m * elastic_m;
    out.minFilmThickness_m = 1e-6;
    out.pressureStiffness_Pa_per_m = c.stiffness_Pa_per_m;  // exact: -dp/dh
  };
  for (const ps::ElasticCouplingScheme scheme :
       {ps::ElasticCouplingScheme::Aitken, ps::ElasticCouplingScheme::Newton,
        ps::ElasticCouplingScheme::Modal}) {
    ps::ElasticCouplingParameters p;
    p.scheme = scheme;
    p.absoluteTolerance_m = 1e-13;
    p.relativeTolerance = 0.0;
    p.deformationRelativeTolerance = 1e-7;
    p.maxIterations = 200;
    p.modes = 1000;  // every mode of the loaded nodes: the modal equations are the full ones
    const std::unique_ptr<ps::ElasticCoupling> coupling =
        ps::makeElasticCoupling(c.side, c.compliance, p);
    const ps::ElasticCouplingReport r = coupling->solve(film);
    const double error = (coupling->pistonElastic_m() - reference).abs().maxCoeff();
    std::printf("[CouplingSchemes] scheme %d: %d film evaluations, error %.2e of the largest "
                "deformation %.3e m\n",
                static_cast<int>(scheme), r.iterations, error / scale, scale);
    EXPECT_TRUE(r.converged);
    EXPECT_LT(error, 1e-5 * scale);
    if (scheme == ps::ElasticCouplingScheme::Modal) {
      EXPECT_LE(r.iterations, 3);  // a linear law with its exact Jacobian: one Newton step
    }
  }
  // The plain fixed point (relaxation fixed at 1) does not converge: the loop's gain is > 1.
  ps::ElasticCouplingParameters plain;
  plain.initialRelaxation = plain.minRelaxation = plain.maxRelaxation = 1.0;
  plain.residualGrowthLimit = 1e9;
  plain.absoluteTolerance_m = 1e-13;
  plain.relativeTolerance = 0.0;
  plain.deformationRelativeTolerance = 1e-7;
  plain.maxIterations = 50;
  EXPECT_FALSE(ps::makeElasticCoupling(c.side, c.compliance, plain)->solve(film).converged);
}

}  // namespace
