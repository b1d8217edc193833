// BoundaryFriction: Coulomb limit, dissipation on random sliding histories (energy
// balance), continuity at zero speed, and the velocity Jacobian against central differences.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "pistondyn/contact_forces/BoundaryFriction.h"

namespace pc = pistondyn::contact_forces;

namespace {
constexpr double kPi = 3.14159265358979323846;
const pc::FrictionRegularisation kBoth[] = {pc::FrictionRegularisation::Algebraic,
                                            pc::FrictionRegularisation::Tanh};

pc::BoundaryFriction makeFriction(pc::FrictionRegularisation kind) {
  pc::BoundaryFrictionParameters p;  // f = 0.1 (thesis), v_ε = 1 mm/s
  p.regularisation = kind;
  return pc::BoundaryFriction(p);
}
}  // namespace

// Far above v_ε the stress is Coulomb's f·p opposite to the sliding direction (hand value:
// f = 0.1, p = 2 MPa, v = (3, −4) m/s → τ = −0.2 MPa · (0.6, −0.8)); below the
// regularisation it is smaller, never larger.
TEST(BoundaryFriction, OpposesSlidingAndReachesCoulomb) {
  for (auto kind : kBoth) {
    const pc::BoundaryFriction friction = makeFriction(kind);
    const Eigen::Vector2d tau = friction.calcShearStress_Pa(2.0e6, Eigen::Vector2d(3.0, -4.0));
    EXPECT_NEAR(tau.x(), -0.12e6, 0.12e6 * 1e-6);
    EXPECT_NEAR(tau.y(), 0.16e6, 0.16e6 * 1e-6);
    for (double speed : {1e-6, 1e-4, 1e-3, 1e-2, 1.0}) {
      EXPECT_LE(friction.calcEffectiveCoefficient(speed), 0.1);
    }
    // Documented fractions of f at v = v_ε: 1/√2 (algebraic), tanh 1 (tanh).
    const double atVeps = friction.calcEffectiveCoefficient(1e-3) / 0.1;
    EXPECT_NEAR(atVeps,
                kind == pc::FrictionRegularisation::Algebraic ? std::sqrt(0.5) : std::tanh(1.0),
                1e-15);
  }
}

// Energy balance: over random sliding histories (random walks through zero speed in 2-D,
// random pressures, 200 seeds per regularisation) the friction power τ·v is never positive
// and the work ∫τ·v dt is negative whenever anything slid under load.
TEST(BoundaryFriction, DoesNegativeWorkOnRandomHistories) {
  for (auto kind : kBoth) {
    const pc::BoundaryFriction friction = makeFriction(kind);
    for (unsigned seed = 1; seed <= 200; ++seed) {
      std::mt19937_64 rng(seed);
      std::normal_distribution<double> kick(0.0, 2e-3);       // m/s per step
      std::uniform_real_distribution<double> load(0.0, 5e6);  // Pa
      Eigen::Vector2d v(kick(rng), kick(rng));
      const double dt = 1e-5;
      double work = 0.0;
      for (int step = 0; step < 2000; ++step) {
        v += Eigen::Vector2d(kick(rng), kick(rng));
        if (step % 500 == 0) {
          v = -v;  // hard reversal through zero, as at a dead centre
        }
        const double power = friction.calcShearStress_Pa(load(rng), v).dot(v);
        ASSERT_LE(power, 0.0) << "seed " << seed << ", step " << step;
        work += power * dt;
      }
      ASSERT_LT(work, 0.0) << "seed " << seed;
    }
  }
}

