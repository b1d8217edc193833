// The Simbody crank train with the ideal-liner guide against closed forms written here,
// independently of the library: kinematics by implicit differentiation of the loop
// closure |P - C| = L (the library uses the rod angle instead), TDC found as the root of
// dy/dphi, side force / conrod force / crank torque from a Newton-Euler free-body
// balance of piston+pin and rod, and the power balance of the whole model.
// Run over 720 deg for both example engines (examples/engines/*/engine.yaml).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/plugin/CycleSimulation.h"

namespace {

using pistondyn::io::EngineDeck;

struct V2 {
  double x, y;
};
V2 operator-(V2 a, V2 b) {
  return {a.x - b.x, a.y - b.y};
}
V2 operator+(V2 a, V2 b) {
  return {a.x + b.x, a.y + b.y};
}
V2 operator*(double k, V2 a) {
  return {k * a.x, k * a.y};
}
double cross(V2 a, V2 b) {
  return a.x * b.y - a.y * b.x;
}
double dot(V2 a, V2 b) {
  return a.x * b.x + a.y * b.y;
}

// Slider-crank with the pin on the line x = e, crank pin C = r(-sin phi, cos phi),
// crank turning at constant omega. Everything from the loop closure
// f = (e - Cx)^2 + (y - Cy)^2 - L^2 = 0 and its time derivatives.
struct ClosedForm {
  double r, L, e, omega;

