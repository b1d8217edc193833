// One meaning of "surface 1" project-wide (SurfacePair.h, BoundaryFriction.h): the film
// and contact grids sit on surface 2 = the skirt; surface 1 = the liner moves with the
// sliding velocity U relative to it (lubrication/FilmProblem.h).
//
// Independent reference: the film solver of lubrication/, which computes the Couette shear
// on each surface from its own discretisation (FilmResult::shearOnSurface1/2). On a uniform
// gap the pressure is flat, so the film's shear on each surface is pure Couette drag:
// the moving liner drags the skirt along U. Boundary friction, used as documented, must
// point the same way on each surface, and do negative work on each surface's motion
// relative to the other.

#include <gtest/gtest.h>

#include <cmath>

#include "pistondyn/contact_forces/BoundaryFriction.h"
#include "pistondyn/contact_forces/GreenwoodTrippLaw.h"
#include "pistondyn/lubrication/FilmSolver.h"
#include "pistondyn/lubrication/PatirChengFlowFactors.h"

namespace pc = pistondyn::contact_forces;
namespace pl = pistondyn::lubrication;

namespace {

// One liner/skirt description, filled into both modules' parameter sets with the mapping
// of contact_forces/README.md ("Which surface is surface 1").
struct SkirtLiner {
  double rqLiner_m = 0.25e-6;
  double rqSkirt_m = 0.6e-6;
};

pc::GreenwoodTrippParameters contactParameters(const SkirtLiner& s) {
  pc::GreenwoodTrippParameters p;
  p.roughnessSurface1_m = s.rqLiner_m;
  p.roughnessSurface2_m = s.rqSkirt_m;
  return p;
}

pl::PatirChengParameters filmParameters(const SkirtLiner& s) {
  pl::PatirChengParameters p;
  p.rq1_m = s.rqLiner_m;
  p.rq2_m = s.rqSkirt_m;
  return p;
}

}  // namespace

// The defaults say surface 1 = liner: cast iron, 0.3 µm; surface 2 = skirt: aluminium.
TEST(SurfaceConvention, ContactDefaultsPutTheLinerFirst) {
  const pc::GreenwoodTrippParameters p;
  EXPECT_EQ(p.surface1.youngsModulus_Pa, pc::kCastIronLiner.youngsModulus_Pa);
  EXPECT_EQ(p.surface2.youngsModulus_Pa, pc::kPistonAluminium.youngsModulus_Pa);
  EXPECT_EQ(p.roughnessSurface1_m, 0.3e-6);
  EXPECT_EQ(p.roughnessSurface2_m, 0.4e-6);
}

// Entered once, the roughness gives the same composite σ in both modules (reference:
// hypot written here), so h/σ, the regime and the flow factors agree node by node.
TEST(SurfaceConvention, OneRoughnessPairGivesOneSigmaInBothModules) {
  const SkirtLiner s;
  const pc::GreenwoodTrippLaw contact(contactParameters(s));
  const pl::PatirChengFlowFactors film(filmParameters(s));
  const double sigma = std::hypot(s.rqLiner_m, s.rqSkirt_m);
  // 4e-16: a few ulps, the rounding of √(a² + b²) against hypot.
  EXPECT_NEAR(contact.compositeSigma_m(), sigma, 4e-16 * sigma);
  EXPECT_NEAR(film.compositeSigma_m(), sigma, 4e-16 * sigma);
}

// Friction signs against the film solver. U has an axial and a circumferential component
// (x circumferential, y axial, as on the skirt grid); the gap is uniform (10 µm, h/σ = 15),
// so the film's shear is Couette drag: along +U on the skirt (surface 2), along −U on the
// liner (surface 1).
TEST(SurfaceConvention, BoundaryFrictionOnTheSkirtPointsLikeTheFilmsCouetteShear) {
  const SkirtLiner s;
  const pl::PatirChengFlowFactors factors(filmParameters(s));
  const pl::FilmGrid grid = pl::FilmGrid::uniform(9, 0.02, 17, 0.03);
  pl::FilmProblem problem;
  problem.gap_m = Eigen::ArrayXd::Constant(grid.nodeCount(), 10e-6);
  problem.viscosity_Pas = 0.01;
  problem.flowFactors = &factors;
  const Eigen::Vector2d U(0.4, -3.0);  // liner relative to skirt [m/s]
  problem.slidingVelocity_mps = U;
  pl::FilmSolver solver;
  const pl::FilmResult film = solver.solve(grid, problem);
  ASSERT_TRUE(film.converged);
  const Eigen::Vector2d filmOnSkirt = film.shearOnSurface2.couetteForce_N;
  const Eigen::Vector2d filmOnLiner = film.shearOnSurface1.couetteForce_N;
  // The film reference itself: drag along U on the skirt, against U on the liner.
  ASSERT_GT(filmOnSkirt.dot(U), 0.0);
  ASSERT_LT(filmOnLiner.dot(U), 0.0);

  for (pc::FrictionRegularisation kind :
       {pc::FrictionRegularisation::Algebraic, pc::FrictionRegularisation::Tanh}) {
    pc::BoundaryFrictionParameters fp;
    fp.regularisation = kind;
    const pc::BoundaryFriction friction(fp);
    const double p = 2e6;
    // As documented: v = velocity of the receiving surface relative to the other.
    const Eigen::Vector2d skirtRelativeToLiner = -U;
    const Eigen::Vector2d onSkirt = friction.calcShearStress_Pa(p, skirtRelativeToLiner);
    const Eigen::Vector2d onLiner = friction.calcShearStress_Pa(p, U);
    // Negative work on each surface's motion relative to the other.
    EXPECT_LT(onSkirt.dot(skirtRelativeToLiner), 0.0);
    EXPECT_LT(onLiner.dot(U), 0.0);
    // Action and reaction.
    EXPECT_NEAR((onSkirt + onLiner).norm(), 0.0, 1e-12 * onSkirt.norm());
    // Same direction as the film's Couette shear on the same surface (cosine 1: both are
    // parallel to U on a uniform gap, up to the solver's tolerance).
    EXPECT_NEAR(onSkirt.dot(filmOnSkirt) / (onSkirt.norm() * filmOnSkirt.norm()), 1.0, 1e-9);
    EXPECT_NEAR(onLiner.dot(filmOnLiner) / (onLiner.norm() * filmOnLiner.norm()), 1.0, 1e-9);
  }
}