// Continuity at zero speed: τ → 0 from every direction, with |τ| ≤ f·p·|v|/v_ε (both
// forms have slope f·p/v_ε at the origin and less elsewhere), and τ(0) = 0 exactly.
TEST(BoundaryFriction, ContinuousAtZeroSpeed) {
  for (auto kind : kBoth) {
    const pc::BoundaryFriction friction = makeFriction(kind);
    const double p = 1e6;
    EXPECT_EQ(friction.calcShearStress_Pa(p, Eigen::Vector2d::Zero()).norm(), 0.0);
    for (int k = 0; k < 16; ++k) {
      const double angle = 2.0 * kPi * k / 16.0;
      const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
      for (double speed : {1e-3, 1e-6, 1e-9, 1e-12, 1e-15}) {
        const double magnitude = friction.calcShearStress_Pa(p, speed * direction).norm();
        ASSERT_LE(magnitude, 0.1 * p * speed / 1e-3 * (1.0 + 1e-12));
      }
      // Opposite tiny velocities give opposite stresses that differ by no more than the
      // slope bound allows: no Coulomb sign jump through zero (a jump would be 2·f·p).
      const Eigen::Vector2d plus = friction.calcShearStress_Pa(p, 1e-9 * direction);
      const Eigen::Vector2d minus = friction.calcShearStress_Pa(p, -1e-9 * direction);
      EXPECT_NEAR((plus + minus).norm(), 0.0, 1e-12);
      EXPECT_LE((plus - minus).norm(), 2.0 * 0.1 * p * 1e-9 / 1e-3 * (1.0 + 1e-12));
    }
  }
}

// ∂τ/∂v against central differences of τ (independent), at speeds from 1e-7 v_ε to
// 100 v_ε in random directions; step 1e-6 of the speed scale.
TEST(BoundaryFriction, JacobianMatchesCentralDifference) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  for (auto kind : kBoth) {
    const pc::BoundaryFriction friction = makeFriction(kind);
    const double p = 3e6;
    for (double speed : {1e-10, 1e-7, 1e-5, 3e-4, 1e-3, 5e-3, 0.1}) {
      const double a = angle(rng);
      const Eigen::Vector2d v = speed * Eigen::Vector2d(std::cos(a), std::sin(a));
      const double step = 1e-6 * std::max(speed, 1e-3);
      Eigen::Matrix2d difference;
      for (int c = 0; c < 2; ++c) {
        Eigen::Vector2d dv = Eigen::Vector2d::Zero();
        dv(c) = step;
        difference.col(c) =
            (friction.calcShearStress_Pa(p, v + dv) - friction.calcShearStress_Pa(p, v - dv)) /
            (2.0 * step);
      }
      const Eigen::Matrix2d jacobian = friction.calcShearStressVelocityJacobian(p, v);
      const double scale = 0.1 * p / 1e-3;  // largest slope, at v = 0
      EXPECT_LE((jacobian - difference).norm(), 1e-6 * scale)
          << "speed " << speed << ", kind " << static_cast<int>(kind);
      EXPECT_NEAR(jacobian(0, 1), jacobian(1, 0), 1e-12 * scale);
    }
  }
}

// The field call equals the scalar call node by node.
TEST(BoundaryFriction, FieldMatchesScalarCalls) {
  const pc::BoundaryFriction friction = makeFriction(pc::FrictionRegularisation::Tanh);
  Eigen::ArrayXXd p(4, 3), vx(4, 3), vy(4, 3), tx, ty;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) {
      p(i, j) = 1e5 * (i + 1);
      vx(i, j) = 1e-3 * (i - 2) * (j + 1);
      vy(i, j) = 2e-4 * (j - 1);
    }
  }
  friction.calcShearStressField(p, vx, vy, tx, ty);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector2d tau =
          friction.calcShearStress_Pa(p(i, j), Eigen::Vector2d(vx(i, j), vy(i, j)));
      EXPECT_NEAR(tx(i, j), tau.x(), 1e-12 * p(i, j));
      EXPECT_NEAR(ty(i, j), tau.y(), 1e-12 * p(i, j));
    }
  }
}

