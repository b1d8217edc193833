// Generates the cylinder-pressure tables of the example engines (examples/engines/*),
// so that every committed table can be reproduced and its model is on record. The model is
// the library's single-zone cycle (mbd_models/SingleZonePressureModel.h, which `pistondyn
// new` uses too):
//   closed cycle IVC -> EVO:  dp/dtheta = (k-1)/V dQ/dtheta - k p/V dV/dtheta
//       with a Wiebe heat release Q = Q_tot (1 - exp(-a ((theta-theta_s)/dtheta)^(m+1)))
//       (a = 6.908 i.e. 99.9 % burnt at theta_s + dtheta, m = 2); Q_tot = 0 = motored.
//       k is an effective polytropic exponent (heat loss lumped in).
//   blow-down EVO -> EVO+60: cosine blend from p(EVO) to the exhaust pressure;
//   exhaust stroke at p_exh; 370 -> 400 deg cosine blend to the intake pressure;
//   intake stroke at p_int until IVC.
// With --target-imep-kPa the heat Q_tot is found by the secant method so that the
// net imep (closed integral of p dV over V_d, trapezoid at 0.01 deg) hits the target.
// This file is the command line: options, the file and its header.
//
// Usage (make_pressure_curve --help prints the options with units and defaults):
//        make_pressure_curve --bore-mm B --stroke-mm S --rod-mm L --cr CR
//          [--pin-offset-mm e] [--crank-offset-mm e] [--k 1.30] [--p-int-bar 1.0]
//          [--p-exh-bar 1.05] [--ivc-deg 580] [--evo-deg 140] [--soc-deg -15]
//          [--burn-deg 50] [--target-imep-kPa X] [--step-deg 0.5] --out FILE.csv

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pistondyn/io/PressureTableCsv.h"
#include "pistondyn/mbd_models/SingleZonePressureModel.h"
#include "pistondyn/mbd_models/SliderCrank.h"

