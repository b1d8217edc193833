// temporary experiment: cycles of the skirt element on the gasoline engine
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include "pistondyn/cli/EngineDeck.h"
#include "pistondyn/lubrication/OilGrades.h"
#include "pistondyn/plugin/CycleSimulation.h"
#include "pistondyn/plugin/GasForceElement.h"
#include "pistondyn/plugin/LubricatedSkirtElement.h"
using namespace pistondyn;
int main(int argc, char** argv) {
  auto deck = cli::loadEngineDeck(std::string(PISTONDYN_SOURCE_DIR) + "/examples/engines/gasoline_1400_2000rpm/engine.yaml", {});
  mbd::EngineDescription e = deck.engine;
  e.tertiaryMotion = false;
  plugin::PistonAssemblyModel model(e);
  model.addElement(std::make_unique<plugin::GasForceElement>(*deck.cylinderPressure, deck.crankcasePressure_Pa));
  plugin::LubricatedSkirtParameters p;
  p.grid.arcWidth_rad = 80.0 * M_PI / 180.0;
  p.grid.nPhi = argc > 2 ? std::atoi(argv[2]) : 32; p.grid.nY = argc > 3 ? std::atoi(argv[3]) : 24;
  p.gap.coldRadialClearance_m = 20e-6;
  p.grid.axialClustering = argc > 5 ? std::atof(argv[5]) : 0.0;
  std::vector<double> hy, dr;
  for (int i = -25; i <= 25; ++i) { hy.push_back(i * 1e-3); double d = i + 8.0; dr.push_back((d > 0 ? 0.12 : 0.08) * d * d * 1e-6); }
  p.gap.skirtProfile.axial.height_m = Eigen::Map<Eigen::VectorXd>(hy.data(), hy.size()); p.gap.skirtProfile.axial.radialDrop_m = Eigen::Map<Eigen::VectorXd>(dr.data(), dr.size());
  p.gap.skirtProfile.ovality.diametralOvality_m = 300e-6;
  p.oil = lubrication::makeSaeGradeOilSpec(lubrication::SaeGrade::k0W30);
  p.roughness.rq1_m = 0.4e-6; p.roughness.rq2_m = 0.6e-6;
  p.supplyFilm.constant_m = argc > 4 ? std::atof(argv[4]) * 1e-6 : std::numeric_limits<double>::infinity();
  model.addElement(std::make_unique<plugin::LubricatedSkirtElement>(p));
  plugin::SimulationSettings s;
  s.integrator = plugin::SimulationSettings::Integrator::LinearlyImplicitBDF2;
  s.outputStep_deg = 2.0;
  s.cycles = argc > 1 ? std::atoi(argv[1]) : 1;
  plugin::CycleSimulation sim(model, s);
  auto t = sim.run();
  const auto& st = sim.getStats();
  printf("wall %.2f s steps %ld rejected %ld failed %ld realizations %ld\n", st.wallTime_s, st.integratorSteps, st.rejectedSteps, st.failedEvaluations, st.realizations);
  for (double f : st.cycleFmep_Pa) printf("fmep %.3f kPa\n", f / 1e3);
  const auto& liner = model.getElementAs<plugin::LubricatedSkirtElement>("lubricated_skirt");
  {
    auto af = t.column("asperity_friction_N"), hf = t.column("hydrodynamic_friction_N"), an = t.column("asperity_normal_force_antithrust_N"), at = t.column("asperity_normal_force_thrust_N"), vy = t.column("piston_vy_mps");
    double wa = 0, wh = 0, amax = 0, atmax = 0;
    for (size_t i = 0; i + 1 < af.size(); ++i) { wa += std::abs(af[i] * vy[i]); wh += std::abs(hf[i]*vy[i]); amax = std::max(amax, an[i]); atmax = std::max(atmax, at[i]); }
    double dt = t.column("time_s")[1] - t.column("time_s")[0];
    printf("work asperity %.4f J hydro %.4f J (row sums); max asperity normal anti %.1f thrust %.1f N\n", wa*dt, wh*dt, amax, atmax);
  }
  printf("visc %.4g Pa s hot clearance %.2f um\n", liner.getViscosity_Pas(), *liner.getHotRunningClearance_m() * 1e6);
  auto a = t.column("crank_angle_deg"), u = t.column("u_lat_um"), tl = t.column("tilt_mrad"), sf = t.column("side_force_N"), ht = t.column("min_film_thickness_thrust_um"), ha = t.column("min_film_thickness_antithrust_um"), fp = t.column("friction_power_W");
  for (size_t i = 0; i < a.size(); i += 15) printf("%6.0f u %7.2f tilt %7.3f side %8.1f hT %7.2f hA %7.2f P %7.2f\n", a[i], u[i], tl[i], sf[i], ht[i], ha[i], fp[i]);
}