// Extreme but finite speeds (reference: the limits of the formulas, written here). For
// |v| ≫ v_ε, τ = −f·p·v/|v| and ∂τ/∂v = −f·p/|v|·(I − e eᵀ) (e = v/|v|; the slope along v
// is (v_ε/|v|)³/v_ε or sech², both below 1e-300 here); for |v| ≪ v_ε, τ = −f·p·v/v_ε.
// Before the robust form, |v|² overflowed from |v| ≈ 1e154 and τ came out as exactly 0.
// 1e149 and 1e151 straddle the switch from the direct |v|² form to the scaled one.
TEST(BoundaryFriction, ExtremeFiniteSpeedsGiveTheirLimits) {
  const double f = 0.1, p = 2e6;
  const Eigen::Vector2d e(0.6, -0.8);
  for (auto kind : kBoth) {
    const pc::BoundaryFriction friction = makeFriction(kind);
    for (double speed : {1e149, 1e151, 1e154, 1e160, 1e200, 1e300, 1.7e308}) {
      const Eigen::Vector2d v = speed * e;
      const Eigen::Vector2d tau = friction.calcShearStress_Pa(p, v);
      EXPECT_LE((tau + f * p * e).norm(), 1e-15 * f * p) << "speed " << speed;
      EXPECT_NEAR(friction.calcEffectiveCoefficient(speed), f, 1e-17);
      const Eigen::Matrix2d expected =
          (-f * p / speed) * (Eigen::Matrix2d::Identity() - e * e.transpose());
      const Eigen::Matrix2d jacobian = friction.calcShearStressVelocityJacobian(p, v);
      EXPECT_LE((jacobian - expected).norm(), 1e-14 * expected.norm()) << "speed " << speed;
      // Field paths, per-node and uniform velocity.
      Eigen::ArrayXXd pf = Eigen::ArrayXXd::Constant(2, 1, p), vx(2, 1), vy(2, 1), tx, ty;
      vx.setConstant(v.x());
      vy.setConstant(v.y());
      friction.calcShearStressField(pf, vx, vy, tx, ty);
      EXPECT_NEAR(tx(1, 0), -f * p * e.x(), 1e-15 * f * p);
      EXPECT_NEAR(ty(1, 0), -f * p * e.y(), 1e-15 * f * p);
      friction.calcShearStressField(pf, v, tx, ty);
      EXPECT_NEAR(tx(0, 0), -f * p * e.x(), 1e-15 * f * p);
      EXPECT_NEAR(ty(0, 0), -f * p * e.y(), 1e-15 * f * p);
    }
    for (double speed : {1e-200, 1e-300, 4.9e-324}) {
      const Eigen::Vector2d v = speed * e;
      const Eigen::Vector2d tau = friction.calcShearStress_Pa(p, v);
      const Eigen::Vector2d expected = (-f * p / 1e-3) * v;
      EXPECT_LE((tau - expected).norm(), 1e-12 * expected.norm() + 1e-300) << "speed " << speed;
      const Eigen::Matrix2d jacobian = friction.calcShearStressVelocityJacobian(p, v);
      EXPECT_LE((jacobian + (f * p / 1e-3) * Eigen::Matrix2d::Identity()).norm(),
                1e-12 * f * p / 1e-3);
    }
  }
}

// One sliding velocity for a whole field equals the per-node call at every node (reference:
// the scalar call), including v = 0 and a purely axial speed.
TEST(BoundaryFriction, UniformVelocityFieldMatchesScalarCalls) {
  for (auto kind : kBoth) {
    const pc::BoundaryFriction friction = makeFriction(kind);
    Eigen::ArrayXXd p(5, 4), tx, ty;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i)
        p(i, j) = 1e5 * (i + 2 * j);  // includes p = 0
    for (const Eigen::Vector2d& v : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.0, -7.5),
                                     Eigen::Vector2d(3e-4, 1e-3), Eigen::Vector2d(-2.0, 0.5)}) {
      friction.calcShearStressField(p, v, tx, ty);
      ASSERT_EQ(tx.rows(), 5);
      ASSERT_EQ(ty.cols(), 4);
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 5; ++i) {
          const Eigen::Vector2d tau = friction.calcShearStress_Pa(p(i, j), v);
          EXPECT_NEAR(tx(i, j), tau.x(), 1e-15 * (1.0 + p(i, j)));
          EXPECT_NEAR(ty(i, j), tau.y(), 1e-15 * (1.0 + p(i, j)));
        }
    }
    Eigen::ArrayXXd bad = p;
    bad(3, 2) = -1.0;
    EXPECT_THROW(friction.calcShearStressField(bad, Eigen::Vector2d(1.0, 0.0), tx, ty),
                 std::invalid_argument);
  }
}
