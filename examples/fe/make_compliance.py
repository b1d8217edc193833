#!/usr/bin/env python3
"""Radial compliance of a piston skirt or a liner band from a gmsh + CalculiX model.

  make_compliance.py skirt  --deck ENGINE.yaml --out DIR [options]   piston skirt (examples/fe/README.md)
  make_compliance.py liner  --deck ENGINE.yaml --out DIR [options]   liner band (plain cylinder)
  make_compliance.py cylinder --radius-mm R --wall-mm T ... --out DIR  plain cylinder (verification)

Writes DIR/<name>_compliance.mtx (Matrix Market, array real general, m/N), DIR/<name>_nodes.csv
(node,phi_deg,y_mm[,gas_u_r_um_per_MPa]) and DIR/<name>_fe_run.json (model, mesh, run times);
with --diagonal-at-phi-deg only DIR/<name>_diagonal.csv (mesh-refinement study). Elastic data
from the deck's liner.asperity.* keys unless given (README.md, "Material data").

Python 3 standard library only; needs the command-line programs gmsh (>= 4.8) and ccx (CalculiX
>= 2.17) on PATH. Units inside the FE model: mm, N, MPa.

Definition of the compliance (examples/fe/README.md, "What the numbers are"). Structural node J
of the tensor grid (phi_i, y_j) on the loaded surface carries the bilinear hat N_J. Load case J is
the radial pressure p_J = N_J / A_J (A_J = integral of N_J dA, so the total force is 1 N),
applied as the FE-consistent nodal loads of the mesh; the radial displacement read at node I is
the hat-weighted mean u_I = integral(u_r N_I dA) / A_I, taken with the same FE weights. So
C_IJ = w_I^T K^-1 w_J / (A_I A_J): symmetric (Maxwell-Betti) and positive definite by
construction, finite under mesh refinement (a point force on a solid is not), and the
work-conjugate of the nodal forces of pistondyn::mapping::ForceMap (consistent load, the same
hats).
"""

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

TWO_PI = 2.0 * math.pi


class InputError(Exception):
    """Bad command line or deck: reported as 'make_compliance: <message>', exit 1."""


# ---------------------------------------------------------------------------------------------
# Deck: the two-level "section: / key: value" subset of YAML the engine decks use.


def read_deck(path):
    """{dotted key: (text, line)} of the nested "key: value" mappings the engine decks use
    (block mappings only; list items and flow collections are not needed here)."""
    values = {}
    stack = []  # [(indent, key)] of the open sections
    with open(path, encoding="utf-8") as f:
        for lineno, raw in enumerate(f, 1):
            line = re.sub(r"(^|\s)#.*$", "", raw.rstrip("\n")).rstrip()
            if not line.strip():
                continue
            indent = len(line) - len(line.lstrip())
            key, sep, value = line.strip().partition(":")
            if not sep:
                raise InputError(f"{path}:{lineno}: expected 'key: value', found '{line.strip()}'")
            while stack and stack[-1][0] >= indent:
                stack.pop()
            dotted = ".".join([k for _, k in stack] + [key])
            if value.strip():
                values[dotted] = (value.strip(), lineno)
            else:
                stack.append((indent, key))
    return values


def deck_number(deck, path, key, default=None):
    if key not in deck:
        if default is not None:
            return default
        raise InputError(f"{path}: the deck has no key {key} (needed for the FE model)")
    text, lineno = deck[key]
    try:
        return float(text)
    except ValueError:
        raise InputError(f"{path}:{lineno}: {key} = '{text}' is not a number")


# ---------------------------------------------------------------------------------------------
# Model description.


class Grid:
    """Structural tensor grid on the loaded surface: nPhi angles phi_i = 2 pi i / nPhi (full circle,
    from +x towards +z) times nY heights y_j (uniform from y0 to y1) [mm]; node k = i + nPhi j."""

    def __init__(self, n_phi, n_y, y0, y1):
        if n_phi < 8 or n_phi % 4:
            raise InputError(f"--n-phi {n_phi}: must be a multiple of 4, at least 8")
        if n_y < 3:
            raise InputError(f"--n-y {n_y}: at least 3 rows needed")
        self.n_phi, self.n_y, self.y0, self.y1 = n_phi, n_y, y0, y1
        self.dphi = TWO_PI / n_phi
        self.dy = (y1 - y0) / (n_y - 1)
        # Fine row heights of the FE mesh on the loaded surface when the mesher split cells
        # (mesh_piston: the pin support's edges); None = the rows nested uniformly.
        self.fine_y = None

    def phi(self, i):
        return self.dphi * i

    def y(self, j):
        return self.y0 + self.dy * j

    def count(self):
        return self.n_phi * self.n_y


def partition(breaks, spacing, what):
    """Layer counts for the intervals between sorted breaks, about `spacing` each (>= 1)."""
    counts = []
    for a, b in zip(breaks[:-1], breaks[1:]):
        if not b > a:
            raise InputError(f"{what}: interval [{a}, {b}] mm is empty; check the dimensions")
        counts.append(max(1, int(round((b - a) / spacing))))
    return counts


# ---------------------------------------------------------------------------------------------
# gmsh: a structured hexahedral mesh of a tensor partition of the meridian half-plane (r, y),
# revolved about the cylinder axis in four quarter turns.


