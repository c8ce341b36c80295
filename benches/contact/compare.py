#!/usr/bin/env python3
"""Side by side with CONTACT on the 2-D Cattaneo problem (BENCHMARKS.md, "Against CONTACT").

A Hertz cylinder (R = 50 mm, E = 200 GPa, nu = 0.3 for both bodies, f = 0.6) is pressed with
P = 1000 N/mm and then sheared at constant P to Q = 0.5 f P. The same case is solved by
`halfplane march` (plane strain) and by CONTACT (a 3-D half-space code, given a strip one element
deep and DY long, which approximates plane strain), on the same cells, and each result is compared
with the Cattaneo-Mindlin traction q = f (p_a - p_c) (Johnson, Contact Mechanics, section 7.1).

Reported per tool and number of cells: the CPU time of the tool's process (user + system, from
getrusage of the waited child), the wall time, and the largest traction error at the cell centres
as a fraction of f p0; then the CPU time each tool needs to reach 0.1% and 0.02% of f p0.

Standard library only. Usage (see README.md beside this file):

    python3 benches/contact/compare.py --contact /path/to/contact_gf
    CONTACT_EXE=/path/to/contact_gf python3 benches/contact/compare.py
    python3 benches/contact/compare.py --halfplane-only --cells 400,800
"""

import argparse
import json
import math
import os
import re
import resource
import shutil
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

# The case. Both bodies are of one material, so normal and tangential problems uncouple
# (Johnson's process in CONTACT, the half-plane theory in halfplane).
YOUNGS = 200000.0  # MPa
POISSON = 0.3
FRICTION = 0.6
RADIUS = 50.0  # mm, cylinder on a flat
NORMAL = 1000.0  # N/mm
SHEAR_RATIO = 0.5  # Q / (f P)
# CONTACT's exterior elements on each side of the contact (its user guide asks for two).
CONTACT_MARGIN = 2


def hertz():
    """Plane-strain Hertz half-width a and peak pressure p0 (Johnson section 4.3, eq. 4.43-4.45,
    with the composite compliance A = 4 (1 - nu^2) / E of two equal bodies: a^2 = 2 P R A / pi,
    p0 = 2 P / (pi a))."""
    compliance = 4.0 * (1.0 - POISSON**2) / YOUNGS
    a = math.sqrt(2.0 * NORMAL * RADIUS * compliance / math.pi)
    return a, 2.0 * NORMAL / (math.pi * a)


def cattaneo(x, a, p0):
    """Cattaneo-Mindlin traction at x (Johnson section 7.1, eq. 7.8-7.10), positive along Q:
    q = f p0 sqrt(1 - x^2/a^2) - f p0 (c/a) sqrt(1 - x^2/c^2), c = a sqrt(1 - Q/(f P))."""
    c = a * math.sqrt(1.0 - SHEAR_RATIO)
    q = 0.0
    if abs(x) < a:
        q += FRICTION * p0 * math.sqrt(1.0 - (x / a) ** 2)
    if abs(x) < c:
        q -= FRICTION * p0 * (c / a) * math.sqrt(1.0 - (x / c) ** 2)
    return q


def pressure(x, a, p0):
    """Hertz pressure p0 sqrt(1 - x^2/a^2) (Johnson eq. 4.43), zero outside the contact."""
    return p0 * math.sqrt(1.0 - (x / a) ** 2) if abs(x) < a else 0.0


def errors(rows, a, p0):
    """Largest |q - q_exact| and |p - p_exact| over (x, p, q) rows, as fractions of f p0 and p0,
    and where the former is: the distance of that cell's centre from the nearer of the stick
    edge |x| = c and the contact edge |x| = a, in cells (positive outside)."""
    dq, at = max((abs(q - cattaneo(x, a, p0)), x) for x, _, q in rows)
    dp = max(abs(p - pressure(x, a, p0)) for x, p, _ in rows)
    width = rows[1][0] - rows[0][0]
    c = a * math.sqrt(1.0 - SHEAR_RATIO)
    from_c, from_a = (abs(at) - c) / width, (abs(at) - a) / width
    where = f"c{from_c:+.2f}" if abs(from_c) < abs(from_a) else f"a{from_a:+.2f}"
    return dq / (FRICTION * p0), dp / p0, where