  struct Kin {
    V2 C, Cd, Cdd, P, Pd, Pdd;
  };
  Kin at(double phi) const {
    Kin k;
    const double s = std::sin(phi), c = std::cos(phi), w = omega;
    k.C = {-r * s, r * c};
    k.Cd = {-r * c * w, -r * s * w};
    k.Cdd = {r * s * w * w, -r * c * w * w};
    const double y = k.C.y + std::sqrt(L * L - (e - k.C.x) * (e - k.C.x));
    const double yd = k.Cd.y + (e - k.C.x) * k.Cd.x / (y - k.C.y);
    const double ydd =
        k.Cdd.y +
        ((e - k.C.x) * k.Cdd.x - k.Cd.x * k.Cd.x - (yd - k.Cd.y) * (yd - k.Cd.y)) / (y - k.C.y);
    k.P = {e, y};
    k.Pd = {0, yd};
    k.Pdd = {0, ydd};
    return k;
  }
  // TDC: root of dy/dphi (= yd / omega) near phi = 0, by bisection to machine precision.
  double tdcPhi() const {
    auto slope = [&](double phi) { return at(phi).Pd.y; };
    double lo = -0.3, hi = 0.3;  // y rises before TDC (slope > 0) and falls after
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (slope(mid) > 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

// Newton-Euler balance at constant crank speed, piston upright and centred (ideal
// guide). Piston side: the piston and, unless it is clamped in the rod, the pin; it
// translates with the pin centre P. Rod side: the rod and, when clamped in it, the pin
// (mass at P, turning with the rod). F = force of the rod side on the piston side at P.
//   piston side, y:   m_ps y'' = F_y - F_gas - m_ps g
//   rod side, moments about the crank pin C (eliminates the crank force):
//     sum_k (r_k - C) x m_k (a_k - g) + sum_k I_k alpha_rod = -(P - C) x F
//   piston side, x:   0 = F_x + N  (N: liner on piston)
//   piston side, moments about P (translating body):
//     pinOffset F_gas - d m_p g + M_guide = d m_p y'',  d = comX - pinOffset
struct Loads {
  double sideForceOnLiner_N, conrodCompression_N, rodTorqueOnCrank_Nm, driveTorque_Nm,
      guideMomentOnLiner_Nm;
};
Loads freeBody(const EngineDeck& d, const ClosedForm::Kin& k, double gasForce_N) {
  const auto& m = d.engine.mass;
  const double g = d.engine.gravity_mps2, L = d.engine.geometry.conrodLength_m;
  const V2 grav{0, -g};
  const bool pinWithRod = d.engine.pinJoint == pistondyn::mbd::PinJoint::FixedInRod;
  const double mps = m.piston.mass_kg + (pinWithRod ? 0.0 : m.pin.mass_kg);
  const double mr = m.conrod.mass_kg, lG = m.conrod.comY_m;  // rod COM on its axis
  const V2 G = k.C + (lG / L) * (k.P - k.C);
  const V2 aG = k.Cdd + (lG / L) * (k.Pdd - k.Cdd);
  const double alphaRod = cross(k.P - k.C, k.Pdd - k.Cdd) / (L * L);

  const double Y = mps * k.Pdd.y + gasForce_N + mps * g;
  double S = cross(G - k.C, mr * (aG - grav)) + m.conrod.inertiaZZ_kgm2 * alphaRod;
  V2 rodSideMassAcc = mr * (aG - grav);
  if (pinWithRod) {
    S += cross(k.P - k.C, m.pin.mass_kg * (k.Pdd - grav)) + m.pin.inertiaZZ_kgm2 * alphaRod;
    rodSideMassAcc = rodSideMassAcc + m.pin.mass_kg * (k.Pdd - grav);
  }
  const V2 PC = k.P - k.C;
  const double X = (S + PC.x * Y) / PC.y;
  const V2 F{X, Y};
  const V2 Fcr = rodSideMassAcc + F;  // crank on rod side
  Loads out;
  out.sideForceOnLiner_N = X;
  out.conrodCompression_N = dot(F, (1.0 / L) * PC);
  out.rodTorqueOnCrank_Nm = cross(k.C, -1.0 * Fcr);
  const V2 throwDir = (1.0 / d.engine.geometry.crankRadius_m) * k.C;
  const V2 Gc = m.crank.comY_m * throwDir;  // crank COM on the throw (comX = 0)
  out.driveTorque_Nm = -out.rodTorqueOnCrank_Nm - cross(Gc, m.crank.mass_kg * grav);
  const double pinOffset = d.engine.geometry.pinOffset_m;
  const double dx = m.piston.comX_m - pinOffset;
  out.guideMomentOnLiner_Nm = -(dx * m.piston.mass_kg * (k.Pdd.y + g) - pinOffset * gasForce_N);
  return out;
}

struct Engine {
  const char* name;
  const char* deck;
  std::vector<std::string> overrides;  // --set assignments applied to the deck
};

class ClosedFormEngines : public ::testing::TestWithParam<Engine> {};

std::string deckPath(const Engine& e) {
  return std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/" + e.deck + "/engine.yaml";
}

// The closed forms hold for the ideal guide, which the example decks do not select (they
// run the lubricated skirt): every deck here is loaded with these overrides first. The
// guide holds the piston by constraints, so an explicit integrator; one cycle at a time.
std::vector<std::string> withIdealGuide(const std::vector<std::string>& overrides) {
  std::vector<std::string> all = {"liner.model=ideal_guide", "simulation.integrator=rk_merson",
                                  "simulation.until_periodic=false", "simulation.cycles=1"};
  all.insert(all.end(), overrides.begin(), overrides.end());
  return all;
}

// The passenger-car example deck (the thesis' parameter-study operating point) on the
// ideal guide, with --set overrides.
EngineDeck loadGasolineDeck(const std::vector<std::string>& overrides) {
  return pistondyn::io::loadEngineDeck(
      std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/gasoline_1400_2000rpm/engine.yaml",
      withIdealGuide(overrides));
}

// Swept volume of a deck's engine [m^3].
double displacement_m3(const EngineDeck& deck) {
  const pistondyn::mbd::SliderCrank kin(deck.engine.geometry);
  return pistondyn::mbd::CylinderVolume(kin, deck.engine.piston.bore_m,
                                        deck.engine.geometry.compressionRatio)
      .displacement_m3();
}

// "Not near zero": above 1e-3 of the cycle's largest magnitude.
double maxAbs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v)
    m = std::max(m, std::abs(x));
  return m;
}

TEST_P(ClosedFormEngines, KinematicsLoadsAndPowerOver720Degrees) {
  const EngineDeck deck =
      pistondyn::io::loadEngineDeck(deckPath(GetParam()), withIdealGuide(GetParam().overrides));
  ASSERT_EQ(deck.linerModel, "ideal_guide");
  ASSERT_EQ(deck.engine.drive.mode, pistondyn::mbd::CrankDrive::Mode::ConstantSpeed);
  auto model = pistondyn::io::buildModel(deck);
  pistondyn::plugin::SimulationSettings settings = deck.simulation;
  settings.outputStep_deg = 1.0;
  settings.cycles = 1;

  // Power balance of the Simbody model at every row: drive + gas + gravity power
  // = d(kinetic energy)/dt, with the ideal guide doing no work.
  const auto& ct = model->getCrankTrain();
  const auto& mass = deck.engine.mass;
  std::vector<double> powerResidual, drivePower, constraintPower;
  auto observer = [&](const SimTK::State& s) {
    const double g = deck.engine.gravity_mps2;
    double dKE = 0.0, gravityPower = 0.0;
    const SimTK::MobilizedBody* bodies[] = {&ct.getCrank(), &ct.getConrod(), &ct.getPin(),
                                            &ct.getPiston()};
    const pistondyn::mbd::PlanarMassProperties* props[] = {&mass.crank, &mass.conrod, &mass.pin,
                                                           &mass.piston};
    for (int b = 0; b < 4; ++b) {
      const SimTK::Vec3 com(props[b]->comX_m, props[b]->comY_m, 0);
      const SimTK::Vec3 v = bodies[b]->findStationVelocityInGround(s, com);
      const SimTK::Vec3 a = bodies[b]->findStationAccelerationInGround(s, com);
      const double w = bodies[b]->getBodyAngularVelocity(s)[2];
      const double alpha = bodies[b]->getBodyAngularAcceleration(s)[2];
      dKE += props[b]->mass_kg * SimTK::dot(v, a) + props[b]->inertiaZZ_kgm2 * w * alpha;
      gravityPower += -props[b]->mass_kg * g * v[1];
    }
    const double theta_deg = ct.getCrankAngle_rad(s) * 180.0 / M_PI;
    const double area = 0.25 * M_PI * std::pow(deck.engine.piston.bore_m, 2);
    const double gasForce =
        (deck.cylinderPressure->calcPressure_Pa(theta_deg) - deck.crankcasePressure_Pa) * area;
    const SimTK::Vec3 crownVelocity =
        ct.getPiston().findStationVelocityInGround(s, ct.getCrownCentreInPiston());
    const double gasPower = -gasForce * crownVelocity[1];
    const double pDrive = ct.getDriveTorque_Nm(s) * ct.getCrankSpeed_radps(s);
    drivePower.push_back(pDrive);
    powerResidual.push_back(pDrive + gasPower + gravityPower - dKE);
    constraintPower.push_back(model->getMatter().calcConstraintPower(s));
  };

  pistondyn::plugin::CycleSimulation sim(*model, settings);
  const auto table = sim.run({}, observer);

  ClosedForm cf{deck.engine.geometry.crankRadius_m, deck.engine.geometry.conrodLength_m,
                deck.engine.geometry.crankOffset_m + deck.engine.geometry.pinOffset_m,
                deck.engine.drive.speed_radps};
  const double phiTdc = cf.tdcPhi();
  const auto angle = table.column("crank_angle_deg");
  const auto y = table.column("piston_y_m"), vy = table.column("piston_vy_mps"),
             ay = table.column("piston_ay_mps2");
  const auto side = table.column("side_force_N"), rod = table.column("conrod_force_N"),
             torque = table.column("crank_torque_Nm"), drive = table.column("drive_torque_Nm"),
             gas = table.column("gas_force_N"), moment = table.column("guide_moment_Nm");
  ASSERT_EQ(angle.size(), 721u);

  std::vector<double> yRef, vRef, aRef, sideRef, rodRef, torqueRef, driveRef, momentRef;
  for (std::size_t i = 0; i < angle.size(); ++i) {
    const auto k = cf.at(angle[i] * M_PI / 180.0 + phiTdc);
    yRef.push_back(k.P.y);
    vRef.push_back(k.Pd.y);
    aRef.push_back(k.Pdd.y);
    const Loads l = freeBody(deck, k, gas[i]);
    sideRef.push_back(l.sideForceOnLiner_N);
    rodRef.push_back(l.conrodCompression_N);
    torqueRef.push_back(l.rodTorqueOnCrank_Nm);
    driveRef.push_back(l.driveTorque_Nm);
    momentRef.push_back(l.guideMomentOnLiner_Nm);
  }
  // The tolerances: |dy| <= 1e-9 m; v, a, side force within 1e-6 relative where
  // not near zero (|ref| > 1e-3 of the cycle maximum). Conrod force and torques likewise.
  auto checkRelative = [&](const char* what, const std::vector<double>& got,
                           const std::vector<double>& ref) {
    const double scale = maxAbs(ref);
    if (scale == 0.0) {
      // Identically zero by symmetry (e.g. the guide moment without pin offset and
      // with a centred COM): compare with the moment scale peak gas force x bore.
      const double momentScale = maxAbs(gas) * deck.engine.piston.bore_m;
      std::printf("  %-16s reference is zero; max |value| %.3e (scale %.3e)\n", what, maxAbs(got),
                  momentScale);
      EXPECT_LE(maxAbs(got), 1e-9 * momentScale) << what;
      return;
    }
    double worst = 0.0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      if (std::abs(ref[i]) < 1e-3 * scale)
        continue;
      worst = std::max(worst, std::abs(got[i] - ref[i]) / std::abs(ref[i]));
    }
    RecordProperty(std::string("max_rel_error_") + what, std::to_string(worst));
    EXPECT_LE(worst, 1e-6) << what;
    std::printf("  %-16s max relative error %.3e\n", what, worst);
  };
  double worstY = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i)
    worstY = std::max(worstY, std::abs(y[i] - yRef[i]));
  std::printf("  %-16s max |error| %.3e m\n", "piston_y", worstY);
  EXPECT_LE(worstY, 1e-9);
  checkRelative("piston_vy", vy, vRef);
  checkRelative("piston_ay", ay, aRef);
  checkRelative("side_force", side, sideRef);
  // The crank train's own side force (the rod's lateral force across the small end) is
  // the same free-body X: on the ideal guide it is what the guide carries, so the two
  // columns agree to rounding.
  const auto crankTrainSide = table.column("crank_train_side_force_N");
  checkRelative("crank_train_side", crankTrainSide, sideRef);
  double worstAgreement = 0.0;
  for (std::size_t i = 0; i < side.size(); ++i)
    worstAgreement = std::max(worstAgreement, std::abs(crankTrainSide[i] - side[i]));
  std::printf("  crank-train vs liner side force: max |difference| %.3e N of %.3e N\n",
              worstAgreement, maxAbs(side));
  EXPECT_LE(worstAgreement, 1e-9 * maxAbs(side));
  checkRelative("conrod_force", rod, rodRef);
  checkRelative("crank_torque", torque, torqueRef);
  checkRelative("drive_torque", drive, driveRef);
  checkRelative("guide_moment", moment, momentRef);