def write_geo(path, r_breaks, r_counts, y_breaks, y_counts, phi_layers_per_quarter):
    lines = [
        "// generated by examples/fe/make_compliance.py - do not edit",
        "Geometry.AutoCoherence = 1;",
        "Mesh.MshFileVersion = 2.2;",
        "Mesh.RecombineAll = 1;",
    ]
    na, nb = len(r_breaks), len(y_breaks)
    pid = lambda a, b: 1 + a + na * b
    for b, y in enumerate(y_breaks):
        for a, r in enumerate(r_breaks):
            lines.append(f"Point({pid(a, b)}) = {{{r!r}, {y!r}, 0, 1}};")
    # horizontal lines (along r) and vertical lines (along y)
    h = lambda a, b: 1 + a + (na - 1) * b
    v = lambda a, b: 1 + (na - 1) * nb + a + na * b
    for b in range(nb):
        for a in range(na - 1):
            lines.append(f"Line({h(a, b)}) = {{{pid(a, b)}, {pid(a + 1, b)}}};")
            lines.append(f"Transfinite Curve{{{h(a, b)}}} = {r_counts[a] + 1};")
    for b in range(nb - 1):
        for a in range(na):
            lines.append(f"Line({v(a, b)}) = {{{pid(a, b)}, {pid(a, b + 1)}}};")
            lines.append(f"Transfinite Curve{{{v(a, b)}}} = {y_counts[b] + 1};")
    surfaces = []
    for b in range(nb - 1):
        for a in range(na - 1):
            s = 1 + a + (na - 1) * b
            lines.append(
                f"Curve Loop({s}) = {{{h(a, b)}, {v(a + 1, b)}, {-h(a, b + 1)}, {-v(a, b)}}};")
            lines.append(f"Plane Surface({s}) = {{{s}}};")
            lines.append(f"Transfinite Surface{{{s}}};")
            lines.append(f"Recombine Surface{{{s}}};")
            surfaces.append(s)
    lines.append(f"S[] = {{{', '.join(map(str, surfaces))}}};")
    lines.append("V[] = {};")
    # Each quadrilateral surface yields [top, volume, 4 lateral surfaces] in the Extrude output.
    for q in range(4):
        lines.append(f"out[] = Extrude {{{{0, -1, 0}}, {{0, 0, 0}}, Pi / 2}} "
                     f"{{ Surface{{S[]}}; Layers{{{phi_layers_per_quarter}}}; Recombine; }};")
        lines.append("For k In {0 : #S[] - 1}")
        lines.append("  S[k] = out[6 * k];")
        lines.append("  V[] += out[6 * k + 1];")
        lines.append("EndFor")
    lines.append("Coherence;")
    lines.append("Physical Volume(1) = {V[]};")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def read_msh22(path):
    """Nodes {tag: (x, y, z)} and 8-node hexahedra [(n1..n8)] of a gmsh 2.2 ASCII file."""
    nodes, hexes = {}, []
    with open(path) as f:
        section = None
        for line in f:
            t = line.strip()
            if t.startswith("$"):
                section = t[1:] if not t.startswith("$End") else None
                count_pending = True
                continue
            if section == "Nodes":
                if count_pending:
                    count_pending = False
                    continue
                p = t.split()
                nodes[int(p[0])] = (float(p[1]), float(p[2]), float(p[3]))
            elif section == "Elements":
                if count_pending:
                    count_pending = False
                    continue
                p = t.split()
                etype, ntags = int(p[1]), int(p[2])
                if etype == 5:
                    hexes.append(tuple(int(x) for x in p[3 + ntags:3 + ntags + 8]))
                elif etype != 15:
                    raise RuntimeError(f"{path}: unexpected element type {etype} (only hexahedra)")
    return nodes, hexes


def run(cmd, cwd, log_path, what):
    t0 = time.monotonic()
    with open(log_path, "w") as log:
        rc = subprocess.call(cmd, cwd=cwd, stdout=log, stderr=subprocess.STDOUT)
    elapsed = time.monotonic() - t0
    if rc != 0:
        tail = open(log_path).read()[-2000:]
        raise RuntimeError(f"{what} failed (exit {rc}); end of {log_path}:\n{tail}")
    return elapsed


class Mesh:
    """The merged, oriented hexahedral mesh of the material regions, nodes renumbered 1..n."""

    def __init__(self, nodes, hexes, keep_element):
        # Merge coincident nodes (the seam of the revolution; gmsh usually merges them itself).
        key = lambda p: (round(p[0] * 1e6), round(p[1] * 1e6), round(p[2] * 1e6))
        canonical, by_key = {}, {}
        for tag in sorted(nodes):
            k = key(nodes[tag])
            canonical[tag] = by_key.setdefault(k, tag)
        elements = []
        for e in hexes:
            conn = [canonical[n] for n in e]
            if len(set(conn)) != 8:
                raise RuntimeError("degenerate hexahedron in the mesh")
            pts = [nodes[n] for n in conn]
            c = [sum(p[d] for p in pts) / 8.0 for d in range(3)]
            if not keep_element(c):
                continue
            if hex_volume_sign(pts) < 0:  # gmsh's revolution may order the faces inside out
                conn = conn[4:] + conn[:4]
            elements.append(conn)
        used = sorted({n for e in elements for n in e})
        self.number = {tag: i + 1 for i, tag in enumerate(used)}
        self.xyz = [nodes[tag] for tag in used]  # index = number - 1
        self.elements = [[self.number[n] for n in e] for e in elements]

    def node_count(self):
        return len(self.xyz)


def hex_volume_sign(p):
    # Sign of the Jacobian at the centre: (e1 x e2) . e3 with the mean edge vectors.
    def sub(a, b):
        return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]

    e1 = [sum(x) / 4 for x in zip(sub(p[1], p[0]), sub(p[2], p[3]), sub(p[5], p[4]), sub(p[6], p[7]))]
    e2 = [sum(x) / 4 for x in zip(sub(p[3], p[0]), sub(p[2], p[1]), sub(p[7], p[4]), sub(p[6], p[5]))]
    e3 = [sum(x) / 4 for x in zip(sub(p[4], p[0]), sub(p[5], p[1]), sub(p[6], p[2]), sub(p[7], p[3]))]
    cx = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
    return cx[0] * e3[0] + cx[1] * e3[1] + cx[2] * e3[2]


def cyl(p):
    """(r, phi in [0, 2 pi), y) of a point (x, y, z); phi from +x towards +z."""
    r = math.hypot(p[0], p[2])
    phi = math.atan2(p[2], p[0])
    if phi < 0:
        phi += TWO_PI
    return r, phi, p[1]


# ---------------------------------------------------------------------------------------------
# Loads and read-outs on the loaded surface: the FE-consistent weights of the structural hats.


def hat_weights_periodic(n_coarse, m, h_fine):
    """w[c] = {fine node g: integral phi_g N_c ds} for the hats N_c of a coarse uniform periodic
    grid (the full circle) and the hats phi_g of the fine grid nested m times in it (spacing
    h_fine): the 1-D linear FE mass matrix applied to the nodal values of N_c - exact, both being
    piecewise linear on the fine grid. Returns (weights, fine node count)."""
    n_fine = n_coarse * m
    weights = []
    for c in range(n_coarse):
        w = {}
        for d in range(-m + 1, m):  # nodes where N_c > 0
            f = (c * m + d) % n_fine
            value = 1.0 - abs(d) / m
            for g in (f - 1, f + 1):  # each element (f, g) adds h/3 and h/6
                g %= n_fine
                w[f] = w.get(f, 0.0) + value * h_fine / 3.0
                w[g] = w.get(g, 0.0) + value * h_fine / 6.0
        weights.append(w)
    return weights, n_fine