def run_timed(cmd, cwd):
    """Runs cmd to completion; returns (cpu seconds of the child, user + system; wall seconds)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(
        cmd, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True, text=True
    )
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        sys.exit(
            f"{' '.join(map(str, cmd))} (in {cwd}) exited {done.returncode}:\n"
            f"{done.stdout[-2000:]}{done.stderr[-2000:]}"
        )
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall, done


# ---------------------------------------------------------------------------------------------
# halfplane


def halfplane_case(cells, sub_cell):
    """The case as a halfplane case file: pressed to P in one increment, sheared to Q in one
    more. `march` puts `cells` equal cells across [-a, a]."""
    q = SHEAR_RATIO * FRICTION * NORMAL
    return f"""# By benches/contact/compare.py: Cattaneo, Q = {SHEAR_RATIO} f P, constant P.
[material]
youngs_modulus = {YOUNGS!r}
poisson_ratio = {POISSON!r}

[friction]
coefficient = {FRICTION!r}

[profile]
kind = "hertz"
radius = {RADIUS!r}

[history]
data = \"\"\"normal,shear,bulk
{NORMAL!r},0.0,0.0
{NORMAL!r},{q!r},0.0
\"\"\"

[solver]
cells = {cells}
sub_cell_boundaries = {"true" if sub_cell else "false"}
"""


def run_halfplane(exe, cells, sub_cell, work):
    tag = "sub-cell" if sub_cell else "cell-edges"
    case = work / f"halfplane-{tag}-{cells}.toml"
    case.write_text(halfplane_case(cells, sub_cell))
    fields = work / f"halfplane-{tag}-{cells}-fields"
    shutil.rmtree(fields, ignore_errors=True)
    cpu, wall, _ = run_timed(
        [exe, "march", case, "--fields", fields, "--format", "csv"], work
    )
    steps = sorted(fields.glob("step_*.csv"))
    if len(steps) != 2:
        sys.exit(f"{fields}: expected the fields of 2 increments, found {len(steps)}")
    rows = []
    with steps[-1].open() as f:
        head = f.readline().strip().split(",")
        ix, ip, iq = head.index("x"), head.index("pressure"), head.index("traction")
        for line in f:
            v = line.split(",")
            rows.append((float(v[ix]), float(v[ip]), float(v[iq])))
    return cpu, wall, rows, ""


# ---------------------------------------------------------------------------------------------
# CONTACT


def contact_input(cells, eps, strip):
    """The case as CONTACT input (module 3; user guide, sections "The control integers",
    "Potential contact area and discretisation" and the cattaneo and carter2d examples).

    One case: P-digit 2 (new sequence, no previous tangential traction), T = 1 (shift),
    N = 1 and F = 1 (total normal force and relative tangential force FX = Q/(fP) prescribed,
    CETA = 0), C = 2 (half-space influence coefficients of piecewise-constant tractions),
    A = 2 (write every element to the .mat file), O = 1 (global output only), W = 0 (no flow
    trace). The grid is one row (MY = 1) of strip-long elements, DY = `strip`, whose centres are
    halfplane's (cells of width 2a/cells across [-a, a]) plus CONTACT_MARGIN on each side; FN is
    the force on that strip, P DY. Undeformed distance h = x^2/(2R) (IBASE = 1, B1 = 1/(2R))."""
    mx, xc1, dx = contact_grid(cells)
    shear_modulus = YOUNGS / (2.0 * (1.0 + POISSON))
    return f"""% By benches/contact/compare.py: 2-D Cattaneo, Q = {SHEAR_RATIO} f P, constant P,
% on a strip one element deep (plane strain approximated by DY = {strip} mm).
 3  MODULE
  201110     P-B-T-N-F-S        PVTIME, BOUND , TANG  , NORM , FORCE, STRESS
  022020     L-D-C-M-Z-E        FRCLAW, DISCNS, INFLCF, MATER, RZNORM, EXRHS
 0002101   H-G-I-A-O-W-R  HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN
   999   100    30     1   {eps:.3e}      MAXGS , MAXIN , MAXNR , MAXOUT, EPS
  {NORMAL * strip:.10e}  {SHEAR_RATIO:.6f}  0.0  0.0     FN, FX, CETA, CPHI
  {FRICTION:.6f}  {FRICTION:.6f}                        FSTAT, FKIN
  {POISSON:.6f}  {POISSON:.6f}  {shear_modulus:.10e}  {shear_modulus:.10e}   POISS 1,2,  GG 1,2
    3                                               IPOTCN
  {mx}  1  {xc1:.15e}  0.0  {dx:.15e}  {strip:.6e}   MX,MY,XC1,YC1,DX,DY
    1    1                                          IBASE, IPLAN
  {1.0 / (2.0 * RADIUS):.15e}  0.0  0.0  0.0  0.0  0.0     B(I), I=1, 6

 0  MODULE