  const double powerScale = maxAbs(drivePower);
  const double worstPower = maxAbs(powerResidual) / powerScale;
  std::printf("  power balance: max |residual| / max |drive power| = %.3e\n", worstPower);
  EXPECT_LE(worstPower, 1e-6);
  EXPECT_LE(maxAbs(constraintPower) / powerScale, 1e-6) << "the ideal guide must do no work";
}

// Both example decks as shipped (on the ideal guide), and variants of the gasoline deck
// that exercise
// what the decks leave at zero or default: offsets of both signs, a negative start
// angle, an off-axis piston COM, and the other two pin joints.
INSTANTIATE_TEST_SUITE_P(
    ExampleEngines, ClosedFormEngines,
    ::testing::Values(Engine{"briggs_stratton_500", "briggs_stratton_500", {}},
                      Engine{"gasoline", "gasoline_1400_2000rpm", {}},
                      Engine{"gasoline_offsets_start_minus90",
                             "gasoline_1400_2000rpm",
                             {"geometry.crank_offset_mm=3", "geometry.pin_offset_mm=-1",
                              "piston.com_towards_thrust_mm=1", "simulation.start_angle_deg=-90"}},
                      Engine{"gasoline_pin_fixed_in_rod",
                             "gasoline_1400_2000rpm",
                             {"pin.joint=fixed_in_rod", "geometry.crank_offset_mm=-3"}},
                      Engine{"gasoline_pin_fixed_in_piston",
                             "gasoline_1400_2000rpm",
                             {"pin.joint=fixed_in_piston", "piston.com_towards_thrust_mm=-0.5"}}),
    [](const auto& paramInfo) { return std::string(paramInfo.param.name); });

