"""The numpy reference for the sweep benchmark (benches/sweep/README.md).

Evaluates only the Hertz closed forms for the rows of benches/sweep/hertz-1e6.toml and writes the
same CSV columns as `halfplane sweep`: the five varied inputs (drawn with the sweep's own
counter-based generator, so the rows are the same), then regime, stick_left, stick_right,
half_width_1, half_width_2, slip_left_1, slip_left_2, slip_right_1, slip_right_2, error.

Formulas (no bulk tension, point 1 has Q = 0 and point 2 Q = dQ >= 0, so point 1 is the smaller-Q
end): A = 4 (1 - nu^2)/E; a_i = sqrt(2 P_i A R/pi) (paper eq. (24)); gross sliding when
|Q_i| >= f P_i at an end; full stick when dQ <= f |P2 - P1| (eq. (1) with dsigma = 0), stick zone
the smaller contact and no slip; otherwise partial slip with d^2 = (A R/pi)(P1 + P2 - dQ/f)
(eq. (30)), e = 0, stick zone [-d, d] and slip zones a_i - d at both edges.

Usage:
    python hertz_numpy.py OUT.csv [ROWS]          write the CSV, print the time taken
    python hertz_numpy.py --compare A.csv B.csv   check two outputs hold the same rows
"""

import sys
import time

import numpy as np

MASK = (1 << 64) - 1
GOLDEN = 0x9E3779B97F4A7C15


def mix_int(z):
    """SplitMix64 finaliser on a Python int (halfplane::design, counter.rs)."""
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return z ^ (z >> 31)


def mix(z):
    """The same on a uint64 array (numpy multiplication wraps modulo 2^64)."""
    z = z ^ (z >> np.uint64(30))
    z = z * np.uint64(0xBF58476D1CE4E5B9)
    z = z ^ (z >> np.uint64(27))
    z = z * np.uint64(0x94D049BB133111EB)
    return z ^ (z >> np.uint64(31))


def unit(seed, axis, rows):
    """Uniform [0, 1) numbers of `axis` for rows 0..rows: the sweep's random design."""
    stream = axis << 1
    key = mix_int((seed + GOLDEN) & MASK)
    key = mix_int(key ^ ((stream * GOLDEN) & MASK))
    counter = np.arange(rows, dtype=np.uint64) * np.uint64(0xD1B54A32D192ED03)
    h = mix(np.uint64(key) ^ counter)
    return (h >> np.uint64(11)).astype(np.float64) * (1.0 / (1 << 53))


def linear(t, lo, hi):
    return np.clip(lo + (hi - lo) * t, lo, hi)


def run(out, rows):
    """Writes the CSV; returns the seconds spent computing (before formatting)."""
    start = time.perf_counter()
    seed, e_mod, nu = 2026, 200000.0, 0.3
    f = linear(unit(seed, 0, rows), 0.2, 0.9)
    r = linear(unit(seed, 1, rows), 10.0, 100.0)
    p1 = linear(unit(seed, 2, rows), 500.0, 1500.0)
    p2 = linear(unit(seed, 3, rows), 500.0, 1500.0)
    dq = linear(unit(seed, 4, rows), 0.0, 600.0)

    a_comp = 4.0 * (1.0 - nu * nu) / e_mod
    a1 = np.sqrt(2.0 * p1 * a_comp * r / np.pi)
    a2 = np.sqrt(2.0 * p2 * a_comp * r / np.pi)
    sliding = dq >= f * p2  # |Q1| = 0 never reaches f P1 > 0
    full = ~sliding & (dq <= f * np.abs(p2 - p1))
    partial = ~sliding & ~full
    with np.errstate(invalid="ignore"):
        d = np.sqrt(a_comp * r / np.pi * (p1 + p2 - dq / f))
    a_min = np.minimum(a1, a2)
    zone = np.where(full, a_min, np.where(partial, d, np.nan))
    nan = np.full(rows, np.nan)
    slip1 = np.where(full, 0.0, np.where(partial, a1 - d, nan))
    slip2 = np.where(full, 0.0, np.where(partial, a2 - d, nan))
    regime = np.where(sliding, "gross-sliding", np.where(full, "full-stick", "partial-slip"))

    computed = time.perf_counter() - start
    # One format per row (numbers with 17 significant digits, round-trip exact), filled from
    # column lists: the fastest way found to write numpy arrays as CSV here (np.savetxt formats
    # the same way row by row; np.char column-wise joins took 20x longer). NaN, written "nan",
    # becomes the empty cell the sweep writes for a value a row does not have.
    fmt = ",".join(["%.17g"] * 5 + ["%s"] + ["%.17g"] * 8) + ","
    columns = [v.tolist() for v in (f, r, p1, p2, dq)]
    columns.append(regime.tolist())
    columns += [v.tolist() for v in (-zone, zone, a1, a2, slip1, slip2, slip1, slip2)]
    text = "\n".join([fmt % row for row in zip(*columns)]).replace("nan", "")
    header = (
        "friction.coefficient,profile.radius,cycle.point1.normal,cycle.point2.normal,"
        "cycle.point2.shear,regime,stick_left,stick_right,half_width_1,half_width_2,"
        "slip_left_1,slip_left_2,slip_right_1,slip_right_2,error\n"
    )
    with open(out, "w") as fh:
        fh.write(header)
        fh.write(text)
        fh.write("\n")
    return computed


def compare(a_path, b_path):
    """Same header, same regimes and errors, numbers equal to 1e-12 relative (the two evaluate
    the same closed forms in different orders)."""
    def load(path):
        with open(path) as fh:
            return [line.rstrip("\n").split(",") for line in fh]

    a, b = load(a_path), load(b_path)
    assert a[0] == b[0], f"headers differ: {a[0]} vs {b[0]}"
    assert len(a) == len(b), f"{len(a)} vs {len(b)} lines"
    worst = 0.0
    for i, (ra, rb) in enumerate(zip(a[1:], b[1:]), start=2):
        for name, x, y in zip(a[0], ra, rb):
            if name in ("regime", "error") or x == "" or y == "":
                assert x == y, f"line {i}, {name}: {x!r} vs {y!r}"
                continue
            x, y = float(x), float(y)
            err = abs(x - y) / max(abs(x), abs(y), 1e-300)
            worst = max(worst, err if abs(x - y) > 1e-15 else 0.0)
            assert err <= 1e-12 or abs(x - y) <= 1e-15, f"line {i}, {name}: {x} vs {y}"
    print(f"same rows: {len(a) - 1}, largest relative difference {worst:.1e}")


if __name__ == "__main__":
    if sys.argv[1] == "--compare":
        compare(sys.argv[2], sys.argv[3])
    else:
        rows = int(sys.argv[2]) if len(sys.argv) > 2 else 1_000_000
        start = time.perf_counter()
        computed = run(sys.argv[1], rows)
        total = time.perf_counter() - start
        print(f"numpy: {rows} rows in {total:.2f} s ({computed:.2f} s computing, the rest writing)")
