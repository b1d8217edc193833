"""pistondyn: piston-assembly dynamics and tribology over whole engine cycles.

The Python face of the C++ library (pistondyn::io): load a deck with overrides, check it,
run it, read its summary (a dict) and cycle results (numpy arrays named with their units),
run sweeps. Crank angle 0 deg = firing TDC; SI inside, the unit in every name.

    import pistondyn
    deck = pistondyn.load_deck("engine.yaml", {"drive.speed_rpm": 3000})
    result = pistondyn.run(deck)                      # or run(deck, out="results/3000rpm")
    result.summary["results"]["fmep_kPa"]             # summary.json as a dict
    result.cycle["tilt_mrad"]                         # a column of cycle.csv, numpy array

A run through the module is the run of `pistondyn run`: the same code, the same numbers.
"""

import json
import numbers

import numpy as np

from ._pistondyn import Deck, DeckError, OutputError, __version__
from . import _pistondyn

__all__ = ["Deck", "DeckError", "OutputError", "Result", "load_deck", "validate", "run",
           "read_results", "run_sweep", "__version__"]


def _value_text(value):
    """A value as --set takes it: numbers in the shortest text that reads back to the same
    double (Python's repr), booleans as true/false, None as null."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    return str(value)


def _overrides(overrides):
    """--set assignments from a dict {key: value}, a list of "key=value", or None."""
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        return ["%s=%s" % (k, _value_text(v)) for k, v in overrides.items()]
    if isinstance(overrides, str):
        raise TypeError("overrides: a dict {key: value} or a list of 'key=value', not a string")
    return [str(o) for o in overrides]


class Result:
    """A run's results: `summary` (summary.json as a dict), `cycle` (every cycle.csv column
    as a numpy array, by its name with the unit), `columns` (their order), `folder` (where
    the files are, or None)."""

    def __init__(self, raw):
        self.summary_json = raw["summary_json"]
        self.summary = json.loads(self.summary_json)
        self.columns = list(raw["columns"])
        rows = np.asarray(raw["rows"], dtype=np.float64)
        self.cycle = {name: rows[:, j].copy() for j, name in enumerate(self.columns)}
        self.folder = raw["folder"] or None

    @property
    def figures(self):
        """summary.json's results (the figures of the last cycle)."""
        return self.summary["results"]

    def __repr__(self):
        return "<pistondyn.Result %d rows x %d columns%s>" % (
            len(next(iter(self.cycle.values()), [])), len(self.columns),
            (" in " + self.folder) if self.folder else "")


def load_deck(path, overrides=None):
    """Reads and checks an engine deck with overrides ({key: value} in the key's unit, or
    ["key=value", ...]). Raises DeckError listing every problem."""
    return _pistondyn._load_deck(str(path), _overrides(overrides))


def validate(path, overrides=None):
    """The deck's problems as a list of lines (file:line: key: what is wrong); empty when
    the deck is valid. Nothing is simulated."""
    try:
        load_deck(path, overrides)
    except DeckError as e:
        return [line for line in str(e).splitlines() if line]
    return []


def run(deck, out=None, overrides=None):
    """Runs a deck (a Deck, or a path loaded with `overrides`) as `pistondyn run` does; with
    `out` also writes cycle.csv and summary.json there (all-or-nothing). Returns a Result."""
    if not isinstance(deck, Deck):
        deck = load_deck(deck, overrides)
    elif overrides:
        raise ValueError("overrides go to load_deck (this deck is loaded already)")
    return Result(_pistondyn._run(deck, "" if out is None else str(out)))


def read_results(folder):
    """A result folder written by `pistondyn run` (or run(..., out=...)) as a Result."""
    return Result(_pistondyn._read_results(str(folder)))


def run_sweep(sweep_deck, out, jobs=None, overrides=None):
    """Runs a sweep deck into `out` (threads, resume), as `pistondyn sweep`. Returns a dict:
    cases, earlier (complete from an earlier run), ran, failed, case_folders."""
    return _pistondyn._run_sweep(str(sweep_deck), str(out), int(jobs or 0),
                                 _overrides(overrides))