// Over a whole cycle at constant speed the rod's mean torque on the crank delivers the
// indicated work: mean torque = imep * V_d / (4 pi) (inertia and gravity torques
// average to zero over a period). imep from the pressure table, torque from Simbody.
TEST(CycleEnergy, MeanCrankTorqueEqualsIndicatedWork) {
  const EngineDeck deck = loadGasolineDeck({});
  auto model = pistondyn::io::buildModel(deck);
  pistondyn::plugin::SimulationSettings settings = deck.simulation;
  settings.outputStep_deg = 0.5;
  const auto table = pistondyn::plugin::CycleSimulation(*model, settings).run();
  const auto torque = table.column("crank_torque_Nm");
  double mean = 0.0;  // periodic trapezoid: drop the repeated last row
  for (std::size_t i = 0; i + 1 < torque.size(); ++i)
    mean += torque[i];
  mean /= static_cast<double>(torque.size() - 1);
  const double expected = pistondyn::io::calcDeckImep_Pa(deck) * displacement_m3(deck) / (4 * M_PI);
  std::printf("  mean crank torque %.9f N m, imep * Vd / 4pi %.9f N m\n", mean, expected);
  EXPECT_NEAR(mean, expected, 1e-6 * std::abs(expected));
}

// The deck's pressure table reproduces the thesis' imep (598 kPa) within 0.5 %.
TEST(CycleEnergy, FiredTableImepMatchesThesisValue) {
  const EngineDeck deck = loadGasolineDeck({});
  ASSERT_TRUE(deck.statedImep_Pa.has_value());
  EXPECT_DOUBLE_EQ(*deck.statedImep_Pa, 598e3);
  EXPECT_NEAR(pistondyn::io::calcDeckImep_Pa(deck), 598e3, 0.005 * 598e3);
}

}  // namespace