def hat_weights_nested(coarse, fine):
    """As hat_weights_periodic for an open coarse grid and a fine grid that need not be uniform: the
    fine node positions `fine` (sorted, containing every coarse node) refine the coarse cells; the
    coarse hat N_c is piecewise linear on the fine grid, so the 1-D mass matrix applied to its
    nodal values is exact. Returns the weights [{fine index: integral phi_g N_c ds}]."""
    index = {}
    for c, yc in enumerate(coarse):
        hits = [f for f, yf in enumerate(fine) if abs(yf - yc) <= 1e-9 * (1.0 + abs(yc))]
        if len(hits) != 1:
            raise RuntimeError(f"coarse node {yc} is not a node of the fine grid")
        index[c] = hits[0]

    def hat(c, f):  # N_c at fine node f
        y = fine[f]
        if c > 0 and coarse[c - 1] < y < coarse[c]:
            return (y - coarse[c - 1]) / (coarse[c] - coarse[c - 1])
        if c + 1 < len(coarse) and coarse[c] <= y < coarse[c + 1]:
            return (coarse[c + 1] - y) / (coarse[c + 1] - coarse[c])
        return 1.0 if f == index[c] else 0.0

    weights = []
    for c in range(len(coarse)):
        w = {}
        lo = index[c - 1] if c > 0 else index[c]
        hi = index[c + 1] if c + 1 < len(coarse) else index[c]
        for f in range(lo, hi + 1):
            value = hat(c, f)
            if value == 0.0:
                continue
            for g in (f - 1, f + 1):  # each element (f, g) adds h/3 at f and h/6 at g
                if 0 <= g < len(fine):
                    h = abs(fine[g] - fine[f])
                    w[f] = w.get(f, 0.0) + value * h / 3.0
                    w[g] = w.get(g, 0.0) + value * h / 6.0
        weights.append(w)
    return weights


def subdivide(breaks, counts):
    """Node positions of intervals [breaks[i], breaks[i+1]] each split uniformly in counts[i]."""
    out = [breaks[0]]
    for a, b, n in zip(breaks[:-1], breaks[1:], counts):
        out += [a + (b - a) * (q + 1) / n for q in range(n)]
        out[-1] = b
    return out


class LoadedSurface:
    """FE nodes of the loaded surface on the structural grid (nested m times) and the weights
    W_J(f) = integral phi_f N_J dA, dA = R dphi dy [mm^2]."""

    def __init__(self, mesh, grid, radius, m):
        self.grid, self.radius, self.m = grid, radius, m
        wphi, self.n_fphi = hat_weights_periodic(grid.n_phi, m, grid.dphi / m)
        # y: the mesher's fine rows (grid.fine_y, not uniform where a support edge splits a
        # cell), else the structural rows nested m times
        fine_y = grid.fine_y or subdivide(
            [grid.y(j) for j in range(grid.n_y)], [m] * (grid.n_y - 1))
        wy = hat_weights_nested([grid.y(j) for j in range(grid.n_y)], fine_y)
        self.n_fy = len(fine_y)
        # FE node number of each fine surface point (a, b)
        self.fe_node = {}
        tol = 1e-6 * max(radius, 1.0)
        for idx, p in enumerate(mesh.xyz):
            r, phi, y = cyl(p)
            if abs(r - radius) > tol or y < grid.y0 - tol or y > grid.y1 + tol:
                continue
            a = phi / (grid.dphi / m)
            ib = min(range(self.n_fy), key=lambda f: abs(fine_y[f] - y))
            ia = int(round(a)) % self.n_fphi
            if abs(a - round(a)) > 1e-6 or abs(fine_y[ib] - y) > 1e-6 * grid.dy:
                raise RuntimeError(f"surface node at phi {math.degrees(phi)} deg, y {y} mm is off "
                                   "the nested structural grid")
            self.fe_node[(ia, ib)] = idx + 1
        expected = self.n_fphi * self.n_fy
        if len(self.fe_node) != expected:
            raise RuntimeError(f"found {len(self.fe_node)} FE nodes on the loaded surface, "
                               f"expected {expected}")
        self.weights = []  # per structural node k: [(fe node, weight mm^2, phi of that node)]
        self.area = []
        for j in range(grid.n_y):
            for i in range(grid.n_phi):
                w = []
                for a, wa in wphi[i].items():
                    for b, wb in wy[j].items():
                        w.append((self.fe_node[(a, b)], radius * wa * wb, a * grid.dphi / m))
                self.weights.append(w)
                self.area.append(sum(x[1] for x in w))

    def nodes(self):
        return sorted(self.fe_node.values())


# ---------------------------------------------------------------------------------------------
# CalculiX input and output.


def num(v):
    """A number in at most 20 characters, 14 significant digits (ccx's field width)."""
    return f"{v:.13e}"


