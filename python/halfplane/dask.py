"""``steady_batch`` on a Dask DataFrame: each partition is solved by
:func:`halfplane.steady_batch` on a worker.

Dask costs 1-3 ms per task (more on a busy machine), so give each partition at least ~0.1 s of
work: 2.5 x 10^5 Hertz rows, 4 x 10^4 flat-rounded or 1.5 x 10^4 power-law rows per
partition or more. Measured on a 2-worker LocalCluster (one thread each, 10^7 Hertz rows):
partitions of 2.5 x 10^5 or 10^6 rows reached 80-90% of the in-process throughput of solving
alone, and more than all of it when the rows are also generated on the workers; partitions of
5 x 10^4 rows 50-76%. Partitions shipped between processes may arrive in buffers that are not
aligned for float64; such columns are copied (under 1 ms per 2 x 10^5 rows), others are read in
place. Needs the ``dask`` extra: ``pip install "./python[dask]"``.
"""

from __future__ import annotations

from typing import Any, Optional

import numpy as np
import pandas as pd

from ._batch import steady_batch as _steady_batch


def meta() -> pd.DataFrame:
    """An empty frame with the columns and dtypes :func:`halfplane.steady_batch` returns."""
    empty = _steady_batch(
        {
            "youngs_modulus": np.empty(0),
            "poisson_ratio": np.empty(0),
            "friction": np.empty(0),
            "profile": np.empty(0, dtype=object),
            "normal1": np.empty(0),
            "shear1": np.empty(0),
            "bulk1": np.empty(0),
            "normal2": np.empty(0),
            "shear2": np.empty(0),
            "bulk2": np.empty(0),
        },
        threads=1,
    )
    return empty


def _partition(frame: pd.DataFrame, threads: Optional[int]) -> pd.DataFrame:
    return _steady_batch(frame, threads=threads)


def steady_batch(ddf: Any, threads: Optional[int] = 1) -> Any:
    """The steady state of every row of the Dask DataFrame ``ddf`` (the columns of
    :func:`halfplane.steady_batch`), as a lazy Dask DataFrame with the same partitions and index.

    ``threads`` is each task's Rust pool: 1 (default) suits one Dask worker thread per core;
    ``None`` uses ``HALFPLANE_NUM_THREADS`` or every core of the worker's machine (for one worker
    per machine). Results equal :func:`halfplane.steady_batch` on the whole table.
    """
    return ddf.map_partitions(_partition, threads, meta=meta())


__all__ = ["meta", "steady_batch"]
