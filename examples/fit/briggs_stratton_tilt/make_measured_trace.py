#!/usr/bin/env python3
"""Makes measured_tilt.csv for fit.yaml: the Briggs & Stratton example run by pistondyn with
fit.yaml's shared overrides at known inputs, its tilt plus Gaussian noise.

    examples/fit/briggs_stratton_tilt/make_measured_trace.py PISTONDYN [OUT.csv]

Standard library only (random.gauss with a fixed seed), so any python3 runs it.
"""
import csv
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DECK = os.path.join(HERE, "..", "..", "engines", "briggs_stratton_500", "engine.yaml")
SHARED = [
    "simulation.cycles=1", "simulation.until_periodic=false",
    "liner.grid.nodes_circumferential=16", "liner.grid.nodes_axial=12",
    "simulation.stepper_order=3", "simulation.max_step_deg=1", "simulation.pose_tolerance_nm=10",
    "liner.film.fallback_to_reference=false", "simulation.jacobian_reuse_steps=20",
    "liner.film.cavitation=reynolds", "liner.oil_supply.film_um=null",
    "liner.oil_supply.fully_flooded=true", "simulation.output_step_deg=2",
]
# The known inputs: the deck's own values.
TRUTH = ["liner.oil.temperature_degC=40", "liner.cold_radial_clearance_um=53",
         "piston.com_above_pin_mm=6"]
NOISE_MRAD = 0.05
SEED = 2024


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    out = sys.argv[2] if len(sys.argv) == 3 else os.path.join(HERE, "measured_tilt.csv")
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "run")
        args = [sys.argv[1], "run", DECK, "--out", run, "--quiet", "--no-plot"]
        for o in SHARED + TRUTH:
            args += ["--set", o]
        subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(run, "cycle.csv")) as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    rng = random.Random(SEED)
    with open(out, "w") as f:
        f.write("# Synthetic measured tilt of the Briggs & Stratton example (fit.yaml's shared "
                "overrides)\n")
        f.write("# made by make_measured_trace.py: pistondyn run at " + ", ".join(TRUTH) + "\n")
        f.write("# plus Gaussian noise N(0, %g mrad), random.Random(%d); crank angle 0 deg = "
                "firing TDC\n" % (NOISE_MRAD, SEED))
        f.write("crank_angle_deg,tilt_mrad\n")
        for r in rows:
            angle = float(r["crank_angle_deg"])
            if 0.0 <= angle < 720.0:
                f.write("%s,%.6f\n" % (r["crank_angle_deg"],
                                        float(r["tilt_mrad"]) + rng.gauss(0.0, NOISE_MRAD)))


if __name__ == "__main__":
    main()
