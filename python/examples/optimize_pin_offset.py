#!/usr/bin/env python3
"""Notebook-style example: the pin offset of the gasoline example engine that minimises its
skirt friction (fmep), by scipy.optimize driving pistondyn through the Python module.

    PYTHONPATH=<build>/python python3 optimize_pin_offset.py [--evaluations N]

Each cell (# %%) runs in a notebook as it is. Without scipy (Debian python3-scipy) the example
evaluates a few pin offsets by hand and says so. The skirt is coarse and one cycle long (the
fast settings of README.md, "Benchmarks"): about 0.2 s a run. `pistondyn optimize` does the
same with constraints, resume and MPI (README.md, "The design loop").
"""
# %% Setup: the deck and the quick skirt settings
import argparse
import os

import pistondyn

HERE = os.path.dirname(os.path.abspath(__file__))
CANDIDATES = [os.path.join(HERE, "..", "..", "examples", "engines"),      # source tree
              os.path.join(HERE, "..", "engines")]                       # installed docs
ENGINES = next(p for p in CANDIDATES if os.path.isdir(p))
DECK = os.path.join(ENGINES, "gasoline_1400_2000rpm", "engine.yaml")
FAST = {
    "simulation.cycles": 1, "simulation.until_periodic": False,
    "liner.grid.nodes_circumferential": 16, "liner.grid.nodes_axial": 12,
    "simulation.stepper_order": 3, "simulation.max_step_deg": 1,
    "simulation.pose_tolerance_nm": 10,
    "liner.film.fallback_to_reference": False, "simulation.jacobian_reuse_steps": 20,
    "liner.film.cavitation": "reynolds", "liner.oil_supply.film_um": None,
    "liner.oil_supply.fully_flooded": True, "simulation.output_step_deg": 2,
}
parser = argparse.ArgumentParser()
parser.add_argument("--evaluations", type=int, default=20)
args, _ = parser.parse_known_args()

# %% The objective: fmep [kPa] of one run at a pin offset [mm]
history = []


def fmep_kPa(pin_offset_mm):
    result = pistondyn.run(DECK, overrides=dict(FAST, **{"geometry.pin_offset_mm": float(pin_offset_mm)}))
    value = result.figures["fmep_kPa"]
    history.append((float(pin_offset_mm), value))
    print("pin offset %+.4f mm: fmep %.4f kPa, min h/sigma %.2f" % (
        pin_offset_mm, value, min(result.figures["min_h_over_sigma_thrust"],
                                  result.figures["min_h_over_sigma_antithrust"])))
    return value


# %% Minimise it over -1 .. 1 mm with scipy, if it is there
try:
    from scipy.optimize import minimize_scalar
except ImportError:
    minimize_scalar = None

if minimize_scalar is not None:
    best = minimize_scalar(fmep_kPa, bounds=(-1.0, 1.0), method="bounded",
                           options={"maxiter": args.evaluations, "xatol": 1e-3})
    print("scipy: fmep %.4f kPa at a pin offset of %+.4f mm (%d runs)" % (
        best.fun, best.x, len(history)))
else:
    print("scipy is not installed (Debian python3-scipy): evaluating a few pin offsets instead")
    for offset in (-1.0, 0.0, 1.0)[: max(1, args.evaluations)]:
        fmep_kPa(offset)
    offset, value = min(history, key=lambda h: h[1])
    print("best of %d: fmep %.4f kPa at a pin offset of %+.4f mm" % (len(history), value, offset))
