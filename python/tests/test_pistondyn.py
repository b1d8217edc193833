"""The Python module against the program: a run through pistondyn.run() equals the same run
through `pistondyn run` (every summary figure and every cycle.csv cell bit for bit); decks load
with overrides and report their problems; result folders read back; sweeps run and resume.
Needs PISTONDYN_EXE and PISTONDYN_SOURCE_DIR (set by CTest) and the module on PYTHONPATH."""

import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import pistondyn

SOURCE = os.environ["PISTONDYN_SOURCE_DIR"]
EXE = os.environ["PISTONDYN_EXE"]
GASOLINE = os.path.join(SOURCE, "examples/engines/gasoline_1400_2000rpm/engine.yaml")
BRIGGS = os.path.join(SOURCE, "examples/engines/briggs_stratton_500/engine.yaml")

# The gasoline deck's skirt, coarse and quick (README.md, "Benchmarks"): about 0.2 s a run.
FAST_SKIRT = {
    "simulation.cycles": 1, "simulation.until_periodic": False,
    "liner.grid.nodes_circumferential": 16, "liner.grid.nodes_axial": 12,
    "simulation.stepper_order": 3, "simulation.max_step_deg": 1,
    "simulation.pose_tolerance_nm": 10,
    "liner.film.fallback_to_reference": False, "simulation.jacobian_reuse_steps": 20,
    "liner.film.cavitation": "reynolds", "liner.oil_supply.film_um": None,
    "liner.oil_supply.fully_flooded": True, "simulation.output_step_deg": 2,
    "geometry.pin_offset_mm": 0.3,
}
IDEAL = {"liner.model": "ideal_guide", "simulation.integrator": "rk_merson",
         "simulation.until_periodic": False, "simulation.cycles": 1,
         "simulation.output_step_deg": 10}


def program_run(deck, overrides, out):
    args = [EXE, "run", deck, "--out", str(out), "--quiet", "--no-plot"]
    for o in pistondyn._overrides(overrides):
        args += ["--set", o]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return out


def read_cycle_csv(path):
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    header = lines[0].strip().split(",")
    rows = np.array([[float(x) for x in l.strip().split(",")] for l in lines[1:]])
    return header, rows


def test_a_run_through_the_module_equals_the_programs_bit_for_bit(tmp_path):
    result = pistondyn.run(GASOLINE, overrides=FAST_SKIRT)
    folder = program_run(GASOLINE, FAST_SKIRT, tmp_path / "program")
    with open(folder / "summary.json") as f:
        summary = json.load(f)
    figures = 0
    for key, value in summary["results"].items():
        if key == "wall_time_s":
            continue
        assert result.figures[key] == value, key  # exact: the same double
        figures += isinstance(value, float)
    assert figures > 20
    assert result.summary["inputs"] == summary["inputs"]
    header, rows = read_cycle_csv(folder / "cycle.csv")
    assert result.columns == header
    for j, name in enumerate(header):
        # cycle.csv writes the shortest text that reads back to the same double.
        assert np.array_equal(result.cycle[name], rows[:, j]), name


def test_cycle_arrays_are_named_with_their_units(tmp_path):
    result = pistondyn.run(BRIGGS, overrides=IDEAL)
    angle = result.cycle["crank_angle_deg"]
    assert np.array_equal(angle, np.arange(0.0, 721.0, 10.0))
    for name in ("time_s", "piston_y_m", "tilt_mrad", "side_force_N", "crank_torque_Nm"):
        assert name in result.cycle and result.cycle[name].shape == angle.shape
    # The piston at TDC and BDC: the slider-crank's positions, with the deck's rod and stroke.
    y = result.cycle["piston_y_m"]
    assert y[0] == pytest.approx(0.0477 / 2 + 0.076, abs=1e-9)
    assert y[18] == pytest.approx(0.076 - 0.0477 / 2, abs=1e-9)


def test_writing_and_reading_a_result_folder(tmp_path):
    written = pistondyn.run(BRIGGS, out=tmp_path / "r", overrides=IDEAL)
    assert (tmp_path / "r" / "cycle.csv").exists() and (tmp_path / "r" / "summary.json").exists()
    back = pistondyn.read_results(tmp_path / "r")
    assert back.columns == written.columns
    for name in written.columns:
        assert np.array_equal(back.cycle[name], written.cycle[name]), name
    assert back.figures["side_force_max_N"] == written.figures["side_force_max_N"]
    with pytest.raises(RuntimeError):
        pistondyn.read_results(tmp_path / "nothing")


def test_decks_load_with_overrides_and_report_their_problems():
    deck = pistondyn.load_deck(BRIGGS, {"drive.speed_rpm": 1500, "liner.model": "ideal_guide",
                                        "simulation.integrator": "rk_merson"})
    assert deck.inputs["geometry.bore_m"] == pytest.approx(0.0651, rel=1e-15)
    assert deck.inputs["drive.speed_rad_per_s"] == pytest.approx(1500 * math.pi / 30, rel=1e-15)
    assert deck.liner_model == "ideal_guide"
    assert "drive.speed_rpm=1500" in deck.overrides
    assert pistondyn.validate(BRIGGS) == []
    problems = pistondyn.validate(BRIGGS, ["geometry.bore_mm=0.0651", "piston.mas_g=75"])
    assert any("--set geometry.bore_mm" in p and "given in m" in p for p in problems), problems
    assert any("--set piston.mas_g" in p for p in problems), problems
    with pytest.raises(pistondyn.DeckError) as e:
        pistondyn.load_deck(BRIGGS, {"drive.speed_rpm": -5})
    assert "drive.speed_rpm" in str(e.value)
    with pytest.raises(TypeError):
        pistondyn.load_deck(BRIGGS, "drive.speed_rpm=5")


def test_sweeps_run_and_resume(tmp_path):
    sweep = tmp_path / "sweep.yaml"
    sweep.write_text("base_deck: %s\nset:\n" % BRIGGS +
                     "".join("  %s: %s\n" % (k, pistondyn._value_text(v)) for k, v in IDEAL.items()) +
                     "cartesian:\n  geometry.pin_offset_mm: [0.0, 0.5]\n")
    first = pistondyn.run_sweep(sweep, tmp_path / "out", jobs=2)
    assert (first["cases"], first["ran"], first["failed"]) == (2, 2, 0)
    for folder in first["case_folders"]:
        r = pistondyn.read_results(tmp_path / "out" / folder)
        assert len(r.cycle["crank_angle_deg"]) == 73
    again = pistondyn.run_sweep(sweep, tmp_path / "out")
    assert (again["earlier"], again["ran"]) == (2, 0)
    other = tmp_path / "other.yaml"
    other.write_text(sweep.read_text().replace("[0.0, 0.5]", "[0.0, 0.6]"))
    with pytest.raises(pistondyn.OutputError):
        pistondyn.run_sweep(other, tmp_path / "out")


def test_the_scipy_example_runs(tmp_path):
    """The notebook-style example runs (its scipy part only where scipy is installed)."""
    example = os.path.join(os.path.dirname(__file__), "..", "examples", "optimize_pin_offset.py")
    done = subprocess.run([sys.executable, example, "--evaluations", "6"], cwd=tmp_path,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "fmep" in done.stdout
