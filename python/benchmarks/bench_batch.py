"""Speed of halfplane.steady_batch (issue 9), every figure a same-run comparison.

1. Hertz rows: steady_batch (the whole analysis: validation, regime, stick zone, slip zones, the
   slip-direction check) against plain numpy evaluating only the Hertz closed forms (a1, a2, d, e
   and the sliding test) on the same rows. Ratio = numpy time / steady_batch time.
2. Flat-rounded rows per second (all cores).
3. Dask on a 2-worker LocalCluster (one thread each) against the same partitions solved in this
   process, rows generated where they are solved, results reduced to a few numbers. With
   `--reuse-partitions` each process generates one partition once and solves it again for every
   partition, so that neither side's time includes making rows: solving plus Dask's overhead
   against solving alone.

Run from the repository root after `pip install "./python[dask]"`:
    python python/benchmarks/bench_batch.py [--rows 1000000] [--dask-rows 10000000]
        [--partition-rows 250000[,1000000,...]] [--reuse-partitions]
"""

from __future__ import annotations

import argparse
import os
import time
from typing import Callable, Dict, List, Tuple

import numpy as np
import pandas as pd

import halfplane


def hertz_rows(n: int, seed: int = 0) -> pd.DataFrame:
    rng = np.random.default_rng(seed)
    q = rng.uniform(100.0, 400.0, n)
    s = rng.uniform(0.0, 30.0, n)
    return pd.DataFrame(
        {
            "youngs_modulus": rng.uniform(1e5, 2.1e5, n),
            "poisson_ratio": np.full(n, 0.3),
            "friction": rng.uniform(0.4, 0.8, n),
            "profile": np.full(n, "hertz", dtype=object),
            "radius": rng.uniform(20.0, 80.0, n),
            "normal1": rng.uniform(800.0, 1200.0, n),
            "shear1": -q,
            "bulk1": -s,
            "normal2": rng.uniform(800.0, 1400.0, n),
            "shear2": q,
            "bulk2": s,
        }
    )


def flat_rows(n: int, seed: int = 1) -> pd.DataFrame:
    t = hertz_rows(n, seed)
    t["profile"] = "flat-rounded"
    t["flat_half_width"] = np.random.default_rng(seed).uniform(0.1, 0.5, n)
    return t


def numpy_hertz(t: Dict[str, np.ndarray]) -> tuple:
    """Only the Hertz closed forms, as a vectorised numpy script would: A = 4(1 - nu^2)/E,
    a_i = sqrt(2 P_i A R/pi) (paper eq. 24), with point 1 the end of smaller Q,
    d = sqrt((AR/pi)(P1 + P2 - dQ/f)) (eq. 30), e = -A R dsigma/(8f) (eq. 28), and |Q_i| >= f P_i."""
    e_mod, nu, f, r = t["youngs_modulus"], t["poisson_ratio"], t["friction"], t["radius"]
    p1, q1, s1, p2, q2, s2 = (t[k] for k in ("normal1", "shear1", "bulk1", "normal2", "shear2", "bulk2"))
    a = 4.0 * (1.0 - nu * nu) / e_mod
    a1 = np.sqrt(2.0 * p1 * a * r / np.pi)
    a2 = np.sqrt(2.0 * p2 * a * r / np.pi)
    swap = q2 < q1
    dq = np.abs(q2 - q1)
    dsigma = np.where(swap, s2 - s1, s1 - s2)
    with np.errstate(invalid="ignore"):  # NaN where no stick zone exists, as the batch gives
        d = np.sqrt(a * r / np.pi * (p1 + p2 - dq / f))
    ecc = -a * r * dsigma / (8.0 * f)
    sliding = (np.abs(q1) >= f * p1) | (np.abs(q2) >= f * p2)
    return a1, a2, d, ecc, sliding


def best(fn: Callable[[], object], repeat: int = 3) -> Tuple[float, float]:
    """Best wall time and best CPU time (all threads) of `repeat` runs."""
    wall, cpu = [], []
    for _ in range(repeat):
        start, start_cpu = time.perf_counter(), time.process_time()
        fn()
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return min(wall), min(cpu)


def hertz(n: int) -> None:
    from halfplane import _batch, _halfplane

    table = hertz_rows(n)
    columns = {k: table[k].to_numpy() for k in table.columns}
    out = halfplane.steady_batch(table)
    assert (out.error == "").mean() > 0.5, "most rows must be solved"
    codes, names = _batch._profiles(table["profile"])
    prepared = [_batch._numbers(c, table[c]) if c in table else None for c in _batch._NUMERIC]
    runs: Dict[str, Tuple[float, float]] = {}
    variants: Dict[str, Callable[[], object]] = {
        "steady_batch, all threads": lambda: halfplane.steady_batch(table),
        "steady_batch, 1 thread": lambda: halfplane.steady_batch(table, threads=1),
        "  of which the Rust solve, all threads": lambda: _halfplane.steady_batch_columns(prepared, codes, names),
        "numpy closed forms only": lambda: numpy_hertz(columns),
    }
    for _ in range(3):  # interleaved, best of three each
        for name, fn in variants.items():
            w, c = best(fn, 1)
            old = runs.get(name, (1e9, 1e9))
            runs[name] = (min(w, old[0]), min(c, old[1]))
    print(f"Hertz, {n:,} rows ({os.cpu_count()} cores), best of 3, wall and CPU (all threads):")
    for name, (w, c) in runs.items():
        print(f"  {name:40s} {w:7.3f} s  {n / w / 1e6:6.2f} M rows/s   CPU {c:7.3f} s")
    batch, numpy_time = runs["steady_batch, all threads"], runs["numpy closed forms only"]
    print(f"  speed relative to numpy: wall {numpy_time[0] / batch[0]:.2f}x, CPU {numpy_time[1] / batch[1]:.2f}x")
    print(f"  regimes: {out.regime.value_counts().to_dict()}")