"""


def contact_grid(cells):
    """CONTACT's elements: (MX, centre of element 1, width), halfplane's cells of width 2a/cells
    across [-a, a] plus CONTACT_MARGIN exterior elements on each side."""
    a, _ = hertz()
    dx = 2.0 * a / cells
    return cells + 2 * CONTACT_MARGIN, -a + (0.5 - CONTACT_MARGIN) * dx, dx


def read_contact_mat(path, cells):
    """(x, pn, px) per element of CONTACT's <experim>.<case>.mat (user guide, "Specification of
    the file <experim>.<case>.mat"): a comment line naming MX MY XL YL DX DY is followed by their
    values, and the comment line naming I IGS H MU PN PX PY ... by one row per element,
    I = ix + MX (iy - 1). The centres are computed from the grid written to the input, since the
    file prints XL and DX to six digits only; the file's own are checked against them."""
    lines = [l for l in path.read_text().splitlines() if l.strip()]
    mx, xc1, dx = contact_grid(cells)
    head = next(k for k, l in enumerate(lines) if l.lstrip("% ").startswith("MX"))
    grid = lines[head + 1].split()
    if (int(grid[0]), int(grid[1])) != (mx, 1) or abs(float(grid[2]) - (xc1 - 0.5 * dx)) > 1e-5:
        sys.exit(f"{path}: grid {grid[:6]} is not the one written to the input")
    table = next(k for k, l in enumerate(lines) if re.match(r"%\s+I\s+IGS", l))
    rows = []
    for line in lines[table + 1 :]:
        v = line.split()
        i = int(v[0])
        rows.append((xc1 + (i - 1) * dx, float(v[4]), float(v[5])))
    if [int(l.split()[0]) for l in lines[table + 1 :]] != list(range(1, mx + 1)):
        sys.exit(f"{path}: expected element rows 1..{mx}")
    return rows


def run_contact(exe, cells, eps, strip, work):
    name = f"contact-{cells}-eps{eps:.0e}"
    (work / f"{name}.inp").write_text(contact_input(cells, eps, strip))
    for old in work.glob(f"{name}.*mat"):
        old.unlink()
    cpu, wall, _ = run_timed([exe, "2", name], work)
    mats = sorted(work.glob(f"{name}.*mat"))
    if len(mats) != 1:
        sys.exit(f"{work}/{name}: expected one .mat file, found {len(mats)}; see {name}.out")
    out = (work / f"{name}.out").read_text(errors="replace")
    # CONTACT's warnings name elements whose state the tolerance leaves uncertain.
    warnings = sorted(set(re.findall(r"(\w+): WARNING", out)))
    if re.search(r"\bERROR\b", out):
        sys.exit(f"{work}/{name}.out reports an error")
    rows = read_contact_mat(mats[0], cells)
    # CONTACT's FX > 0 gives px > 0 on the element rows; check rather than assume.
    total = sum(q for _, _, q in rows)
    if total <= 0.0:
        sys.exit(f"{mats[0]}: total px {total} not along the prescribed FX")
    return cpu, wall, rows, ",".join(warnings)


# ---------------------------------------------------------------------------------------------
# report


def time_to(runs, target):
    """The CPU time at which a tool's error first falls to `target` (runs sorted by cells):
    interpolated in log-log between the last run above and the first at or below it; at most
    the first run's time when that one already is; None when no run reaches it. The second
    value names a later run that is above the target again, if any."""
    for k, r in enumerate(runs):
        if r["error"] <= target:
            again = next((s["cells"] for s in runs[k + 1 :] if s["error"] > target), None)
            if k == 0:
                return ("<=", r["cpu"]), again
            p = runs[k - 1]
            t = (math.log(target) - math.log(p["error"])) / (
                math.log(r["error"]) - math.log(p["error"])
            )
            cpu = math.exp(math.log(p["cpu"]) + t * (math.log(r["cpu"]) - math.log(p["cpu"])))
            return ("~", cpu), again
    return None, None