def write_ccx(path, mesh, material, fixed, load_cases, out_nodes):
    """fixed: [(node, first dof, last dof)]; load_cases: [[(node, dof, value N)]]."""
    E, nu = material
    L = ["** generated by examples/fe/make_compliance.py - do not edit",
         "** units: mm, N, MPa", "*NODE, NSET=NALL"]
    # ccx reads at most 20 characters per number
    L += [f"{i + 1}, {num(p[0])}, {num(p[1])}, {num(p[2])}" for i, p in enumerate(mesh.xyz)]
    L.append("*ELEMENT, TYPE=C3D8I, ELSET=EALL")
    L += [f"{k + 1}, " + ", ".join(map(str, e)) for k, e in enumerate(mesh.elements)]
    L.append("*NSET, NSET=NOUT")
    L += [str(n) for n in out_nodes]
    L += ["*MATERIAL, NAME=M", "*ELASTIC", f"{E!r}, {nu!r}",
          "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "*BOUNDARY"]
    L += [f"{n}, {a}, {b}" for n, a, b in fixed]
    for case in load_cases:
        L += ["*STEP", "*STATIC", "*CLOAD, OP=NEW"]
        L += [f"{n}, {d}, {num(v)}" for n, d, v in case]
        L += ["*NODE PRINT, NSET=NOUT", "U", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(L) + "\n")


def read_ccx_displacements(path, n_cases):
    """[{node: (ux, uy, uz)}] per step of a .dat file with one NODE PRINT U per step."""
    cases, current = [], None
    with open(path) as f:
        for line in f:
            if line.lstrip().startswith("displacements"):
                current = {}
                cases.append(current)
                continue
            p = line.split()
            if current is not None and len(p) == 4:
                try:
                    current[int(p[0])] = (float(p[1]), float(p[2]), float(p[3]))
                except ValueError:
                    current = None
    if len(cases) != n_cases:
        raise RuntimeError(f"{path}: {len(cases)} displacement blocks, expected {n_cases}")
    return cases


# ---------------------------------------------------------------------------------------------
# Writers.


def write_mtx(path, matrix, header_lines):
    n = len(matrix)
    with open(path, "w") as f:
        f.write("%%MatrixMarket matrix array real general\n")
        for h in header_lines:
            f.write(f"% {h}\n")
        f.write(f"{n} {n}\n")
        for j in range(n):  # column-major, as the format prescribes
            for i in range(n):
                f.write(f"{matrix[i][j]:.7e}\n")


def write_nodes(path, grid, header_lines, gas=None, y_offset=0.0):
    with open(path, "w") as f:
        for h in header_lines:
            f.write(f"# {h}\n")
        f.write("node,phi_deg,y_mm" + (",gas_u_r_um_per_MPa" if gas is not None else "") + "\n")
        for j in range(grid.n_y):
            for i in range(grid.n_phi):
                k = i + grid.n_phi * j
                row = f"{k + 1},{360.0 * i / grid.n_phi!r},{grid.y(j) + y_offset:.9g}"
                if gas is not None:
                    row += f",{gas[k]:.7e}"
                f.write(row + "\n")


# ---------------------------------------------------------------------------------------------
# The models.


def radial_loads(surface, k, scale):
    """CLOAD lines of load case k: the radial pressure N_k / A_k (1 N in total) times scale."""
    out = []
    for node, w, phi in surface.weights[k]:
        f = scale * w / surface.area[k]
        out.append((node, 1, f * math.cos(phi)))
        out.append((node, 3, f * math.sin(phi)))
    return out


def read_out(surface, disp, k):
    """Hat-weighted radial displacement at structural node k [mm]."""
    s = 0.0
    for node, w, phi in surface.weights[k]:
        u = disp[node]
        s += w * (u[0] * math.cos(phi) + u[2] * math.sin(phi))
    return s / surface.area[k]


def mirror_index(grid, k, mirror_x, mirror_z):
    i, j = k % grid.n_phi, k // grid.n_phi
    if mirror_z:  # z -> -z: phi -> -phi
        i = (-i) % grid.n_phi
    if mirror_x:  # x -> -x: phi -> pi - phi
        i = (grid.n_phi // 2 - i) % grid.n_phi
    return i + grid.n_phi * j


def solve_cases(work, mesh, material, fixed, surface, cases, extra_case, keep):
    """Runs ccx on the load cases (structural node indices; extra_case: [(node,dof,value)] or
    None) and returns (columns {k: [u_I]}, extra column or None, ccx seconds)."""
    load_cases = [radial_loads(surface, k, 1.0) for k in cases]
    if extra_case is not None:
        load_cases.append(extra_case)
    inp = os.path.join(work, "model.inp")
    write_ccx(inp, mesh, material, fixed, load_cases, surface.nodes())
    seconds = run(["ccx", "-i", "model"], work, os.path.join(work, "ccx.log"), "ccx")
    disp = read_ccx_displacements(os.path.join(work, "model.dat"), len(load_cases))
    n = surface.grid.count()
    columns = {k: [read_out(surface, disp[c], i) for i in range(n)] for c, k in enumerate(cases)}
    extra = [read_out(surface, disp[-1], i) for i in range(n)] if extra_case is not None else None
    if not keep:
        for name in ("model.inp", "model.dat", "model.frd", "model.sta", "model.cvg",
                     "spooles.out", "model.12d"):
            try:
                os.remove(os.path.join(work, name))
            except FileNotFoundError:
                pass
    return columns, extra, seconds


def mesh_piston(args, work):
    """Skirt + pin bosses + ring belt + crown; returns (mesh, grid, model dict)."""
    R = 0.5 * args.bore_mm
    L = args.skirt_length_mm
    y_top = args.skirt_top_mm
    y_bot = y_top - L
    y_crown = args.compression_height_mm
    t_s, t_rb, t_c = args.skirt_wall_mm, args.ring_belt_wall_mm, args.crown_mm
    r0 = args.crown_hole_fraction * R
    r1, r2 = R - t_rb, R - t_s
    grid = Grid(args.n_phi, args.n_y, y_bot, y_top)
    m = args.refine
    # Boss: from boss_half_height below the pin axis up into the ring belt, snapped to a
    # structural row; half-angle snapped to a multiple of the structural angle step.
    j_b = max(0, min(grid.n_y - 1, int(round((-args.boss_half_height_mm - y_bot) / grid.dy))))
    y_b = grid.y(j_b)
    beta = max(1, int(round(math.radians(args.boss_half_angle_deg) / grid.dphi))) * grid.dphi
    y_c1 = y_crown - t_c
    if not (r0 < r1 < r2 < R and y_top < y_c1 < y_crown):
        raise InputError("the piston dimensions do not nest: need crown hole < ring belt inner "
                         "radius < skirt inner radius < bore/2 and skirt top < crown underside")
    h_arc = R * grid.dphi / m
    r_breaks = [r0, r1, r2, R]
    r_counts = [max(2, int(round((r1 - r0) / (1.5 * h_arc)))),
                max(1, int(round((t_rb - t_s) / (t_s / m)))), m]
    # The pin's support: the boss over the pin's diameter in height, its edges y = -+a on mesh
    # lines at every refinement (a support made of the nodes inside the pin circle is a
    # staircase that moves with the mesh and does not converge). An edge within 0.1 of a row
    # spacing of a structural row is moved onto it (no sliver elements); otherwise it splits its
    # cell - a rule of the structural grid, not of the mesh, so the model is the same at every
    # refinement.
    a = args.pin_radius_mm
    edges = []
    for e in (-a, a):
        j = int(round((e - y_bot) / grid.dy))
        edges.append(grid.y(j) if 0 <= j < grid.n_y and abs(grid.y(j) - e) <= 0.1 * grid.dy else e)
    edges[0] = max(edges[0], y_b)  # bosses ending above the pin's bottom: support from there
    if not (y_b < edges[1] < y_top):
        raise InputError(f"the pin's top (radius {a:g} mm) is not between the boss's bottom "
                         f"({y_b:g} mm) and the skirt top ({y_top:g} mm): check "
                         "--pin-diameter-mm and --boss-half-height-mm")
    # y: every structural row and the support edges are breaks; m layers per structural cell,
    # a split cell shares its m in proportion (at least one layer each side).
    y_breaks, y_counts = [y_bot], []
    for j in range(grid.n_y - 1):
        lo, hi = grid.y(j), grid.y(j + 1)
        inner = [e for e in edges if lo + 1e-9 < e < hi - 1e-9]
        for u, v in zip([lo] + inner, inner + [hi]):
            y_breaks.append(v)
            y_counts.append(m if not inner else max(1, int(round(m * (v - u) / grid.dy))))
    grid.fine_y = subdivide(y_breaks, y_counts)
    y_breaks += [y_c1, y_crown]
    y_counts += partition([y_top, y_c1], 1.5 * grid.dy / m, "ring belt")
    y_counts += [max(2, m)]
    geo = os.path.join(work, "model.geo")
    write_geo(geo, r_breaks, r_counts, y_breaks, y_counts, grid.n_phi // 4 * m)
    t_gmsh = run(["gmsh", "-3", "model.geo", "-o", "model.msh", "-format", "msh22"],
                 work, os.path.join(work, "gmsh.log"), "gmsh")
    nodes, hexes = read_msh22(os.path.join(work, "model.msh"))
    tol = 1e-6 * R

    def near_pin_axis(phi):
        return abs(math.sin(phi)) >= math.cos(beta) - 1e-12

    def keep(c):
        r, phi, y = cyl(c)
        if y < y_top:
            if r > r2:
                return True  # skirt wall
            return r > r1 and y > y_b and near_pin_axis(phi)  # pin boss
        if r > r1:
            return True  # ring belt
        return y > y_c1  # crown

    mesh = Mesh(nodes, hexes, keep)
    fixed = []
    for idx, p in enumerate(mesh.xyz):
        r, phi, y = cyl(p)
        if r < r2 + tol and near_pin_axis(phi) and edges[0] - tol <= y <= edges[1] + tol:
            fixed.append((idx + 1, 1, 3))
    for side in (+1, -1):
        if not any(mesh.xyz[n - 1][2] * side > 0 for n, _, _ in fixed):
            raise InputError("the pin (radius %g mm) meets no boss node on one side; check "
                             "--pin-diameter-mm and the boss size" % args.pin_radius_mm)
    model = {
        "kind": "piston skirt: skirt shell, two pin bosses, ring belt, annular crown; "
                "bonded rigid pin over the boss's width and the pin's diameter",
        "bore_mm": args.bore_mm, "skirt_top_above_pin_mm": y_top, "skirt_length_mm": L,
        "compression_height_mm": y_crown, "skirt_wall_mm": t_s, "ring_belt_wall_mm": t_rb,
        "crown_thickness_mm": t_c, "crown_hole_radius_mm": r0,
        "pin_diameter_mm": 2 * args.pin_radius_mm,
        "boss_bottom_above_pin_mm": y_b, "boss_half_angle_deg": math.degrees(beta),
        "pin_support_y_mm": edges,
        "young_modulus_MPa": args.young_MPa, "poisson_ratio": args.poisson,
        "loaded_surface": "outer, radius bore/2",
    }
    info = {"gmsh_s": t_gmsh, "r_layers": r_counts, "y_layers": y_counts,
            "phi_layers": grid.n_phi * m, "fixed_nodes": len(fixed)}
    return mesh, grid, fixed, model, info, (R, r0, y_crown)


def crown_pressure_case(mesh, R, y_crown, pressure):
    """Nodal forces (-y) of a uniform pressure on the crown top: the consistent loads of the top
    faces (2 x 2 Gauss), scaled so that their total is the force on the full bore area,
    pressure * pi R^2 (the crown's central hole and the polygonal faces carry the rest)."""
    forces = {}
    tol = 1e-6 * R
    g = 1.0 / math.sqrt(3.0)
    for e in mesh.elements:
        for face in ((0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6),
                     (3, 0, 4, 7)):
            nodes = [e[q] for q in face]
            pts = [mesh.xyz[n - 1] for n in nodes]
            if any(abs(pt[1] - y_crown) > tol for pt in pts):
                continue
            for s in (-g, g):  # 2 x 2 Gauss on the planar quadrilateral in (x, z)
                for t in (-g, g):
                    N = [(1 - s) * (1 - t) / 4, (1 + s) * (1 - t) / 4, (1 + s) * (1 + t) / 4,
                         (1 - s) * (1 + t) / 4]
                    dNs = [-(1 - t) / 4, (1 - t) / 4, (1 + t) / 4, -(1 + t) / 4]
                    dNt = [-(1 - s) / 4, -(1 + s) / 4, (1 + s) / 4, (1 - s) / 4]
                    xs = sum(d * pt[0] for d, pt in zip(dNs, pts))
                    zs = sum(d * pt[2] for d, pt in zip(dNs, pts))
                    xt = sum(d * pt[0] for d, pt in zip(dNt, pts))
                    zt = sum(d * pt[2] for d, pt in zip(dNt, pts))
                    detj = abs(xs * zt - xt * zs)
                    for n, Nq in zip(nodes, N):
                        forces[n] = forces.get(n, 0.0) + Nq * detj
    if not forces:
        raise RuntimeError("no element face on the crown top")
    scale = pressure * math.pi * R * R / sum(forces.values())
    return [(n, 2, -scale * f) for n, f in sorted(forces.items())]


def mesh_cylinder(args, work):
    """Plain cylinder r in [Ri, Ri + t], y in [y_bottom, y_top_fe]; grid on the loaded surface."""
    Ri, t = args.inner_radius_mm, args.wall_mm
    Ro = Ri + t
    R = Ro if args.loaded_surface == "outer" else Ri
    grid = Grid(args.n_phi, args.n_y, args.grid_bottom_mm, args.grid_top_mm)
    m = args.refine
    yb, yt = args.bottom_mm, args.top_mm
    if not (yb <= grid.y0 < grid.y1 <= yt):
        raise InputError("the structural grid must lie within the cylinder's length")
    y_breaks = [yb] + ([grid.y0] if grid.y0 > yb else []) + [grid.y1] + ([yt] if yt > grid.y1 else [])
    spacing_far = args.far_spacing_factor * grid.dy / m
    y_counts = []
    if grid.y0 > yb:
        y_counts += partition([yb, grid.y0], spacing_far, "cylinder below the grid")
    y_counts.append((grid.n_y - 1) * m)
    if yt > grid.y1:
        y_counts += partition([grid.y1, yt], spacing_far, "cylinder above the grid")
    r_counts = [max(2, m)]
    geo = os.path.join(work, "model.geo")
    write_geo(geo, [Ri, Ro], r_counts, y_breaks, y_counts, grid.n_phi // 4 * m)
    t_gmsh = run(["gmsh", "-3", "model.geo", "-o", "model.msh", "-format", "msh22"],
                 work, os.path.join(work, "gmsh.log"), "gmsh")
    nodes, hexes = read_msh22(os.path.join(work, "model.msh"))
    mesh = Mesh(nodes, hexes, lambda c: True)
    tol = 1e-6 * Ro
    fixed = []
    for idx, p in enumerate(mesh.xyz):
        if abs(p[1] - yt) < tol:
            fixed.append((idx + 1, 1, 3))  # top end clamped (liner flange)
        elif abs(p[1] - yb) < tol:
            # bottom end: x and z held, free along the axis (seal)
            fixed += [(idx + 1, 1, 1), (idx + 1, 3, 3)]
    model = {
        "kind": "plain cylinder: top end clamped, bottom end held radially and tangentially, "
                "free axially",
        "inner_radius_mm": Ri, "wall_mm": t, "bottom_mm": yb, "top_mm": yt,
        "young_modulus_MPa": args.young_MPa, "poisson_ratio": args.poisson,
        "loaded_surface": f"{args.loaded_surface}, radius {R!r} mm",
    }
    info = {"gmsh_s": t_gmsh, "r_layers": r_counts, "y_layers": y_counts,
            "phi_layers": grid.n_phi * m, "fixed_nodes": len(fixed)}
    return mesh, grid, fixed, model, info, R


# ---------------------------------------------------------------------------------------------


def compliance(args):
    t_start = time.monotonic()
    work = os.path.abspath(args.work_dir or tempfile.mkdtemp(prefix="pistondyn_fe_"))
    os.makedirs(work, exist_ok=True)
    try:
        if args.model == "skirt":
            mesh, grid, fixed, model, info, crown = mesh_piston(args, work)
            R = 0.5 * args.bore_mm
        else:
            mesh, grid, fixed, model, info, R = mesh_cylinder(args, work)
        surface = LoadedSurface(mesh, grid, R, args.refine)
        n = grid.count()
        if args.diagonal_at_phi_deg:
            diagonal_only(args, work, mesh, grid, fixed, surface, info, t_start)
            return
        if args.ring_at_row is not None:
            ring_only(args, work, mesh, grid, fixed, surface, model, t_start)
            return
        if args.model == "skirt":
            # Symmetric about the x-y and y-z planes: load only phi in [0, pi/2], the rest by
            # reflection.
            cases = [i + grid.n_phi * j for j in range(grid.n_y) for i in range(grid.n_phi // 4 + 1)]
            extra = crown_pressure_case(mesh, crown[0], crown[2], 1.0)
        else:
            # Axisymmetric: load only phi = 0, the rest by rotation.
            cases = [grid.n_phi * j for j in range(grid.n_y)]
            extra = None
        columns, gas, t_ccx = solve_cases(work, mesh, (args.young_MPa, args.poisson), fixed,
                                          surface, cases, extra, args.keep)
        C = [[0.0] * n for _ in range(n)]  # [mm/N]
        for k in range(n):
            i, j = k % grid.n_phi, k // grid.n_phi
            if args.model == "skirt":
                for mx in (False, True):
                    for mz in (False, True):
                        src = mirror_index(grid, k, mx, mz)
                        if src in columns:
                            col = columns[src]
                            for row in range(n):
                                C[row][k] = col[mirror_index(grid, row, mx, mz)]
                            break
                    else:
                        continue
                    break
            else:
                col = columns[grid.n_phi * j]
                for row in range(n):
                    ri, rj = row % grid.n_phi, row // grid.n_phi
                    C[row][k] = col[(ri - i) % grid.n_phi + grid.n_phi * rj]
        C = [[v * 1e-3 for v in row] for row in C]  # mm/N -> m/N
        t_total = time.monotonic() - t_start
        os.makedirs(args.out, exist_ok=True)
        name = args.name
        mesh_info = dict(info, nodes=mesh.node_count(), elements=len(mesh.elements),
                         element="C3D8I", dofs=3 * mesh.node_count(),
                         refine_per_structural_cell=args.refine,
                         load_cases=len(cases) + (1 if gas is not None else 0))
        header = [
            f"pistondyn structural compliance: {name}, generated by examples/fe/make_compliance.py",
            f"command: {' '.join(sys.argv[1:])}",
            "entry (i, j): radial displacement at node i [m] (+ outward) per unit radial force at "
            "node j [N] (+ outward)",
            f"nodes: {name}_nodes.csv (row/column k = node k); {grid.n_phi} x {grid.n_y} tensor "
            "grid, phi fastest",
            f"FE: {mesh.node_count()} nodes, {len(mesh.elements)} C3D8I elements, "
            f"{args.refine} elements per structural cell; written unsymmetrised (FE precision "
            "about 1e-6 relative)",
        ]
        write_mtx(os.path.join(args.out, f"{name}_compliance.mtx"), C, header)
        gas_um_per_MPa = None if gas is None else [v * 1e3 for v in gas]  # mm/MPa -> um/MPa
        write_nodes(os.path.join(args.out, f"{name}_nodes.csv"), grid, [
            f"pistondyn structural grid: {name}, generated by examples/fe/make_compliance.py",
            "phi from +x (thrust) towards +z (pin axis); y " + args.y_meaning,
            "gas_u_r_um_per_MPa: radial displacement (+ outward) per unit cylinder pressure"
            if gas is not None else "no gas-pressure field",
        ], gas_um_per_MPa, args.y_output_offset_mm)
        run_info = {
            "name": name, "command": sys.argv[1:], "model": model,
            "grid": {"n_phi": grid.n_phi, "n_y": grid.n_y, "y0_mm": grid.y0, "y1_mm": grid.y1},
            "mesh": mesh_info,
            "times_s": {"gmsh": round(info["gmsh_s"], 2), "ccx": round(t_ccx, 2),
                        "total": round(t_total, 2)},
            "versions": {"gmsh": tool_version(["gmsh", "--version"]),
                         "ccx": tool_version(["ccx", "-v"])},
        }
        with open(os.path.join(args.out, f"{name}_fe_run.json"), "w") as f:
            json.dump(run_info, f, indent=2)
            f.write("\n")
        print(f"make_compliance: {name}: {n} structural nodes, FE {mesh.node_count()} nodes / "
              f"{len(mesh.elements)} elements, {len(cases)} load cases, gmsh {info['gmsh_s']:.1f} s, "
              f"ccx {t_ccx:.1f} s, total {t_total:.1f} s")
    finally:
        if not args.work_dir and not args.keep:
            shutil.rmtree(work, ignore_errors=True)


def diagonal_only(args, work, mesh, grid, fixed, surface, info, t_start):
    """Mesh-refinement study: only the diagonal entries C_kk of the nodes at the angles asked
    for (every row), written to NAME_diagonal.csv [m/N] with the run record."""
    cases = []
    for text in args.diagonal_at_phi_deg.split(","):
        a = float(text) / 360.0 * grid.n_phi
        if abs(a - round(a)) > 1e-9:
            raise InputError(f"--diagonal-at-phi-deg {text}: not a structural node angle "
                             f"(multiples of {360.0 / grid.n_phi:g} deg)")
        cases += [int(round(a)) % grid.n_phi + grid.n_phi * j for j in range(grid.n_y)]
    columns, _, t_ccx = solve_cases(work, mesh, (args.young_MPa, args.poisson), fixed, surface,
                                    cases, None, args.keep)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, f"{args.name}_diagonal.csv"), "w") as f:
        f.write(f"# diagonal of the compliance, examples/fe/make_compliance.py {' '.join(sys.argv[1:])}\n")
        f.write(f"# FE: {mesh.node_count()} nodes, {len(mesh.elements)} C3D8I elements, "
                f"refine {args.refine}; ccx {t_ccx:.1f} s\n")
        f.write("node,phi_deg,y_mm,c_kk_m_per_N\n")
        for k in cases:
            i, j = k % grid.n_phi, k // grid.n_phi
            f.write(f"{k + 1},{360.0 * i / grid.n_phi!r},{grid.y(j):.9g},{columns[k][k] * 1e-3:.7e}\n")
    print(f"make_compliance: {args.name}: diagonal at {len(cases)} nodes, FE {mesh.node_count()} "
          f"nodes / {len(mesh.elements)} elements, ccx {t_ccx:.1f} s, total "
          f"{time.monotonic() - t_start:.1f} s")


def ring_only(args, work, mesh, grid, fixed, surface, model, t_start):
    """Verification: one load case, the uniform radial ring of nodal forces on structural row
    --ring-at-row (1 N in total, 1/nPhi N per node, each as its consistent hat load); writes the
    row's mean hat-weighted radial displacement [m/N] and the model to NAME_ring.json."""
    j = args.ring_at_row
    if not 0 <= j < grid.n_y:
        raise InputError(f"--ring-at-row {j}: rows are 0..{grid.n_y - 1}")
    row = [i + grid.n_phi * j for i in range(grid.n_phi)]
    summed = {}  # neighbouring hats share FE nodes: one CLOAD line per node and DOF
    for k in row:
        for node, dof, value in radial_loads(surface, k, 1.0 / grid.n_phi):
            summed[(node, dof)] = summed.get((node, dof), 0.0) + value
    load = [(node, dof, value) for (node, dof), value in sorted(summed.items())]
    _, u, t_ccx = solve_cases(work, mesh, (args.young_MPa, args.poisson), fixed, surface, [],
                              load, args.keep)
    mean = sum(u[k] for k in row) / grid.n_phi * 1e-3  # mm/N -> m/N
    os.makedirs(args.out, exist_ok=True)
    record = {"name": args.name, "command": sys.argv[1:], "model": model,
              "grid": {"n_phi": grid.n_phi, "n_y": grid.n_y, "y0_mm": grid.y0, "y1_mm": grid.y1},
              "ring_row": j, "ring_y_mm": grid.y(j), "mean_radial_displacement_m_per_N": mean,
              "row_min_max_m_per_N": [min(u[k] for k in row) * 1e-3, max(u[k] for k in row) * 1e-3],
              "fe_nodes": mesh.node_count(), "fe_elements": len(mesh.elements),
              "times_s": {"ccx": round(t_ccx, 2), "total": round(time.monotonic() - t_start, 2)}}
    with open(os.path.join(args.out, f"{args.name}_ring.json"), "w") as f:
        json.dump(record, f, indent=2)
        f.write("\n")
    print(f"make_compliance: {args.name}: ring at row {j}: {mean:.6e} m/N, ccx {t_ccx:.1f} s")


def tool_version(cmd):
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
        text = (out.stdout + out.stderr).strip()
        m = re.search(r"(\d+\.\d+(\.\d+)?)", text)
        return m.group(1) if m else text[:40]
    except (OSError, subprocess.SubprocessError):
        return "unknown"


# ---------------------------------------------------------------------------------------------
# Command line.


def pin_heights(deck, path):
    """Pin-axis heights above the crank axis at BDC and TDC [mm] (crank and rod collinear)."""
    r = 0.5 * deck_number(deck, path, "geometry.stroke_mm")
    l = deck_number(deck, path, "geometry.conrod_length_mm")
    e = (deck_number(deck, path, "geometry.pin_offset_mm", 0.0) +
         deck_number(deck, path, "geometry.crank_offset_mm", 0.0))
    return math.sqrt((l - r) ** 2 - e * e), math.sqrt((l + r) ** 2 - e * e)


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="make_compliance.py",
        description="Radial compliance of a piston skirt or a liner band from gmsh + CalculiX "
                    "(examples/fe/README.md).")
    sub = p.add_subparsers(dest="model", required=True)

    def common(q, name, n_phi, young, poisson):
        q.add_argument("--out", required=True, help="folder for the files written")
        q.add_argument("--name", default=name, help=f"file stem (default {name})")
        q.add_argument("--n-phi", type=int, default=n_phi,
                       help=f"structural nodes around the full circle (multiple of 4, default {n_phi})")
        q.add_argument("--refine", type=int, default=3,
                       help="FE elements per structural cell along phi and y, and through the "
                            "wall (>= 2, default 3)")
        q.add_argument("--young-MPa", type=float,
                       help=f"Young's modulus [MPa] (default: the deck's "
                            f"liner.asperity.{name}_youngs_modulus_GPa, else {young:g})")
        q.add_argument("--poisson", type=float,
                       help=f"Poisson's ratio (default: the deck's "
                            f"liner.asperity.{name}_poisson_ratio, else {poisson:g})")
        q.set_defaults(material_defaults=(name, young, poisson))
        q.add_argument("--work-dir", help="keep the gmsh / ccx files in this folder")
        q.add_argument("--keep", action="store_true", help="keep the ccx input and output")
        q.add_argument("--ring-at-row", type=int,
                       help="verification: only the uniform ring load on this structural row "
                            "(0 = lowest), written to NAME_ring.json")
        q.add_argument("--diagonal-at-phi-deg",
                       help="refinement study: only the diagonal at these node angles "
                            "(comma-separated, every row), written to NAME_diagonal.csv")

    s = sub.add_parser("skirt", help="piston skirt with pin bosses, ring belt and crown")
    common(s, "skirt", 36, 72000.0, 0.33)
    s.add_argument("--deck", help="engine deck: bore, skirt length and top, compression height")
    s.add_argument("--n-y", type=int, default=13, help="structural rows over the skirt (default 13)")
    for key, what in (("bore-mm", "bore"), ("skirt-length-mm", "skirt length"),
                      ("skirt-top-mm", "skirt top above the pin axis"),
                      ("compression-height-mm", "pin axis to crown top")):
        s.add_argument(f"--{key}", type=float, help=f"{what} [mm] (default: from the deck)")
    s.add_argument("--skirt-wall-mm", type=float, help="skirt wall (default 0.04 bore, EST)")
    s.add_argument("--ring-belt-wall-mm", type=float,
                   help="radial wall of ring belt and pin bosses (default 0.09 bore, EST)")
    s.add_argument("--crown-mm", type=float, help="crown thickness (default 0.08 bore, EST)")
    s.add_argument("--crown-hole-fraction", type=float, default=0.2,
                   help="radius of the crown's central hole / (bore/2) (default 0.2; the "
                        "structured mesh needs it)")
    s.add_argument("--pin-diameter-mm", type=float, help="pin diameter (default 0.24 bore, EST)")
    s.add_argument("--boss-half-height-mm", type=float,
                   help="pin boss reaches this far below the pin axis (default 0.8 pin diameter)")
    s.add_argument("--boss-half-angle-deg", type=float, default=20.0,
                   help="pin boss half-width around the pin axis (default 20, snapped to the grid)")

    ln = sub.add_parser("liner", help="liner band: plain cylinder over the skirt's travel")
    common(ln, "liner", 36, 115000.0, 0.26)
    ln.add_argument("--deck", required=True, help="engine deck (bore, stroke, rod, offsets, skirt)")
    ln.add_argument("--wall-mm", type=float, help="liner wall (default 0.1 bore, EST)")
    ln.add_argument("--row-spacing-mm", type=float, default=5.0,
                    help="target spacing of the structural rows (default 5)")
    ln.add_argument("--margin-below-mm", type=float, default=10.0,
                    help="liner below the lowest skirt edge at BDC (default 10)")

    c = sub.add_parser("cylinder", help="plain cylinder (verification of the FE chain)")
    common(c, "cylinder", 36, 72000.0, 0.33)
    c.add_argument("--n-y", type=int, default=13, help="structural rows (default 13)")
    c.add_argument("--loaded-radius-mm", type=float, required=True, help="radius of the loaded surface")
    c.add_argument("--wall-mm", type=float, required=True)
    c.add_argument("--loaded-surface", choices=("outer", "inner"), default="outer")
    c.add_argument("--length-mm", type=float, required=True, help="cylinder length, centred on y = 0")
    c.add_argument("--grid-length-mm", type=float, required=True,
                   help="length of the structural grid, centred on y = 0")

    args = p.parse_args(argv)
    if args.refine < 2:
        raise InputError(f"--refine {args.refine}: at least 2 (2 elements through the wall)")
    args.far_spacing_factor = 2.0
    if args.model == "skirt":
        deck, path = ({}, None) if not args.deck else (read_deck(args.deck), args.deck)

        def get(attr, key):
            v = getattr(args, attr)
            if v is None:
                if path is None:
                    raise InputError(f"--{attr.replace('_', '-')} or --deck needed")
                v = deck_number(deck, path, key)
                setattr(args, attr, v)
            return v

        bore = get("bore_mm", "geometry.bore_mm")
        get("skirt_length_mm", "piston.skirt_length_mm")
        get("skirt_top_mm", "piston.skirt_top_above_pin_mm")
        get("compression_height_mm", "piston.compression_height_mm")
        args.skirt_wall_mm = args.skirt_wall_mm or round(0.04 * bore, 1)
        args.ring_belt_wall_mm = args.ring_belt_wall_mm or round(0.09 * bore, 1)
        args.crown_mm = args.crown_mm or round(0.08 * bore, 1)
        args.pin_diameter_mm = args.pin_diameter_mm or round(0.24 * bore, 1)
        args.pin_radius_mm = 0.5 * args.pin_diameter_mm
        if args.boss_half_height_mm is None:
            args.boss_half_height_mm = 0.8 * args.pin_diameter_mm
        args.y_meaning = "[mm]: height above the pin axis in the piston frame"
    elif args.model == "liner":
        deck = read_deck(args.deck)
        bore = deck_number(deck, args.deck, "geometry.bore_mm")
        L = deck_number(deck, args.deck, "piston.skirt_length_mm")
        top = deck_number(deck, args.deck, "piston.skirt_top_above_pin_mm")
        ch = deck_number(deck, args.deck, "piston.compression_height_mm")
        bdc, tdc = pin_heights(deck, args.deck)
        args.wall_mm = args.wall_mm or round(0.1 * bore, 1)
        args.inner_radius_mm = 0.5 * bore
        args.loaded_surface = "inner"
        args.grid_bottom_mm, args.grid_top_mm = bdc + top - L, tdc + top
        args.n_y = max(3, int(round((args.grid_top_mm - args.grid_bottom_mm) / args.row_spacing_mm)) + 1)
        args.bottom_mm = args.grid_bottom_mm - args.margin_below_mm
        args.top_mm = tdc + ch  # liner top: crown flush with it at TDC (as the skirt element)
        args.y_meaning = "[mm]: height above the crank axis (ground frame)"
    else:
        if args.loaded_surface == "outer":
            args.inner_radius_mm = args.loaded_radius_mm - args.wall_mm
        else:
            args.inner_radius_mm = args.loaded_radius_mm
        args.grid_bottom_mm, args.grid_top_mm = -0.5 * args.grid_length_mm, 0.5 * args.grid_length_mm
        args.bottom_mm, args.top_mm = -0.5 * args.length_mm, 0.5 * args.length_mm
        args.y_meaning = "[mm]: along the axis from the cylinder's middle"
    # Elastic data: the deck's (its asperity-contact data, so film contact and compliance see
    # one material), else the defaults of README.md "Material data".
    part, young, poisson = args.material_defaults
    deck = read_deck(args.deck) if getattr(args, "deck", None) else {}
    if args.young_MPa is None:
        key = f"liner.asperity.{part}_youngs_modulus_GPa"
        args.young_MPa = 1e3 * deck_number(deck, args.deck, key) if key in deck else young
    if args.poisson is None:
        key = f"liner.asperity.{part}_poisson_ratio"
        args.poisson = deck_number(deck, args.deck, key) if key in deck else poisson
    args.y_output_offset_mm = 0.0
    for tool in ("gmsh", "ccx"):
        if shutil.which(tool) is None:
            raise InputError(f"the program '{tool}' is not on PATH (Debian: apt-get install "
                             f"{'gmsh' if tool == 'gmsh' else 'calculix-ccx'})")
    return args


def main(argv):
    try:
        args = parse_args(argv)
        compliance(args)
    except InputError as e:
        print(f"make_compliance: {e}", file=sys.stderr)
        return 1
    except (RuntimeError, OSError) as e:
        print(f"make_compliance: failed: {e}", file=sys.stderr)
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