namespace {

// Free crank with flywheel, gas force and a constant load torque. Over exactly one
// cycle (rows land on crank angles) the configuration repeats, so potential energy
// returns and the kinetic energy changes by the gas work minus the load work:
//   KE(720) - KE(0) = imep * V_d - T_load * 4 pi
// (gas work along the ideal-guide path is the closed integral of p dV).
TEST(FreeCrank, CycleEnergyBalanceWithGasAndLoad) {
  const EngineDeck deck = loadGasolineDeck(
      {"drive.mode=free", "drive.flywheel_inertia_kg_m2=0.08", "drive.load_torque_Nm=10",
       "simulation.output_step_deg=2", "simulation.accuracy=1e-11"});
  auto model = pistondyn::io::buildModel(deck);
  std::vector<double> energy;
  const auto& system = model->getSystem();
  auto observer = [&](const SimTK::State& s) {
    energy.push_back(system.calcKineticEnergy(s) + system.calcPotentialEnergy(s));
  };
  pistondyn::plugin::CycleSimulation sim(*model, deck.simulation);
  const auto table = sim.run({}, observer);
  const double gasWork = pistondyn::io::calcDeckImep_Pa(deck) * displacement_m3(deck);
  const double loadWork = 10.0 * 4.0 * M_PI;
  // The potential energy also holds the gravity of the reciprocating parts; it returns
  // with the configuration, so the total mechanical energy change is the same.
  const double dE = energy.back() - energy.front();
  std::printf("  dE = %.9f J, gas work - load work = %.9f J (gas %.6f J), %ld steps\n", dE,
              gasWork - loadWork, gasWork, sim.getStats().integratorSteps);
  EXPECT_NEAR(dE, gasWork - loadWork, 1e-6 * gasWork);
  // The rows really are at the nominal angles (landing to 1e-12 rad).
  const auto angle = table.column("crank_angle_deg");
  EXPECT_DOUBLE_EQ(angle.back(), 720.0);
}

// The textbook slider-crank side force: with a rod of no mass, the small end carries the
// force along the rod only, so its lateral part is the piston side's axial load (gas force
// + inertia + weight) times tan(rod angle) - the form of every engine-dynamics text. The
// gasoline deck with a rod of 1e-6 g (allowed as implausible) on the ideal guide; the rod
// angle from the closed-form kinematics above (tan = (P - C).x / (P - C).y).
TEST(CrankTrainSideForce, IsTheAxialLoadTimesTanRodAngleForAMasslessRod) {
  const EngineDeck deck =
      loadGasolineDeck({"conrod.mass_g=1e-6", "conrod.inertia_kg_mm2=1e-9",
                        "checks.allow_implausible=[conrod.mass_g, conrod.inertia_kg_mm2]"});
  auto model = pistondyn::io::buildModel(deck);
  pistondyn::plugin::SimulationSettings settings = deck.simulation;
  pistondyn::plugin::CycleSimulation sim(*model, settings);
  const auto table = sim.run();
  const auto& g = deck.engine.geometry;
  const ClosedForm cf{g.crankRadius_m, g.conrodLength_m, g.crankOffset_m + g.pinOffset_m,
                      deck.engine.drive.speed_radps};
  const double phiTdc = cf.tdcPhi();
  const auto& m = deck.engine.mass;
  const double pistonSide_kg = m.piston.mass_kg + m.pin.mass_kg;  // floating pin
  const auto angle = table.column("crank_angle_deg"), gas = table.column("gas_force_N"),
             side = table.column("crank_train_side_force_N");
  std::vector<double> ref;
  for (std::size_t i = 0; i < angle.size(); ++i) {
    const auto k = cf.at(angle[i] * M_PI / 180.0 + phiTdc);
    const V2 rod = k.P - k.C;
    const double axial = gas[i] + pistonSide_kg * (k.Pdd.y + deck.engine.gravity_mps2);
    ref.push_back(axial * rod.x / rod.y);
  }
  const double scale = maxAbs(ref);
  double worst = 0.0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (std::abs(ref[i]) >= 1e-3 * scale)
      worst = std::max(worst, std::abs(side[i] - ref[i]) / std::abs(ref[i]));
  }
  std::printf("  crank-train side force vs (gas + inertia) tan(rod angle): max rel. error %.3e\n",
              worst);
  EXPECT_LE(worst, 1e-6);
}

}  // namespace