def flat(n: int) -> None:
    table = flat_rows(n)
    t, _ = best(lambda: halfplane.steady_batch(table), 2)
    out = halfplane.steady_batch(table)
    print(f"flat-rounded, {n:,} rows: {t:.3f} s, {n / t:,.0f} rows/s "
          f"({(out.error == '').mean():.0%} solved)")


def _partition(seed: int, rows: int) -> pd.DataFrame:
    return hertz_rows(rows, seed)


def _worker_partition(seed: int, rows: int) -> pd.DataFrame:
    """One table of `rows` rows per Dask worker, kept on the worker, whatever the seed. (It refers
    to no module-level data: Dask ships functions of a script by value, with what they refer to.)"""
    from distributed import get_worker

    store = get_worker().__dict__.setdefault("_halfplane_bench_tables", {})
    if rows not in store:
        store[rows] = hertz_rows(rows, 0)
    return store[rows]


def _reduce(out: pd.DataFrame) -> pd.DataFrame:
    return pd.DataFrame({"rows": [len(out)], "solved": [int((out.error == "").sum())],
                         "stick_left": [float(np.nansum(out.stick_left))]})


def dask(n: int, partition_sizes: List[int], reuse: bool) -> None:
    """For each partition size: the same partitions generated, solved (all threads) and reduced in
    a loop in this process, then on the cluster; the two measured back to back. With `reuse`, each
    process's one table is made before the timed runs."""
    import dask.dataframe as dd
    from distributed import Client, LocalCluster

    import halfplane.dask as hdask

    sample = _partition(0, 10)
    # Explicit metas, so that the client does not generate and solve a partition to infer them.
    rows_meta = sample.iloc[:0]
    reduced_meta = _reduce(halfplane.steady_batch(sample)).iloc[:0]
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        warm = dd.from_map(_partition, [0, 1, 2, 3], rows=1000, meta=rows_meta)
        hdask.steady_batch(warm).map_partitions(_reduce, meta=reduced_meta).compute()
        remote_make = _worker_partition if reuse else _partition
        print(f"Dask, {n:,} Hertz rows ("
              + ("one table per process, made before timing" if reuse
                 else "rows generated and reduced where solved")
              + "), wall and CPU of this process:")
        for partition_rows in partition_sizes:
            parts = max(1, n // partition_rows)
            seeds = list(range(parts))
            make: Callable[[int, int], pd.DataFrame] = _partition
            if reuse:
                table = hertz_rows(partition_rows, 0)
                make = lambda _seed, _rows: table  # noqa: E731
                ddf = dd.from_map(remote_make, seeds, rows=partition_rows, meta=rows_meta)
                hdask.steady_batch(ddf).map_partitions(_reduce, meta=reduced_meta).compute()
            start, start_cpu = time.perf_counter(), time.process_time()
            totals = [_reduce(halfplane.steady_batch(make(s, partition_rows))) for s in seeds]
            local, local_cpu = time.perf_counter() - start, time.process_time() - start_cpu
            local_solved = sum(int(t["solved"].iloc[0]) for t in totals)
            start, start_cpu = time.perf_counter(), time.process_time()
            ddf = dd.from_map(remote_make, seeds, rows=partition_rows, meta=rows_meta)
            reduced = hdask.steady_batch(ddf).map_partitions(_reduce, meta=reduced_meta).compute()
            remote, remote_cpu = time.perf_counter() - start, time.process_time() - start_cpu
            solved = int(reduced["solved"].sum())
            rows = parts * partition_rows
            print(f"  {parts:4d} partitions of {partition_rows:>9,}: in-process {local:7.3f} s "
                  f"(CPU {local_cpu:6.3f} s, {rows / local / 1e6:5.2f} M rows/s), LocalCluster 2 x 1 "
                  f"thread {remote:7.3f} s ({rows / remote / 1e6:5.2f} M rows/s): "
                  f"Dask / in-process {local / remote:4.0%}   (solved rows equal: {solved == local_solved})")
        del client


def main() -> None:
    parser = argparse.ArgumentParser(description="steady_batch benchmarks")
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--flat-rows", type=int, default=100_000)
    parser.add_argument("--dask-rows", type=int, default=10_000_000)
    parser.add_argument("--partition-rows", default="250000",
                        help="rows per Dask partition; several, comma-separated, are compared")
    parser.add_argument("--skip-dask", action="store_true")
    parser.add_argument("--reuse-partitions", action="store_true",
                        help="Dask: one table per process, made before timing (solving only)")
    args = parser.parse_args()
    hertz(args.rows)
    flat(args.flat_rows)
    if not args.skip_dask:
        dask(args.dask_rows, [int(r) for r in args.partition_rows.split(",")], args.reuse_partitions)


if __name__ == "__main__":
    main()