def exponent(runs):
    """Least-squares slope of log(cpu) against log(cells)."""
    xs = [math.log(r["cells"]) for r in runs]
    ys = [math.log(r["cpu"]) for r in runs]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def loosest_eps(by_eps, slack):
    """Per cell count, the run at the loosest CONTACT tolerance that keeps its accuracy: whose
    traction differs from the tightest tolerance's nowhere by more than `slack` times the
    tightest's error against the exact traction. Chosen per cell count because a tolerance that
    suffices on a coarse grid need not on a fine one (EPS bounds the relative change of the
    tractions between iterations, not their error)."""
    tightest = by_eps[min(by_eps)]
    chosen = []
    for k, tight in enumerate(tightest):
        for eps in sorted(by_eps, reverse=True):
            r = by_eps[eps][k]
            change = max(abs(q - t) for q, t in zip(r["traction"], tight["traction"]))
            if change <= slack * tight["error"]:
                chosen.append(dict(r, eps=eps, change=change))
                break
    return chosen


def compared_names(results):
    """The series compared: halfplane's two and CONTACT at its chosen tolerances."""
    return [k for k in results if not k.startswith("CONTACT ")]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--contact", default=os.environ.get("CONTACT_EXE"),
                    help="CONTACT executable (default: $CONTACT_EXE)")
    ap.add_argument("--halfplane", default=os.environ.get("HALFPLANE_EXE"),
                    help="halfplane executable (default: $HALFPLANE_EXE, else a release build "
                    "of the repository made with cargo)")
    ap.add_argument("--halfplane-only", action="store_true", help="skip CONTACT")
    ap.add_argument("--cells", default="400,800,1600,3200")
    ap.add_argument("--eps", default="1e-4,1e-5,1e-6,1e-7,1e-8",
                    help="CONTACT tolerances EPS to run; the loosest that keeps the tightest's "
                    "accuracy is the one compared")
    ap.add_argument("--slack", type=float, default=0.1,
                    help="a CONTACT tolerance keeps the accuracy when its traction differs from "
                    "the tightest tolerance's by at most this fraction of the latter's error")
    ap.add_argument("--strip", type=float, default=200.0,
                    help="CONTACT's element depth DY in mm (default 200, about 260 a)")
    ap.add_argument("--repeats", type=int, default=3,
                    help="runs of each halfplane case; the least CPU time counts")
    ap.add_argument("--contact-repeats", type=int, default=1)
    ap.add_argument("--work", default=None, help="scratch directory (default target/bench-contact)")
    ap.add_argument("--json", default=None, help="also write every run to this JSON file")
    args = ap.parse_args()

    cells = [int(c) for c in args.cells.split(",")]
    eps_list = [float(e) for e in args.eps.split(",")]
    if not args.halfplane_only and not args.contact:
        sys.exit("no CONTACT executable: pass --contact PATH or set CONTACT_EXE "
                 "(README.md beside this script says how to build one), or use --halfplane-only")
    target_dir = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    work = Path(args.work) if args.work else target_dir / "bench-contact"
    work.mkdir(parents=True, exist_ok=True)
    work = work.resolve()
    exe = args.halfplane
    if exe is None:
        subprocess.run(["cargo", "build", "--release", "-q", "-p", "halfplane-cli"],
                       cwd=REPO, check=True)
        exe = target_dir / "release" / "halfplane"
    exe = Path(exe).resolve()
    contact = None if args.halfplane_only else Path(args.contact).resolve()

    a, p0 = hertz()
    print(f"Cattaneo: R = {RADIUS} mm, E = {YOUNGS} MPa, nu = {POISSON}, f = {FRICTION}, "
          f"P = {NORMAL} N/mm, Q = {SHEAR_RATIO} f P; a = {a:.6f} mm, p0 = {p0:.4f} MPa")
    if contact:
        print(f"CONTACT: {contact}, strip DY = {args.strip} mm, {CONTACT_MARGIN} exterior "
              "elements each side; direct influence products unless built with MKL's FFT")
    print(f"halfplane: {exe}")

    tools = {}
    for sub_cell in (False, True):
        name = "halfplane sub-cell" if sub_cell else "halfplane"
        tools[name] = []
        for n in cells:
            best = None
            for _ in range(args.repeats):
                cpu, wall, rows, note = run_halfplane(exe, n, sub_cell, work)
                if best is None or cpu < best[0]:
                    best = (cpu, wall, rows, note)
            tools[name].append((n, best))
    by_eps = {}
    if contact:
        for eps in eps_list:
            by_eps[eps] = []
            for n in cells:
                best = None
                for _ in range(args.contact_repeats):
                    cpu, wall, rows, note = run_contact(contact, n, eps, args.strip, work)
                    if best is None or cpu < best[0]:
                        best = (cpu, wall, rows, note)
                by_eps[eps].append((n, best))

    def summarise(runs):
        out = []
        for n, (cpu, wall, rows, note) in runs:
            eq, ep, where = errors(rows, a, p0)
            out.append({"cells": n, "cpu": cpu, "wall": wall, "error": eq, "error_at": where,
                        "pressure_error": ep, "warnings": note,
                        "traction": [q / (FRICTION * p0) for _, _, q in rows]})
        return out

    results = {name: summarise(runs) for name, runs in tools.items()}
    contact_results = {eps: summarise(runs) for eps, runs in by_eps.items()}
    chosen = loosest_eps(contact_results, args.slack) if contact_results else None
    for eps, runs in sorted(contact_results.items(), reverse=True):
        results[f"CONTACT EPS {eps:.0e}"] = runs

    print("\ntool                  cells    cpu_s   wall_s  max |q - q_exact|/(f p0)  at (cells)  "
          "max |p - p_exact|/p0  CONTACT warnings")
    for name, runs in results.items():
        for r in runs:
            print(f"{name:<20} {r['cells']:>6} {r['cpu']:>8.3f} {r['wall']:>8.3f}  "
                  f"{r['error']:>24.3e}  {r['error_at']:>10}  {r['pressure_error']:>20.3e}  "
                  f"{r['warnings']}")
    print("'at': the cell of the largest traction error, as its centre's distance in cells from "
          "the nearer of the stick edge (c) and the contact edge (a), positive outside")
    if chosen is not None:
        results["CONTACT"] = chosen
        print(f"\nCONTACT compared at the loosest EPS of {args.eps} whose traction differs "
              f"from EPS {min(eps_list):.0e}'s by at most {args.slack:g} times the latter's "
              "error (cells: EPS, largest difference / (f p0)): "
              + ", ".join(f"{r['cells']}: {r['eps']:.0e}, {r['change']:.1e}" for r in chosen))
        if any(r["eps"] == min(eps_list) for r in chosen):
            print("  (where the tightest EPS is the one chosen, no run shows that it keeps the "
                  "accuracy: add a tighter --eps to see how far it still moves)")
    print("\nSummary (CPU s / max traction error as a fraction of f p0):\n")
    print("| cells | " + " | ".join(compared_names(results)) + " |")
    print("|---" * (1 + len(compared_names(results))) + "|")
    for k, n in enumerate(cells):
        cols = []
        for name in compared_names(results):
            r = results[name][k]
            eps = f" (EPS {r['eps']:.0e})" if "eps" in r else ""
            cols.append(f"{r['cpu']:.3f} s / {r['error']:.2e}{eps}")
        print(f"| {n} | " + " | ".join(cols) + " |")
    print("\nCPU time against cells, least-squares exponent b of cpu ~ N^b:")
    for name, runs in results.items():
        if len(runs) >= 2:
            print(f"  {name:<20} b = {exponent(runs):.2f}")
    compared = {k: results[k] for k in compared_names(results)}
    print("\nCPU time to reach an error of (first grid at or below it; '~' interpolated "
          "log-log between grids):")
    for target in (1e-3, 2e-4):
        for name, runs in compared.items():
            hit, again = time_to(runs, target)
            if hit is None:
                best = min(runs, key=lambda r: r["error"])
                text = (f"not reached in {cells[0]}-{cells[-1]} cells "
                        f"(best {best['error']:.2e} at {best['cells']})")
            else:
                text = f"{hit[0]} {hit[1]:.3f} s"
                if again is not None:
                    text += f" (above it again at {again} cells)"
            print(f"  {target:.2%} of f p0  {name:<20} {text}")
    if args.json:
        for runs in results.values():
            for r in runs:
                r.pop("traction")
        Path(args.json).write_text(json.dumps(
            {"case": {"E": YOUNGS, "nu": POISSON, "f": FRICTION, "R": RADIUS, "P": NORMAL,
                      "Q_over_fP": SHEAR_RATIO, "a": a, "p0": p0, "strip": args.strip},
             "results": results}, indent=1))


if __name__ == "__main__":
    main()
