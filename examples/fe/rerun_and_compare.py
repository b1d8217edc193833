#!/usr/bin/env python3
"""Reruns make_compliance.py for committed compliance files and checks the new result matches.

  rerun_and_compare.py DIR/NAME_fe_run.json [...]

For each run record (written by make_compliance.py beside its .mtx), reruns the recorded command
(from examples/fe, with --out pointing to a scratch folder) and compares:
  - the node tables: node, angle and height identical as text after the comment lines, the
    gas column (skirts) within 1e-6 of its largest value;
  - the compliance: max |C_new - C_committed| <= 1e-6 * max diagonal (the files carry 8
    significant digits; gmsh's structured mesh and ccx's direct solver are deterministic, so
    anything larger means the script, the tools or the committed files changed).
Exit 0 when all match, 1 otherwise (the differences printed). Used by the CTest test
fe_compliance_rerun (label slow, configure with -DPISTONDYN_FE_RERUN_TEST=ON).
"""

import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def read_mtx(path):
    with open(path) as f:
        lines = [l for l in f if not l.startswith("%") and l.strip()]
    n, m = (int(x) for x in lines[0].split()[:2])
    values = [float(x) for x in lines[1:]]
    if len(values) != n * m:
        raise RuntimeError(f"{path}: {len(values)} values, expected {n * m}")
    return n, values  # column-major


def data_lines(path):
    with open(path) as f:
        return [l for l in f if not l.startswith("#")]


def compare_node_tables(new_path, old_path):
    """(node, phi_deg and y_mm identical as text, largest difference of the other columns
    relative to their largest |value|). The other column is the skirt's gas field: numbers
    like the matrix's (the B&S skirt's were rescaled from 72 to 75 GPa and rounded again), so
    compared as numbers; the grid columns must match exactly."""
    new, old = data_lines(new_path), data_lines(old_path)
    if len(new) != len(old) or not new or new[0] != old[0]:
        return False, 0.0
    same, worst, scale = True, 0.0, 0.0
    for a, b in zip(new[1:], old[1:]):
        fa, fb = a.strip().split(","), b.strip().split(",")
        if len(fa) != len(fb) or fa[:3] != fb[:3]:
            same = False
            continue
        for x, y in zip(fa[3:], fb[3:]):
            worst = max(worst, abs(float(x) - float(y)))
            scale = max(scale, abs(float(y)))
    return same, (worst / scale if scale > 0.0 else worst)


def check(record_path):
    with open(record_path) as f:
        record = json.load(f)
    name, command = record["name"], list(record["command"])
    committed = os.path.dirname(os.path.abspath(record_path))
    with tempfile.TemporaryDirectory(prefix="pistondyn_fe_rerun_") as out:
        i = command.index("--out")
        command[i + 1] = out
        print(f"rerun_and_compare: {name}: make_compliance.py {' '.join(command)}", flush=True)
        subprocess.run([sys.executable, os.path.join(HERE, "make_compliance.py")] + command,
                       cwd=HERE, check=True)
        n_new, c_new = read_mtx(os.path.join(out, f"{name}_compliance.mtx"))
        n_old, c_old = read_mtx(os.path.join(committed, f"{name}_compliance.mtx"))
        if n_new != n_old:
            print(f"  FAIL: {n_new} nodes now, {n_old} committed")
            return False
        scale = max(c_old[k * n_old + k] for k in range(n_old))
        worst = max(abs(a - b) for a, b in zip(c_new, c_old)) / scale
        same_nodes, gas_worst = compare_node_tables(
            os.path.join(out, f"{name}_nodes.csv"), os.path.join(committed, f"{name}_nodes.csv"))
        ok = worst <= 1e-6 and same_nodes and gas_worst <= 1e-6
        gas = "" if gas_worst == 0.0 else f", gas column max difference {gas_worst:.2e} of its largest value (limit 1e-6)"
        print(f"  {'ok' if ok else 'FAIL'}: max |dC| = {worst:.2e} of the largest diagonal "
              f"(limit 1e-6); nodes, angles and heights {'identical' if same_nodes else 'DIFFERENT'}"
              f"{gas}")
        return ok


def main(argv):
    if not argv:
        print(__doc__, file=sys.stderr)
        return 2
    results = [check(p) for p in argv]
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