namespace {

struct Params {
  double bore_mm = 0, stroke_mm = 0, rod_mm = 0, cr = 0, pinOffset_mm = 0, crankOffset_mm = 0;
  double k = 1.30, pInt_bar = 1.0, pExh_bar = 1.05, ivc_deg = 580, evo_deg = 140;
  double soc_deg = -15, burn_deg = 50, targetImep_kPa = NAN, step_deg = 0.5;
  std::string out;
};

constexpr double kFine_deg = pistondyn::mbd::kSingleZoneFineStep_deg;

const char* kHelp =
    "make_pressure_curve: writes a cylinder-pressure table (CSV crank_angle_deg,pressure_bar,\n"
    "absolute; crank angle 0 deg = firing TDC, 720 deg cycle) from a single-zone model: a\n"
    "polytropic closed cycle IVC -> EVO with a Wiebe heat release (a = 6.908, m = 2; none:\n"
    "motored), cosine blow-down to the exhaust pressure, exhaust and intake strokes at their\n"
    "pressures. The table is what a deck's gas.cylinder_pressure_file reads.\n"
    "\n"
    "usage: make_pressure_curve --bore-mm B --stroke-mm S --rod-mm L --cr CR --out FILE.csv\n"
    "                           [options]\n"
    "  --bore-mm B           cylinder bore [mm] (required)\n"
    "  --stroke-mm S         stroke = twice the crank radius [mm] (required)\n"
    "  --rod-mm L            connecting-rod length [mm] (required)\n"
    "  --cr CR               compression ratio, > 1 (required)\n"
    "  --out FILE.csv        the table to write (required)\n"
    "  --pin-offset-mm e     pin offset, + towards thrust [mm] (default 0)\n"
    "  --crank-offset-mm e   crank offset, + towards thrust [mm] (default 0)\n"
    "  --k K                 effective polytropic exponent, heat loss lumped in (default 1.30)\n"
    "  --p-int-bar P         intake pressure [bar] (default 1.0)\n"
    "  --p-exh-bar P         exhaust pressure [bar] (default 1.05)\n"
    "  --ivc-deg A           intake valve closing [deg] (default 580)\n"
    "  --evo-deg A           exhaust valve opening [deg] (default 140)\n"
    "  --soc-deg A           start of combustion [deg from firing TDC] (default -15)\n"
    "  --burn-deg A          combustion duration [deg] (default 50)\n"
    "  --target-imep-kPa X   find the heat release that gives this net imep [kPa] (default:\n"
    "                        none, motored)\n"
    "  --step-deg A          table step [deg], a multiple of 0.01 (default 0.5)\n"
    "  -h, --help            print this help and exit\n"
    "The file's header records the command and the resulting heat release and imep.\n"
    "Exit codes: 0 ok; 1 the file could not be written; 2 bad arguments.\n";

// Parses the arguments; false with `problem` set if they are bad.
bool parse(int argc, char** argv, Params& p, std::string& problem) {
  const std::map<std::string, double*> num = {{"--bore-mm", &p.bore_mm},
                                              {"--stroke-mm", &p.stroke_mm},
                                              {"--rod-mm", &p.rod_mm},
                                              {"--cr", &p.cr},
                                              {"--pin-offset-mm", &p.pinOffset_mm},
                                              {"--crank-offset-mm", &p.crankOffset_mm},
                                              {"--k", &p.k},
                                              {"--p-int-bar", &p.pInt_bar},
                                              {"--p-exh-bar", &p.pExh_bar},
                                              {"--ivc-deg", &p.ivc_deg},
                                              {"--evo-deg", &p.evo_deg},
                                              {"--soc-deg", &p.soc_deg},
                                              {"--burn-deg", &p.burn_deg},
                                              {"--target-imep-kPa", &p.targetImep_kPa},
                                              {"--step-deg", &p.step_deg}};
  for (int i = 1; i < argc; i += 2) {
    if (num.count(argv[i]) == 0 && std::strcmp(argv[i], "--out") != 0) {
      problem = std::string("unknown option ") + argv[i];
      return false;
    }
    if (i + 1 >= argc) {
      problem = std::string(argv[i]) + " needs a value";
      return false;
    }
    if (std::strcmp(argv[i], "--out") == 0) {
      p.out = argv[i + 1];
      continue;
    }
    char* end = nullptr;
    *num.at(argv[i]) = std::strtod(argv[i + 1], &end);
    if (*end != '\0' || end == argv[i + 1] || !std::isfinite(*num.at(argv[i]))) {
      problem = std::string(argv[i]) + " " + argv[i + 1] + ": not a number";
      return false;
    }
  }
  if (!(p.bore_mm > 0 && p.stroke_mm > 0 && p.rod_mm > 0)) {
    problem = "--bore-mm, --stroke-mm and --rod-mm are required and must be positive";
  } else if (!(p.cr > 1)) {
    problem = "--cr is required and must be greater than 1";
  } else if (p.out.empty()) {
    problem = "--out FILE.csv is required";
  } else if (!(p.step_deg >= kFine_deg)) {
    problem = "--step-deg must be at least 0.01";
  }
  return problem.empty();
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0) {
      std::fputs(kHelp, stdout);
      return 0;
    }
  }
  Params p;
  std::string problem;
  if (!parse(argc, argv, p, problem)) {
    std::fprintf(stderr, "make_pressure_curve: %s (make_pressure_curve --help: the options)\n",
                 problem.c_str());
    return 2;
  }
  pistondyn::mbd::CrankTrainGeometry g;
  g.crankRadius_m = 0.5e-3 * p.stroke_mm;
  g.conrodLength_m = 1e-3 * p.rod_mm;
  g.pinOffset_m = 1e-3 * p.pinOffset_mm;
  g.crankOffset_m = 1e-3 * p.crankOffset_mm;
  pistondyn::mbd::SingleZoneCycle cycle;
  cycle.polytropicExponent = p.k;
  cycle.intakePressure_Pa = p.pInt_bar * 1e5;
  cycle.exhaustPressure_Pa = p.pExh_bar * 1e5;
  cycle.intakeValveClosing_deg = p.ivc_deg;
  cycle.exhaustValveOpening_deg = p.evo_deg;
  cycle.combustionStart_deg = p.soc_deg;
  cycle.combustionDuration_deg = p.burn_deg;
  std::optional<double> target;
  if (std::isfinite(p.targetImep_kPa))
    target = p.targetImep_kPa * 1e3;
  pistondyn::mbd::SingleZonePressureTable table;
  try {
    const pistondyn::mbd::SliderCrank kin(g);
    const pistondyn::mbd::CylinderVolume vol(kin, 1e-3 * p.bore_mm, p.cr);
    table = pistondyn::mbd::makeSingleZonePressureTable(cycle, vol, target, p.step_deg);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "make_pressure_curve: %s (make_pressure_curve --help: the options)\n",
                 e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_pressure_curve: %s\n", e.what());
    return 1;
  }
  const double q = table.heatReleased_J, imep = table.netImep_Pa;

  std::string command = "command:";
  for (int i = 1; i < argc; ++i)
    command += std::string(" ") + argv[i];
  std::ostringstream result;  // default stream format, as the committed tables' headers
  result << "heat released Q_tot = " << q << " J per cycle; net imep (trapezoid at " << kFine_deg
         << " deg) = " << imep / 1e3 << " kPa";
  const std::string text = pistondyn::io::formatPressureTableCsv(
      table.crankAngle_deg, table.pressure_Pa,
      {"Generated by examples/tools/make_pressure_curve (single-zone model, see its header)",
       command, result.str(), "crank angle 0 deg = firing TDC; absolute pressure"});
  std::ofstream out(p.out);
  if (!out) {
    std::fprintf(stderr, "make_pressure_curve: cannot write %s\n", p.out.c_str());
    return 1;
  }
  out << text;
  out.close();
  if (!out) {
    std::fprintf(stderr, "make_pressure_curve: writing %s failed\n", p.out.c_str());
    return 1;
  }
  std::printf("make_pressure_curve: wrote %s, Q_tot %.3f J, net imep %.4f kPa\n", p.out.c_str(), q,
              imep / 1e3);
  return 0;
}
